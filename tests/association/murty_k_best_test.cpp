#include "skytrack/association/murty_k_best.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "jpda_test_support.hpp"

namespace skytrack {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Listed {
  double cost = 0.0;
  std::vector<int> columns;
};

// Every complete assignment (each row its own column, finite costs), cheapest first.
std::vector<Listed> all_assignments(const Eigen::MatrixXd& cost) {
  std::vector<Listed> out;
  std::vector<int> columns(static_cast<std::size_t>(cost.rows()));
  std::vector<char> used(static_cast<std::size_t>(cost.cols()), 0);
  auto recurse = [&](auto&& self, int r) -> void {
    if (r == cost.rows()) {
      double sum = 0.0;
      for (int i = 0; i < cost.rows(); ++i) sum += cost(i, columns[static_cast<std::size_t>(i)]);
      out.push_back({sum, columns});
      return;
    }
    for (int c = 0; c < cost.cols(); ++c) {
      if (used[static_cast<std::size_t>(c)] != 0 || !std::isfinite(cost(r, c))) continue;
      used[static_cast<std::size_t>(c)] = 1;
      columns[static_cast<std::size_t>(r)] = c;
      self(self, r + 1);
      used[static_cast<std::size_t>(c)] = 0;
    }
  };
  recurse(recurse, 0);
  std::stable_sort(out.begin(), out.end(),
                   [](const Listed& a, const Listed& b) { return a.cost < b.cost; });
  return out;
}

Eigen::MatrixXd random_cost(int rows, int cols, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double forbidden = 0.5 * unit(rng);
  Eigen::MatrixXd cost(rows, cols);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c)
      cost(r, c) = unit(rng) < forbidden ? kInf : 10.0 * unit(rng) - 3.0;
  }
  return cost;
}

TEST(MurtyKBest, ListsExactlyTheKBestAssignmentsInOrder) {
  std::mt19937_64 rng(1968);
  std::uniform_int_distribution<int> rows_of(1, 5), extra_of(0, 3), k_of(1, 40);
  MurtyKBest murty;
  for (int trial = 0; trial < 300; ++trial) {
    const int rows = rows_of(rng);
    const Eigen::MatrixXd cost = random_cost(rows, rows + extra_of(rng), rng);
    const std::vector<Listed> truth = all_assignments(cost);
    const int k = k_of(rng);
    const KBestAssignments& best = murty.solve(cost, k);
    const int expected = std::min<int>(k, static_cast<int>(truth.size()));
    ASSERT_EQ(best.count, expected) << "trial " << trial;
    EXPECT_EQ(best.exhausted, static_cast<int>(truth.size()) < k);
    std::set<std::vector<int>> distinct;
    for (int e = 0; e < best.count; ++e) {
      const auto columns = best.assignment(e);
      const std::vector<int> listed(columns.begin(), columns.end());
      double sum = 0.0;
      for (int r = 0; r < rows; ++r) sum += cost(r, listed[static_cast<std::size_t>(r)]);
      EXPECT_DOUBLE_EQ(best.costs[static_cast<std::size_t>(e)], sum);
      EXPECT_NEAR(best.costs[static_cast<std::size_t>(e)], truth[static_cast<std::size_t>(e)].cost,
                  1e-9)
          << "trial " << trial << " rank " << e;
      distinct.insert(listed);
    }
    EXPECT_EQ(static_cast<int>(distinct.size()), best.count);  // no assignment twice
  }
}

TEST(MurtyKBest, JpdaJointEventsComeOutInBruteForceOrder) {
  // GIVEN JPDA clusters as tracks x (plots + tracks) matrices (jpda_solver.hpp)
  std::mt19937_64 rng(42);
  std::uniform_int_distribution<int> tracks_of(1, 5), plots_of(1, 6);
  MurtyKBest murty;
  for (int trial = 0; trial < 200; ++trial) {
    // Each draw is its own step, last argument first: the order GCC used when the scenes were
    // measured (C++ leaves the evaluation order of arguments unspecified).
    const int plots_drawn = plots_of(rng), tracks_drawn = tracks_of(rng);
    const JpdaProblem p = test::random_problem(tracks_drawn, plots_drawn, rng);
    const int tracks = static_cast<int>(p.likelihood.rows());
    const int plots = static_cast<int>(p.likelihood.cols());
    Eigen::MatrixXd cost = Eigen::MatrixXd::Constant(tracks, plots + tracks, kInf);
    for (int t = 0; t < tracks; ++t) {
      for (int j = 0; j < plots; ++j) {
        if (p.likelihood(t, j) > 0.0)
          cost(t, j) = -std::log(p.likelihood(t, j) / p.clutter_density);
      }
      if (p.miss(t) > 0.0) cost(t, plots + t) = -std::log(p.miss(t));
    }
    std::vector<test::JointEvent> events = test::brute_force_jpda(p).events;
    std::stable_sort(events.begin(), events.end(),
                     [](const auto& a, const auto& b) { return a.weight > b.weight; });
    const KBestAssignments& best = murty.solve(cost, 30);  // WHEN the 30 best are listed
    ASSERT_EQ(best.count, std::min<int>(30, static_cast<int>(events.size())));
    for (int e = 0; e < best.count; ++e) {  // THEN event e is the brute-force e-th best
      const double log_ratio =
          std::log(events[0].weight / events[static_cast<std::size_t>(e)].weight);
      EXPECT_NEAR(best.costs[static_cast<std::size_t>(e)] - best.costs[0], log_ratio, 1e-9);
      const bool distinct_weights =
          (e == 0 || events[static_cast<std::size_t>(e)].weight <
                         events[static_cast<std::size_t>(e - 1)].weight * (1.0 - 1e-12)) &&
          (e + 1 >= static_cast<int>(events.size()) ||
           events[static_cast<std::size_t>(e + 1)].weight <
               events[static_cast<std::size_t>(e)].weight * (1.0 - 1e-12));
      if (!distinct_weights) continue;
      for (int t = 0; t < tracks; ++t) {
        const int c = best.assignment(e)[static_cast<std::size_t>(t)];
        EXPECT_EQ(c < plots ? c : -1,
                  events[static_cast<std::size_t>(e)].plot_of_track[static_cast<std::size_t>(t)]);
      }
    }
  }
}

TEST(MurtyKBest, NoCompleteAssignmentGivesNone) {
  MurtyKBest murty;
  EXPECT_EQ(murty.solve(Eigen::MatrixXd::Ones(3, 2), 5).count, 0);  // more rows than columns
  Eigen::MatrixXd blocked = Eigen::MatrixXd::Ones(2, 3);
  blocked.row(1).setConstant(kInf);
  EXPECT_EQ(murty.solve(blocked, 5).count, 0);
  EXPECT_TRUE(murty.solve(blocked, 5).exhausted);
  EXPECT_EQ(murty.solve(Eigen::MatrixXd::Ones(2, 3), 0).count, 0);
}

TEST(MurtyKBest, EmptyProblemHasOneEmptyAssignment) {
  MurtyKBest murty;
  const KBestAssignments& best = murty.solve(Eigen::MatrixXd(0, 4), 3);
  EXPECT_EQ(best.count, 1);
  EXPECT_EQ(best.costs[0], 0.0);
  EXPECT_TRUE(best.exhausted);
}

}  // namespace
}  // namespace skytrack
