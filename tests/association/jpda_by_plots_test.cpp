#include "skytrack/association/jpda_by_plots.hpp"

#include <cstdint>
#include <random>

#include <gtest/gtest.h>

#include "jpda_test_support.hpp"
#include "skytrack/association/jpda_exact.hpp"
#include "skytrack/association/jpda_solver.hpp"

namespace skytrack {
namespace {

/// JpdaExact's input: column 0 the miss weight, then L_tj / lambda.
Eigen::MatrixXd weights_of(const JpdaProblem& p) {
  Eigen::MatrixXd w(p.likelihood.rows(), p.likelihood.cols() + 1);
  w.col(0) = p.miss;
  w.rightCols(p.likelihood.cols()) = p.likelihood / p.clutter_density;
  return w;
}

TEST(JpdaByPlots, MatchesBruteForceOnRandomClusters) {
  // GIVEN random clusters (some tracks that cannot miss, plots gated by one track or by
  // several, plots gated by none); WHEN solved over the plots THEN the marginals and the
  // count of joint events are the enumeration's.
  std::mt19937_64 rng(1977);
  std::uniform_int_distribution<int> tracks_of(2, 6), plots_of(1, 8);
  JpdaByPlots by_plots;
  int solved = 0, refused = 0;
  for (int trial = 0; trial < 600; ++trial) {
    // Each draw is its own step, last argument first: the order GCC used when the scenes were
    // measured (C++ leaves the evaluation order of arguments unspecified).
    const int plots = plots_of(rng), tracks = tracks_of(rng);
    const JpdaProblem problem = test::random_problem(tracks, plots, rng);
    const Eigen::MatrixXd w = weights_of(problem);
    if (!by_plots.plan(w)) {
      ++refused;
      continue;
    }
    const test::BruteForceJpda truth = test::brute_force_jpda(problem);
    Eigen::MatrixXd beta = Eigen::MatrixXd::Constant(w.rows(), w.cols(), -1.0);
    const JpdaExactOutcome outcome = by_plots.run(w, std::int64_t{1} << 30, beta);
    ASSERT_TRUE(outcome.completed) << trial;
    ASSERT_EQ(outcome.events, static_cast<std::int64_t>(truth.events.size())) << trial;
    ASSERT_GT(outcome.total_weight, 0.0) << trial;
    EXPECT_LT((beta - truth.beta).cwiseAbs().maxCoeff(), 1e-9) << "trial " << trial;
    ++solved;
  }
  EXPECT_GT(solved, 300);
  EXPECT_GT(refused, 10);  // a track with no miss and no private plot, or no shared plot
}

TEST(JpdaByPlots, RefusesATrackThatMustTakeASharedPlot) {
  // GIVEN two tracks gating the same two plots, the first unable to miss (PD PG = 1):
  // dividing its row by its stay weight (0) has no meaning.
  JpdaProblem p;
  p.likelihood = (Eigen::MatrixXd(2, 2) << 1.0, 2.0, 0.5, 1.0).finished();
  p.miss = Eigen::Vector2d(0.0, 0.3);
  p.clutter_density = 1.0;
  JpdaByPlots by_plots;
  EXPECT_FALSE(by_plots.plan(weights_of(p)));
  p.miss(0) = 0.1;  // WHEN it can miss THEN the transposed problem exists
  EXPECT_TRUE(by_plots.plan(weights_of(p)));
}

TEST(JpdaSolver, TakesThePlotOrderWhenFewTracksShareManyPlots) {
  // GIVEN 4 tracks that all gate the same 24 plots (a few targets crossing in clutter): over
  // the tracks, the key is the set of used plots (up to 24 live bits); over the plots, the
  // set of used tracks (4 bits).
  std::mt19937_64 rng(24);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  JpdaProblem p;
  p.likelihood = Eigen::MatrixXd::Zero(4, 24);
  for (Eigen::Index t = 0; t < 4; ++t) {
    for (Eigen::Index j = 0; j < 24; ++j) p.likelihood(t, j) = 0.05 + 2.0 * unit(rng);
  }
  p.miss = Eigen::Vector4d(0.1, 0.2, 0.3, 0.05);
  p.clutter_density = 0.7;
  JpdaOptions options;
  options.max_exact_tracks = 32;
  JpdaSolver solver(options);
  const JpdaResult& result = solver.solve(p);  // WHEN solved
  ASSERT_EQ(result.status, JpdaStatus::kOk);
  EXPECT_FALSE(result.approximated);
  // THEN by the plots, in at most 24 levels of at most 2^4 states
  EXPECT_LE(solver.exact_outcome().states, 1 + 24 * 16);
  const test::BruteForceJpda truth = test::brute_force_jpda(p);  // 25^4 events
  EXPECT_EQ(result.hypotheses, static_cast<std::int64_t>(truth.events.size()));
  EXPECT_LT((result.beta - truth.beta).cwiseAbs().maxCoeff(), 1e-9);
  // AND the programme over the tracks gives the same marginals with far more states
  const Eigen::MatrixXd w = weights_of(p);
  Eigen::MatrixXd by_tracks = Eigen::MatrixXd::Zero(w.rows(), w.cols());
  JpdaExact exact;
  const JpdaExactOutcome outcome = exact.compute(w, std::int64_t{1} << 30, by_tracks);
  EXPECT_GT(outcome.states, 5 * solver.exact_outcome().states);  // measured 2653 against 353
  EXPECT_LT((by_tracks - result.beta).cwiseAbs().maxCoeff(), 1e-9);
}

}  // namespace
}  // namespace skytrack
