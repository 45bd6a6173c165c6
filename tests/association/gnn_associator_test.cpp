#include "skytrack/association/gnn_associator.hpp"

#include <algorithm>
#include <random>

#include <gtest/gtest.h>

#include "jpda_test_support.hpp"
#include "skytrack/association/jpda_solver.hpp"

namespace skytrack {
namespace {

TEST(GnnAssociator, PicksTheMapJointEventAndMurtysBest) {
  std::mt19937_64 rng(2025);
  std::uniform_int_distribution<int> tracks_of(1, 6), plots_of(1, 7);
  GnnAssociator gnn;
  JpdaSolver solver;
  int compared = 0;
  for (int trial = 0; trial < 400; ++trial) {
    // Each draw is its own step, last argument first: the order GCC used when the scenes were
    // measured (C++ leaves the evaluation order of arguments unspecified).
    const int plots = plots_of(rng), tracks = tracks_of(rng);
    const JpdaProblem problem = test::random_problem(tracks, plots, rng);
    std::vector<test::JointEvent> events = test::brute_force_jpda(problem).events;
    if (events.empty()) continue;
    std::stable_sort(events.begin(), events.end(),
                     [](const auto& a, const auto& b) { return a.weight > b.weight; });
    if (events.size() > 1 && events[1].weight > events[0].weight * (1.0 - 1e-12)) continue;  // tie
    const JpdaResult& result = gnn.associate(problem);
    ASSERT_EQ(result.status, JpdaStatus::kOk);
    const auto assignment = gnn.assignment();
    for (std::size_t t = 0; t < assignment.size(); ++t) {
      EXPECT_EQ(assignment[t], events[0].plot_of_track[t]) << "trial " << trial;  // MAP event
    }
    const Eigen::MatrixXd hard = result.beta;
    EXPECT_EQ(hard, solver.solve_k_best(problem, 1).beta);  // the best of Murty's list
    EXPECT_EQ(hard.sum(), static_cast<double>(hard.rows()));
    ++compared;
  }
  EXPECT_GT(compared, 300);
}

TEST(GnnAssociator, HandCaseTakesTheHeaviestEvent) {
  // Same cluster as JpdaSolver.HandComputedTwoTracksTwoPlots: T1 z1, T2 z2 weighs 12 of 25.
  JpdaProblem problem;
  problem.likelihood = (Eigen::MatrixXd(2, 2) << 4.0, 1.0, 2.0, 3.0).finished();
  problem.miss = Eigen::Vector2d(0.5, 0.5);
  problem.clutter_density = 2.0;
  GnnAssociator gnn;
  const JpdaResult& result = gnn.associate(problem);
  EXPECT_EQ(result.beta, (Eigen::MatrixXd(2, 3) << 0, 1, 0, 0, 0, 1).finished());
  EXPECT_FALSE(result.approximated);
  EXPECT_EQ(result.hypotheses, 1);
}

TEST(GnnAssociator, LeavesAPlotToClutterWhenMissingIsMoreLikely) {
  // GIVEN L = 0.1 < miss * lambda = 0.5 * 1: clutter + miss explains the plot better.
  JpdaProblem problem;
  problem.likelihood = Eigen::MatrixXd::Constant(1, 1, 0.1);
  problem.miss = Eigen::VectorXd::Constant(1, 0.5);
  problem.clutter_density = 1.0;
  GnnAssociator gnn;
  EXPECT_EQ(gnn.associate(problem).beta(0, 0), 1.0);
  EXPECT_EQ(gnn.assignment()[0], -1);
  problem.clutter_density = 0.1;  // WHEN clutter is rarer THEN the plot is the track's
  EXPECT_EQ(gnn.associate(problem).beta(0, 1), 1.0);
  EXPECT_EQ(gnn.assignment()[0], 0);
}

TEST(GnnAssociator, InvalidOrInfeasibleInputGivesAStatus) {
  JpdaProblem problem;
  problem.likelihood = Eigen::MatrixXd::Zero(1, 2);
  problem.miss = Eigen::VectorXd::Zero(1);  // no miss, no plot: infeasible
  problem.clutter_density = 1.0;
  GnnAssociator gnn;
  EXPECT_EQ(gnn.associate(problem).status, JpdaStatus::kNoFeasibleEvent);
  EXPECT_EQ(gnn.associate(problem).beta(0, 0), 1.0);
  problem.clutter_density = -1.0;
  EXPECT_EQ(gnn.associate(problem).status, JpdaStatus::kInvalidInput);
}

}  // namespace
}  // namespace skytrack
