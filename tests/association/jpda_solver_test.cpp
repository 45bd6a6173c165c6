#include "skytrack/association/jpda_solver.hpp"

#include "skytrack/association/jpda_exact.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "jpda_test_support.hpp"

namespace skytrack {
namespace {

void expect_rows_sum_to_one(const Eigen::MatrixXd& beta) {
  for (Eigen::Index t = 0; t < beta.rows(); ++t) EXPECT_NEAR(beta.row(t).sum(), 1.0, 1e-12);
}

JpdaOptions exact_everywhere() {
  JpdaOptions options;
  options.max_exact_tracks = 64;
  return options;
}

TEST(JpdaSolver, HandComputedTwoTracksTwoPlots) {
  // GIVEN T1, T2 both gating z1, z2: L = [[4, 1], [2, 3]], miss = 0.5 each, lambda = 2.
  // The seven feasible joint events and their weights prod(miss | L) * lambda^(unassigned):
  //   T1 -,  T2 -  : 0.5 * 0.5 * 2^2 = 1      T1 -,  T2 z1 : 0.5 * 2 * 2 = 2
  //   T1 z1, T2 -  : 4 * 0.5 * 2     = 4      T1 -,  T2 z2 : 0.5 * 3 * 2 = 3
  //   T1 z2, T2 -  : 1 * 0.5 * 2     = 1      T1 z1, T2 z2 : 4 * 3       = 12
  //                                           T1 z2, T2 z1 : 1 * 2       = 2
  // Z = 25. T1: miss (1+2+3)/25 = 0.24, z1 (4+12)/25 = 0.64, z2 (1+2)/25 = 0.12.
  //         T2: miss (1+4+1)/25 = 0.24, z1 (2+2)/25 = 0.16,  z2 (3+12)/25 = 0.60.
  JpdaProblem problem;
  problem.likelihood = (Eigen::MatrixXd(2, 2) << 4.0, 1.0, 2.0, 3.0).finished();
  problem.miss = Eigen::Vector2d(0.5, 0.5);
  problem.clutter_density = 2.0;
  const Eigen::MatrixXd expected =
      (Eigen::MatrixXd(2, 3) << 0.24, 0.64, 0.12, 0.24, 0.16, 0.60).finished();

  JpdaSolver solver;
  const JpdaResult& exact = solver.solve(problem);  // WHEN solved exactly
  EXPECT_EQ(exact.status, JpdaStatus::kOk);         // THEN the marginals are the hand ones
  EXPECT_FALSE(exact.approximated);
  EXPECT_EQ(exact.hypotheses, 7);
  EXPECT_LT((exact.beta - expected).cwiseAbs().maxCoeff(), 1e-12);

  const JpdaResult& k_best = solver.solve_k_best(problem, 100);  // and by Murty, k > 7
  EXPECT_FALSE(k_best.approximated);
  EXPECT_EQ(k_best.hypotheses, 7);
  EXPECT_LT((k_best.beta - expected).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(JpdaSolver, HandComputedOneTrackIsItsPdaWeights) {
  // GIVEN one track gating z1 and z3 (z2 outside its gate): L = [3, 0, 1], miss 0.5,
  // lambda 2. Events: miss 0.5, z1 3 / 2 = 1.5, z3 1 / 2 = 0.5; Z = 2.5 (the PDA weights).
  JpdaProblem problem;
  problem.likelihood = (Eigen::MatrixXd(1, 3) << 3.0, 0.0, 1.0).finished();
  problem.miss = Eigen::VectorXd::Constant(1, 0.5);
  problem.clutter_density = 2.0;
  const Eigen::MatrixXd expected = (Eigen::MatrixXd(1, 4) << 0.2, 0.6, 0.0, 0.2).finished();
  JpdaSolver solver;
  const JpdaResult& exact = solver.solve(problem);  // WHEN solved exactly
  EXPECT_EQ(exact.status, JpdaStatus::kOk);         // THEN three events, the PDA weights
  EXPECT_EQ(exact.hypotheses, 3);
  EXPECT_EQ(solver.exact_outcome().states, 2);
  EXPECT_LT((exact.beta - expected).cwiseAbs().maxCoeff(), 1e-15);
  JpdaOptions bounded;  // AND a state bound below its two states leaves it to k-best
  bounded.max_exact_states = 1;
  JpdaSolver small(bounded);
  EXPECT_EQ(small.solve(problem).hypotheses, 3);  // which enumerates all three
  EXPECT_FALSE(small.exact_outcome().completed);
  EXPECT_LT((small.solve(problem).beta - expected).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(JpdaSolver, ExactMatchesBruteForceOnRandomSmallClusters) {
  std::mt19937_64 rng(20240603);
  std::uniform_int_distribution<int> tracks_of(1, 6), plots_of(1, 7);
  JpdaSolver solver(exact_everywhere());
  for (int trial = 0; trial < 600; ++trial) {
    // Each draw is its own step, last argument first: the order GCC used when the scenes were
    // measured (C++ leaves the evaluation order of arguments unspecified).
    const int plots = plots_of(rng), tracks = tracks_of(rng);
    const JpdaProblem problem = test::random_problem(tracks, plots, rng);
    const test::BruteForceJpda truth = test::brute_force_jpda(problem);
    const JpdaResult& result = solver.solve(problem);
    ASSERT_FALSE(result.approximated);
    ASSERT_EQ(result.hypotheses, static_cast<std::int64_t>(truth.events.size())) << trial;
    if (truth.events.empty()) {
      EXPECT_EQ(result.status, JpdaStatus::kNoFeasibleEvent);
      continue;
    }
    ASSERT_EQ(result.status, JpdaStatus::kOk);
    EXPECT_LT((result.beta - truth.beta).cwiseAbs().maxCoeff(), 1e-9) << "trial " << trial;
    expect_rows_sum_to_one(result.beta);
  }
}

TEST(JpdaSolver, ExactEqualsExhaustiveMurtyOnEightTrackChains) {
  // Two independent methods on clusters too large for the brute-force enumerator above.
  std::mt19937_64 rng(88);
  JpdaSolver solver(exact_everywhere());
  for (int trial = 0; trial < 5; ++trial) {
    const JpdaProblem problem = test::chain_cluster(8, 3.0, 0.01, rng);
    const JpdaResult exact = solver.solve_exact(problem);
    ASSERT_EQ(exact.status, JpdaStatus::kOk);
    ASSERT_LT(exact.hypotheses, 20000);
    const JpdaResult& listed = solver.solve_k_best(problem, static_cast<int>(exact.hypotheses) + 1);
    EXPECT_FALSE(listed.approximated);  // every event listed
    EXPECT_EQ(listed.hypotheses, exact.hypotheses);
    EXPECT_LT((listed.beta - exact.beta).cwiseAbs().maxCoeff(), 1e-9);
  }
}

TEST(JpdaSolver, ScalingLikelihoodsAndClutterTogetherChangesNothing) {
  // GIVEN the solvers divide L by lambda (jpda_problem.hpp): only L / lambda matters.
  std::mt19937_64 rng(7);
  JpdaSolver solver;
  for (int trial = 0; trial < 50; ++trial) {
    JpdaProblem problem = test::random_problem(4, 5, rng);
    const Eigen::MatrixXd before = solver.solve(problem).beta;
    problem.likelihood *= 1e-7;  // WHEN both are scaled to realistic 3-D magnitudes
    problem.clutter_density *= 1e-7;
    EXPECT_LT((solver.solve(problem).beta - before).cwiseAbs().maxCoeff(), 1e-12);  // THEN same
  }
}

TEST(JpdaSolver, KBestWithEveryEventEqualsExact) {
  std::mt19937_64 rng(99);
  std::uniform_int_distribution<int> tracks_of(1, 5), plots_of(1, 6);
  JpdaSolver solver;
  for (int trial = 0; trial < 200; ++trial) {
    const int plots = plots_of(rng), tracks = tracks_of(rng);
    const JpdaProblem problem = test::random_problem(tracks, plots, rng);
    const test::BruteForceJpda truth = test::brute_force_jpda(problem);
    if (truth.events.empty()) continue;
    const int all = static_cast<int>(truth.events.size());
    const JpdaResult& result = solver.solve_k_best(problem, all);
    ASSERT_EQ(result.hypotheses, all);
    EXPECT_LT((result.beta - truth.beta).cwiseAbs().maxCoeff(), 1e-9) << "trial " << trial;
    expect_rows_sum_to_one(result.beta);
  }
}

struct KBestError {
  double worst = 0.0;
  double mean = 0.0;
};

// Max |beta_k-best - beta_exact| over 10 chain clusters each of 8, 9 and 10 tracks.
KBestError k_best_error(double spacing, double clutter_density, int k) {
  std::mt19937_64 rng(31337);
  JpdaSolver solver(exact_everywhere());
  KBestError error;
  int runs = 0;
  for (int tracks = 8; tracks <= 10; ++tracks) {
    for (int trial = 0; trial < 10; ++trial) {
      const JpdaProblem problem = test::chain_cluster(tracks, spacing, clutter_density, rng);
      const Eigen::MatrixXd exact = solver.solve_exact(problem).beta;
      EXPECT_EQ(solver.solve_exact(problem).status, JpdaStatus::kOk);
      const JpdaResult& approx = solver.solve_k_best(problem, k);
      expect_rows_sum_to_one(approx.beta);
      const double e = (approx.beta - exact).cwiseAbs().maxCoeff();
      error.worst = std::max(error.worst, e);
      error.mean += e;
      ++runs;
    }
  }
  error.mean /= runs;
  std::cout << "[ measured ] spacing " << spacing << " sigma, clutter " << clutter_density
            << " / sigma^2, k = " << k << ": max |beta error| = " << error.worst
            << ", mean = " << error.mean << '\n';
  return error;
}

TEST(JpdaSolver, KBestIsCloseToExactWhenThePosteriorIsConcentrated) {
  // GIVEN 8-10 targets 4 sigma apart (gates overlap), PD 0.9, 0.005 false plots / sigma^2
  // (0.15 per gate). WHEN Murty keeps the 100 best events THEN beta is within 0.02.
  EXPECT_LT(k_best_error(4.0, 0.005, 100).worst, 0.02);
}

TEST(JpdaSolver, KBestErrorShrinksWithKOnDenseClusters) {
  // GIVEN targets 2.5 sigma apart in 0.02 false plots / sigma^2: the posterior spreads over
  // ~1e5 events, so 100 of them are not enough (measured max error ~0.1; use the exact
  // method there). WHEN k grows THEN the error shrinks.
  const KBestError k100 = k_best_error(2.5, 0.02, 100);
  const KBestError k1000 = k_best_error(2.5, 0.02, 1000);
  EXPECT_LT(k1000.worst, k100.worst);
  EXPECT_LT(k1000.mean, 0.5 * k100.mean);
}

TEST(JpdaSolver, ExactTwelveTrackSparseClusterFinishesAndIgnoresTrackOrder) {
  std::mt19937_64 rng(12);
  const JpdaProblem problem = test::chain_cluster(12, 3.0, 0.01, rng);
  JpdaSolver solver(exact_everywhere());
  const JpdaResult result = solver.solve(problem);  // copy: the solver is reused below
  EXPECT_EQ(result.status, JpdaStatus::kOk);
  EXPECT_FALSE(result.approximated);
  EXPECT_GT(result.hypotheses, 1000);
  expect_rows_sum_to_one(result.beta);
  // WHEN the tracks are given in reverse, THEN the marginals are the same rows reversed.
  JpdaProblem reversed = problem;
  reversed.likelihood = problem.likelihood.colwise().reverse();
  reversed.miss = problem.miss.reverse();
  const JpdaResult& again = solver.solve(reversed);
  EXPECT_LT((again.beta.colwise().reverse() - result.beta).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(again.hypotheses, result.hypotheses);
}

TEST(JpdaSolver, ExactHandlesMoreThan64SharedPlotsWhenFewAreLiveAtOnce) {
  // GIVEN a 30-track chain A and the block-diagonal cluster A (+) A: two independent copies,
  // so the exact marginals of each copy must be A's own (JPDA factorises over blocks).
  std::mt19937_64 rng(64);
  const JpdaProblem a = test::chain_cluster(30, 1.5, 0.02, rng);
  const Eigen::Index t = a.likelihood.rows(), m = a.likelihood.cols();
  JpdaProblem twice;
  twice.likelihood = Eigen::MatrixXd::Zero(2 * t, 2 * m);
  twice.likelihood.topLeftCorner(t, m) = a.likelihood;
  twice.likelihood.bottomRightCorner(t, m) = a.likelihood;
  twice.miss.resize(2 * t);
  twice.miss << a.miss, a.miss;
  twice.clutter_density = a.clutter_density;
  JpdaSolver solver(exact_everywhere());
  const JpdaResult single = solver.solve_exact(a);
  ASSERT_EQ(single.status, JpdaStatus::kOk);
  const JpdaResult& both = solver.solve_exact(twice);  // WHEN solved exactly
  ASSERT_EQ(both.status, JpdaStatus::kOk);
  // THEN the programme over the tracks, which the solver may leave for the one over the
  // plots, completes beyond one word of shared plots
  Eigen::MatrixXd w(twice.likelihood.rows(), twice.likelihood.cols() + 1);
  w.col(0) = twice.miss;
  w.rightCols(twice.likelihood.cols()) = twice.likelihood / twice.clutter_density;
  Eigen::MatrixXd by_tracks = Eigen::MatrixXd::Zero(w.rows(), w.cols());
  JpdaExact exact;
  const JpdaExactOutcome outcome = exact.compute(w, std::int64_t{1} << 16, by_tracks);
  ASSERT_TRUE(outcome.completed);
  EXPECT_GT(outcome.shared_plots, 64);
  EXPECT_LE(outcome.key_bits, 64);
  EXPECT_LT((by_tracks - both.beta).cwiseAbs().maxCoeff(), 1e-9);
  Eigen::MatrixXd first(t, m + 1), second(t, m + 1);
  first << both.beta.topLeftCorner(t, 1), both.beta.block(0, 1, t, m);
  second << both.beta.bottomLeftCorner(t, 1), both.beta.block(t, 1 + m, t, m);
  EXPECT_LT((first - single.beta).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((second - single.beta).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_EQ(both.beta.block(0, 1 + m, t, m).cwiseAbs().maxCoeff(), 0.0);
}

TEST(JpdaSolver, FallsBackToKBestAboveMaxExactTracks) {
  std::mt19937_64 rng(5);
  const JpdaProblem problem = test::chain_cluster(6, 2.0, 0.05, rng);
  JpdaOptions options;
  options.max_exact_tracks = 5;
  options.k_best = 10;
  JpdaSolver solver(options);
  const JpdaResult& result = solver.solve(problem);
  EXPECT_EQ(result.status, JpdaStatus::kOk);
  EXPECT_TRUE(result.approximated);
  EXPECT_EQ(result.hypotheses, 10);
  expect_rows_sum_to_one(result.beta);
}

TEST(JpdaSolver, FallsBackWhenTheExactStateBoundIsReached) {
  std::mt19937_64 rng(6);
  const JpdaProblem problem = test::chain_cluster(6, 1.0, 0.05, rng);
  JpdaOptions options;
  options.max_exact_states = 4;
  JpdaSolver solver(options);
  EXPECT_TRUE(solver.solve(problem).approximated);
  EXPECT_FALSE(solver.exact_outcome().completed);
  EXPECT_EQ(solver.solve_exact(problem).status, JpdaStatus::kExactLimit);
  expect_rows_sum_to_one(solver.solve_exact(problem).beta);
}

TEST(JpdaExact, SkipsOnlyPassesThatWouldStopAtTheStateBound) {
  // GIVEN dense chain clusters and small state bounds; WHEN the exact method runs with the
  // bound and without one THEN it completes exactly when the whole pass fits the bound, and a
  // pass it skips (proved to stop by its lower bound, no state made) would have exceeded it.
  std::mt19937_64 rng(77);
  std::uniform_int_distribution<int> tracks_of(6, 12);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  JpdaExact exact;
  int skipped = 0, stopped = 0, completed = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const double clutter_density = 0.05 + 0.3 * unit(rng), spacing = 0.8 + 1.2 * unit(rng);
    const int tracks = tracks_of(rng);
    const JpdaProblem p = test::chain_cluster(tracks, spacing, clutter_density, rng);
    Eigen::MatrixXd w(p.likelihood.rows(), p.likelihood.cols() + 1);
    w.col(0) = p.miss;
    w.rightCols(p.likelihood.cols()) = p.likelihood / p.clutter_density;
    Eigen::MatrixXd beta = Eigen::MatrixXd::Zero(w.rows(), w.cols());
    const std::int64_t all = exact.compute(w, std::int64_t{1} << 40, beta).states;
    for (const std::int64_t bound : {16, 64, 256}) {
      const JpdaExactOutcome bounded = exact.compute(w, bound, beta);
      ASSERT_EQ(bounded.completed, all <= bound) << "trial " << trial << " bound " << bound;
      if (bounded.completed) {
        ++completed;
      } else if (bounded.states == 0) {
        ++skipped;
      } else {
        ++stopped;
      }
    }
  }
  EXPECT_GT(skipped, 0);  // the lower bound proved some stops in advance
  EXPECT_GT(stopped, 0);  // and left others to the pass itself
  EXPECT_GT(completed, 0);
}

TEST(JpdaSolver, InvalidInputGivesAllMissAndAStatus) {
  JpdaProblem problem;
  problem.likelihood = Eigen::MatrixXd::Constant(2, 3, 1.0);
  problem.miss = Eigen::Vector2d(0.1, 0.1);
  problem.clutter_density = 0.0;  // lambda must be > 0
  JpdaSolver solver;
  EXPECT_EQ(solver.solve(problem).status, JpdaStatus::kInvalidInput);
  problem.clutter_density = 1.0;
  problem.likelihood(1, 2) = std::numeric_limits<double>::quiet_NaN();
  const JpdaResult& result = solver.solve(problem);
  EXPECT_EQ(result.status, JpdaStatus::kInvalidInput);
  ASSERT_EQ(result.beta.rows(), 2);
  ASSERT_EQ(result.beta.cols(), 4);
  EXPECT_EQ(result.beta.col(0).sum(), 2.0);
  problem.likelihood(1, 2) = 1.0;
  problem.miss = Eigen::Vector3d(0.1, 0.1, 0.1);  // wrong size
  EXPECT_EQ(solver.solve(problem).status, JpdaStatus::kInvalidInput);
}

TEST(JpdaSolver, TrackThatCannotBeExplainedGivesNoFeasibleEvent) {
  // GIVEN a track with PD * PG = 1 (miss 0) and no gated plot: every event has weight 0.
  JpdaProblem problem;
  problem.likelihood = (Eigen::MatrixXd(2, 1) << 1.0, 0.0).finished();
  problem.miss = Eigen::Vector2d(0.2, 0.0);
  problem.clutter_density = 1.0;
  JpdaSolver solver;
  EXPECT_EQ(solver.solve(problem).status, JpdaStatus::kNoFeasibleEvent);
  EXPECT_EQ(solver.solve_k_best(problem, 5).status, JpdaStatus::kNoFeasibleEvent);
  expect_rows_sum_to_one(solver.solve(problem).beta);
}

TEST(JpdaSolver, EmptyClusterShapes) {
  JpdaSolver solver;
  JpdaProblem no_plots;
  no_plots.likelihood = Eigen::MatrixXd::Zero(3, 0);
  no_plots.miss = Eigen::Vector3d(0.1, 0.2, 0.3);
  no_plots.clutter_density = 1.0;
  const JpdaResult& result = solver.solve(no_plots);
  EXPECT_EQ(result.status, JpdaStatus::kOk);
  EXPECT_EQ(result.hypotheses, 1);
  EXPECT_EQ(result.beta, Eigen::MatrixXd::Ones(3, 1));
  JpdaProblem no_tracks;
  no_tracks.likelihood = Eigen::MatrixXd::Zero(0, 4);
  no_tracks.clutter_density = 1.0;
  EXPECT_EQ(solver.solve(no_tracks).status, JpdaStatus::kOk);
  EXPECT_EQ(solver.solve(no_tracks).beta.rows(), 0);
}

}  // namespace
}  // namespace skytrack
