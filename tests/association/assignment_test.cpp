#include "skytrack/association/assignment.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace skytrack {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct BruteForce {
  int assigned = 0;
  double cost = 0.0;
};

// Best (most allowed pairs, then least cost) over every injective map short -> long side.
BruteForce brute_force(const Eigen::MatrixXd& cost) {
  const bool transposed = cost.rows() > cost.cols();
  const Eigen::MatrixXd c = transposed ? Eigen::MatrixXd(cost.transpose()) : cost;
  const int n = static_cast<int>(c.rows());
  const int m = static_cast<int>(c.cols());
  std::vector<int> perm(static_cast<std::size_t>(m));
  std::iota(perm.begin(), perm.end(), 0);
  BruteForce best{-1, 0.0};
  do {
    BruteForce here;
    for (int r = 0; r < n; ++r) {
      const double x = c(r, perm[r]);
      if (std::isfinite(x)) {
        ++here.assigned;
        here.cost += x;
      }
    }
    if (here.assigned > best.assigned ||
        (here.assigned == best.assigned && here.cost < best.cost)) {
      best = here;
    }
  } while (std::next_permutation(perm.begin(), perm.end()));
  return best;
}

void expect_consistent(const Eigen::MatrixXd& cost, const AssignmentResult& result) {
  ASSERT_EQ(result.row_to_col.size(), static_cast<std::size_t>(cost.rows()));
  ASSERT_EQ(result.col_to_row.size(), static_cast<std::size_t>(cost.cols()));
  int assigned = 0;
  double total = 0.0;
  for (int r = 0; r < cost.rows(); ++r) {
    const int c = result.row_to_col[r];
    if (c < 0) continue;
    ++assigned;
    EXPECT_EQ(result.col_to_row[c], r);
    EXPECT_TRUE(std::isfinite(cost(r, c))) << "forbidden pair used at " << r << "," << c;
    total += cost(r, c);
  }
  const auto cols_used = std::count_if(result.col_to_row.begin(), result.col_to_row.end(),
                                       [](int r) { return r >= 0; });
  EXPECT_EQ(cols_used, assigned);
  EXPECT_EQ(result.assigned, assigned);
  EXPECT_NEAR(result.total_cost, total, 1e-9);
  const auto full = std::min(cost.rows(), cost.cols());
  EXPECT_EQ(result.feasible, assigned == full);
}

Eigen::MatrixXd random_cost(std::mt19937& rng, int rows, int cols, double p_forbidden,
                            bool integer) {
  std::uniform_real_distribution<double> uniform(-5.0, 20.0);
  std::uniform_int_distribution<int> small(0, 4);  // many ties
  std::bernoulli_distribution forbid(p_forbidden);
  Eigen::MatrixXd cost(rows, cols);
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < cols; ++j) {
      cost(i, j) = forbid(rng) ? kInf : (integer ? small(rng) : uniform(rng));
    }
  }
  return cost;
}

TEST(Assignment, MatchesBruteForceOnRandomMatrices) {
  // GIVEN one reused solver and many random matrices of every shape up to 7 x 7
  AssignmentSolver solver;
  std::mt19937 rng(20240611);
  for (int rows = 1; rows <= 7; ++rows) {
    for (int cols = 1; cols <= 7; ++cols) {
      for (int trial = 0; trial < 24; ++trial) {
        const double p_forbidden = (trial % 3) * 0.3;  // 0, 0.3, 0.6
        const Eigen::MatrixXd cost = random_cost(rng, rows, cols, p_forbidden, trial % 2 == 1);
        // WHEN solved  THEN as many pairs and as cheap as the exhaustive search
        const AssignmentResult& result = solver.solve(cost);
        const BruteForce best = brute_force(cost);
        SCOPED_TRACE(testing::Message() << rows << "x" << cols << " trial " << trial);
        expect_consistent(cost, result);
        EXPECT_EQ(result.assigned, best.assigned);
        EXPECT_NEAR(result.total_cost, best.cost, 1e-9);
      }
    }
  }
}

TEST(Assignment, EmptyMatricesGiveEmptyFeasibleAssignment) {
  for (const auto& [rows, cols] : {std::pair{0, 0}, std::pair{0, 3}, std::pair{4, 0}}) {
    const AssignmentResult result = solve_assignment(Eigen::MatrixXd(rows, cols));
    EXPECT_TRUE(result.feasible);
    EXPECT_EQ(result.assigned, 0);
    EXPECT_EQ(result.total_cost, 0.0);
    EXPECT_EQ(result.row_to_col, std::vector<int>(rows, -1));
    EXPECT_EQ(result.col_to_row, std::vector<int>(cols, -1));
  }
}

TEST(Assignment, HandMadeCaseAvoidsGreedyChoice) {
  // GIVEN greedy would take (0,0)=1 and then pay 100 for (1,1)
  Eigen::MatrixXd cost(2, 3);
  cost << 1.0, 2.0, kInf,  //
      3.0, 100.0, kInf;
  const AssignmentResult result = solve_assignment(cost);
  // THEN the optimum is (0,1) + (1,0) = 5; column 2 is left free
  EXPECT_EQ(result.row_to_col, (std::vector<int>{1, 0}));
  EXPECT_EQ(result.col_to_row, (std::vector<int>{1, 0, -1}));
  EXPECT_DOUBLE_EQ(result.total_cost, 5.0);
  EXPECT_TRUE(result.feasible);
}

TEST(Assignment, ForbiddenEntriesGiveMaximumCardinalityThenMinimumCost) {
  // GIVEN row 1 can only take column 0, which row 0 would like too
  Eigen::MatrixXd cost(3, 2);
  cost << 0.0, 50.0,  //
      10.0, kInf,     //
      kInf, kInf;     // row 2 can take nothing
  const AssignmentResult result = solve_assignment(cost);
  // THEN both assignable rows are served (cost 60 beats the cheaper single pair 0)
  EXPECT_EQ(result.row_to_col, (std::vector<int>{1, 0, -1}));
  EXPECT_DOUBLE_EQ(result.total_cost, 60.0);
  EXPECT_EQ(result.assigned, 2);
  EXPECT_TRUE(result.feasible);  // min(3, 2) = 2 pairs assigned
}

TEST(Assignment, AllForbiddenIsInfeasibleAndEmpty) {
  const Eigen::MatrixXd cost = Eigen::MatrixXd::Constant(2, 2, kInf);
  const AssignmentResult result = solve_assignment(cost);
  EXPECT_FALSE(result.feasible);
  EXPECT_EQ(result.assigned, 0);
  EXPECT_EQ(result.row_to_col, (std::vector<int>{-1, -1}));
}

TEST(Assignment, LargeSquareHasPermutationAndBeatsIdentity) {
  // GIVEN a 60 x 60 random matrix (too big for brute force)
  std::mt19937 rng(7);
  const Eigen::MatrixXd cost = random_cost(rng, 60, 60, 0.0, false);
  const AssignmentResult result = solve_assignment(cost);
  // THEN a full permutation no worse than the diagonal or any single swap of it
  expect_consistent(cost, result);
  EXPECT_LE(result.total_cost, cost.trace() + 1e-9);
  std::vector<int> p = result.row_to_col;
  for (int a = 0; a < 60; ++a) {
    for (int b = a + 1; b < 60; ++b) {
      const double delta = cost(a, p[b]) + cost(b, p[a]) - cost(a, p[a]) - cost(b, p[b]);
      EXPECT_GE(delta, -1e-9);
    }
  }
}

}  // namespace
}  // namespace skytrack
