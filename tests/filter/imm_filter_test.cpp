#include "skytrack/filter/imm_filter.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "filter_test_support.hpp"
#include "skytrack/filter/pda.hpp"

namespace skytrack {
namespace {

ImmFilter two_cv_modes() {
  Eigen::MatrixXd transition(2, 2);
  transition << 0.9, 0.1, 0.2, 0.8;
  auto filter = ImmFilter::create({ConstantVelocity{0.0, 1.0}, ConstantVelocity{1.0, 1.0}},
                                  {"quiet", "noisy"}, transition, test::layout_2d(), {});
  EXPECT_TRUE(filter) << filter.error().message;
  return *filter;
}

TEST(ImmFilter, OneStepMatchesHandComputation) {
  // GIVEN p = [0.9 0.1; 0.2 0.8], mu = (0.7, 0.3), state [x vx y vy]
  //   mode 1 (CV, q = 0): (0, 10, 0, 0),  P = diag(4, 1, 4, 1)
  //   mode 2 (CV, q = 1): (2, 12, 1, -1), P = diag(9, 4, 9, 4)
  //   one plot at t = 1: (13, 0.5), sigma 2 (R = 4 I), beta = 1
  // By hand (4x4 arithmetic written out independently of the library):
  // eq. 1-2: c = (0.69, 0.31); mu_1|1 = 0.63/0.69 = 0.9130434782608696,
  //   mu_2|1 = 0.06/0.69 = 0.08695652173913043, mu_1|2 = 0.07/0.31 = 0.2258064516129032,
  //   mu_2|2 = 0.24/0.31 = 0.7741935483870968
  //   mode 1 mixed: x0 = (0.17391304347826086, 10.17391304347826, 0.08695652173913043,
  //     -0.08695652173913043), P0(0,0) = 4.752362948960303, P0(0,2) = 0.15879017013232516
  //     (the spread of the means couples x and y)
  //   mode 2 mixed: x0 = (1.5483870967741935, 11.548387096774192, 0.7741935483870968,
  //     -0.7741935483870968), P0(0,0) = 8.570239334027056
  // prediction (F = [1 1; 0 1] per axis, Q = q [1/3 1/2; 1/2 1]):
  //   mode 1: x- = (10.347826086956522, 10.17391304347826, 0, -0.08695652173913043),
  //     S = diag(10.965973534971646, 9.695652173913043), nu = (2.6521739130434785, 0.5)
  //   mode 2: x- = (13.096774193548386, 11.548387096774192, 0, -0.7741935483870968),
  //     S = diag(18.32396808879639, 15.526881720430106), nu = (-0.0967741935483861, 0.5)
  // eq. 3: Lambda = (0.011056604159207898, 0.00935752405859496)
  // eq. 4-5: mu = (0.7245144400097432, 0.2754855599902569)
  // mode posteriors: x1 = (12.032580589553525, 10.632477159110497, 0.2937219730941704,
  //   -0.09874244660152147), x2 = (13.021125160899523, 11.520812826531383,
  //   0.371191135734072, -0.6474049242962108)
  // eq. 6-7: x = (12.304910344366107, 10.87720080790926, 0.31506360874600003,
  //   -0.2498910365148848),
  //   P = [2.897390808044036  0.9903333858194716  0.01528519566289814  -0.23423598907027954
  //        .                  2.0372166185490013  0.013735733202571935 -0.21397383453017826
  //        .                  .                   2.5217067231990185    0.639682281561935
  //        .                  .                   .                     1.878024333589953]
  const ImmFilter filter = two_cv_modes();
  // WHEN predicted to t = 1 and updated with the one plot, beta = 1
  const ImmEstimate predicted = filter.predict(test::two_mode_posterior(), 1.0);
  PlotMeasurement plot = test::cartesian_xy(13.0, 0.5, 2.0);
  plot.time = 1.0;
  const std::array<PlotHypothesis, 1> hypotheses = {filter.hypothesise(predicted, plot)};
  const std::array<double, 1> beta = {1.0};
  const ImmEstimate posterior = filter.update(predicted, hypotheses, beta, 0.0, 0.9, 0.99, 1e-6);
  const Gaussian combined = filter.combine(posterior);
  // THEN every intermediate and final number matches to 1e-9
  constexpr double kTol = 1e-9;
  EXPECT_NEAR(predicted.probabilities[0], 0.69, kTol);
  EXPECT_NEAR(predicted.probabilities[1], 0.31, kTol);
  const double x1[4] = {10.347826086956522, 10.17391304347826, 0.0, -0.08695652173913043};
  const double x2[4] = {13.096774193548386, 11.548387096774192, 0.0, -0.7741935483870968};
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(predicted.modes[0].mean[i], x1[i], kTol);
    EXPECT_NEAR(predicted.modes[1].mean[i], x2[i], kTol);
  }
  EXPECT_NEAR(predicted.modes[0].covariance(0, 3), -0.3175803402646503, kTol);
  EXPECT_NEAR(predicted.modes[1].covariance(0, 1), 5.221123829344433, kTol);
  EXPECT_NEAR(hypotheses[0].per_mode[0].S(0, 0), 10.965973534971646, kTol);
  EXPECT_NEAR(hypotheses[0].per_mode[1].S(0, 0), 18.32396808879639, kTol);
  EXPECT_NEAR(hypotheses[0].per_mode[0].S(1, 1), 9.695652173913043, kTol);
  EXPECT_NEAR(hypotheses[0].per_mode[1].S(1, 1), 15.526881720430106, kTol);
  EXPECT_NEAR(hypotheses[0].per_mode[1].residual[0], -0.0967741935483861, kTol);
  EXPECT_NEAR(std::exp(hypotheses[0].per_mode[0].log_likelihood), 0.011056604159207898, 1e-12);
  EXPECT_NEAR(std::exp(hypotheses[0].per_mode[1].log_likelihood), 0.00935752405859496, 1e-12);
  EXPECT_NEAR(hypotheses[0].likelihood, 0.69 * 0.011056604159207898 + 0.31 * 0.00935752405859496,
              1e-12);
  EXPECT_NEAR(posterior.probabilities[0], 0.7245144400097432, kTol);
  EXPECT_NEAR(posterior.probabilities[1], 0.2754855599902569, kTol);
  EXPECT_NEAR(posterior.modes[0].mean[3], -0.09874244660152147, kTol);
  EXPECT_NEAR(posterior.modes[1].mean[3], -0.6474049242962108, kTol);
  EXPECT_NEAR(posterior.modes[1].covariance(1, 1), 3.53417588302391, kTol);
  const double x[4] = {12.304910344366107, 10.87720080790926, 0.31506360874600003,
                       -0.2498910365148848};
  const double P[4][4] = {
      {2.897390808044036, 0.9903333858194716, 0.01528519566289814, -0.23423598907027954},
      {0.9903333858194716, 2.0372166185490013, 0.013735733202571935, -0.21397383453017826},
      {0.01528519566289814, 0.013735733202571935, 2.5217067231990185, 0.639682281561935},
      {-0.23423598907027954, -0.21397383453017826, 0.639682281561935, 1.878024333589953}};
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(combined.mean[i], x[i], kTol) << i;
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(combined.covariance(i, j), P[i][j], kTol) << i << j;
  }
  EXPECT_EQ(posterior.failed_modes, 0u);
}

TEST(ImmFilter, IdenticalModesEqualASingleKalmanFilter) {
  // GIVEN three identical CV modes with an arbitrary Markov matrix
  Eigen::MatrixXd transition(3, 3);
  transition << 0.5, 0.3, 0.2, 0.1, 0.6, 0.3, 0.25, 0.25, 0.5;
  const ConstantVelocity cv{2.0, 1.0};
  auto filter = ImmFilter::create({cv, cv, cv}, {"a", "b", "c"}, transition, test::layout_2d(), {});
  ASSERT_TRUE(filter);
  StateMat P0 = StateMat::Identity(4, 4) * 100.0;
  const Gaussian start = test::gaussian({0, 50, 0, -20}, P0);
  ImmEstimate imm = filter->initial(start, Eigen::Vector3d(0.2, 0.5, 0.3), 0.0);
  Eigen::VectorXd markov = imm.probabilities;  // mu_k = p' mu_k-1: no mode is favoured
  Gaussian kf = start;
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 5.0);
  for (int k = 1; k <= 10; ++k) {
    // WHEN both run predict + update over ten plots
    const double t = 2.0 * k;
    imm = filter->predict(imm, t);
    kf = predict(cv, test::layout_2d(), kf, 2.0);
    // Each draw is its own step, last argument first: the order GCC used when the scenes were
    // measured (C++ leaves the evaluation order of arguments unspecified).
    const double noise_y = noise(rng), noise_x = noise(rng);
    PlotMeasurement plot = test::cartesian_xy(50 * t + noise_x, -20 * t + noise_y, 5.0);
    const std::array<PlotHypothesis, 1> h = {filter->hypothesise(imm, plot)};
    const std::array<double, 1> beta = {1.0};
    imm = filter->update(imm, h, beta, 0.0, 0.9, 0.99, 1e-6);
    kf = kalman_update(kf, innovate(kf, test::layout_2d(), plot, {}));
    // THEN the combined IMM estimate is the KF's, and the mode probabilities only follow
    // the Markov chain (equal likelihoods favour no mode)
    const Gaussian combined = filter->combine(imm);
    markov = (transition.transpose() * markov).eval();
    EXPECT_LT((combined.mean - kf.mean).norm(), 1e-9);
    EXPECT_LT((combined.covariance - kf.covariance).norm(), 1e-9);
    EXPECT_LT((imm.probabilities - markov).norm(), 1e-12);
    EXPECT_NEAR(imm.probabilities.sum(), 1.0, 1e-12);
  }
}

TEST(ImmFilter, ProbabilitiesStayNormalisedUnderClutterAndMisses) {
  // GIVEN the shipped default profile (whatever its modes) in 3-D, plots around a target
  config::TrackingProfile profile;
  profile.dimension = 3;
  auto filter = ImmFilter::from_profile(profile);
  ASSERT_TRUE(filter) << filter.error().message;
  ASSERT_EQ(filter->mode_count(), static_cast<int>(profile.motion_models.size()));
  for (int j = 0; j < filter->mode_count(); ++j) {
    EXPECT_EQ(filter->names()[j], profile.motion_models[j].name);
  }
  const int n = filter->layout().size();
  Gaussian start;
  start.mean = StateVec::Zero(n);
  start.mean.head(6) << 0, 200, 30000, 0, 5000, 0;
  start.covariance = StateMat::Identity(n, n) * 400.0;
  const Eigen::Map<const Eigen::VectorXd> initial(profile.initial_mode_probabilities.data(),
                                                  profile.initial_mode_probabilities.size());
  ImmEstimate imm = filter->initial(start, initial, 0.0);
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::uniform_int_distribution<int> plot_count(0, 3);
  PlotScan scan;
  for (int k = 1; k <= 15; ++k) {
    scan.time = 2.0 * k;
    imm = filter->predict(imm, scan.time);
    const Gaussian predicted = filter->combine(imm);
    std::vector<PlotHypothesis> hypotheses;
    const int m = plot_count(rng);
    for (int i = 0; i < m; ++i) {
      Plot plot;
      plot.range =
          std::hypot(predicted.mean[0], predicted.mean[2], predicted.mean[4]) + 60 * noise(rng);
      plot.azimuth = std::atan2(predicted.mean[0], predicted.mean[2]) + 0.005 * noise(rng);
      plot.elevation = std::asin(predicted.mean[4] / plot.range) + 0.005 * noise(rng);
      auto measurement = measurement_from_plot(plot, scan, profile.measurement.default_sigma, 3);
      ASSERT_TRUE(measurement);
      hypotheses.push_back(filter->hypothesise(imm, *measurement));
    }
    std::vector<double> likelihoods, beta(hypotheses.size());
    for (const PlotHypothesis& h : hypotheses) likelihoods.push_back(h.likelihood);
    const double beta0 = pda_weights(likelihoods, 0.9, 0.99, 1e-10, beta);
    imm = filter->update(imm, hypotheses, beta, beta0, 0.9, 0.99, 1e-10);
    // THEN the mode probabilities are a distribution and the estimate stays finite
    EXPECT_NEAR(imm.probabilities.sum(), 1.0, 1e-12);
    EXPECT_TRUE((imm.probabilities.array() >= 0.0).all());
    EXPECT_TRUE(filter->combine(imm).covariance.allFinite());
    EXPECT_EQ(imm.failed_modes, 0u);
  }
}

TEST(ImmFilter, IsolatedTrackIsTheImmPdaf) {
  // GIVEN two plots, PDA weights for an isolated track with PD, PG, lambda
  const ImmFilter filter = two_cv_modes();
  const ImmEstimate predicted = filter.predict(test::two_mode_posterior(), 1.0);
  const std::array<PlotHypothesis, 2> hypotheses = {
      filter.hypothesise(predicted, test::cartesian_xy(13.0, 0.5, 2.0)),
      filter.hypothesise(predicted, test::cartesian_xy(9.0, -2.0, 2.0))};
  const double pd = 0.8, pg = 0.99, lambda = 2e-3;
  const std::array<double, 2> likelihoods = {hypotheses[0].likelihood, hypotheses[1].likelihood};
  std::array<double, 2> beta{};
  const double beta0 = pda_weights(likelihoods, pd, pg, lambda, beta);
  // WHEN updated with those weights
  const ImmEstimate posterior = filter.update(predicted, hypotheses, beta, beta0, pd, pg, lambda);
  // THEN mu_j ~ c_j Lambda_j, Lambda_j = (1 - PD PG) + (PD / lambda) sum_i N_ij (IMM-PDAF)
  std::array<double, 2> weight{};
  for (int j = 0; j < 2; ++j) {
    double sum = 0.0;
    for (const PlotHypothesis& h : hypotheses) sum += std::exp(h.per_mode[j].log_likelihood);
    weight[j] = predicted.probabilities[j] * ((1.0 - pd * pg) + pd / lambda * sum);
  }
  EXPECT_NEAR(posterior.probabilities[0], weight[0] / (weight[0] + weight[1]), 1e-12);
  // AND each mode's state is that of its mode-matched PDAF, weighted by its own likelihoods
  for (int j = 0; j < 2; ++j) {
    std::array<double, 2> mode_likelihoods{};
    std::array<Innovation, 2> innovations;
    for (std::size_t i = 0; i < 2; ++i) {
      innovations[i] = hypotheses[i].per_mode[static_cast<std::size_t>(j)];
      mode_likelihoods[i] = std::exp(innovations[i].log_likelihood);
    }
    std::array<double, 2> mode_beta{};
    const double mode_miss = pda_weights(mode_likelihoods, pd, pg, lambda, mode_beta);
    const Gaussian pdaf =
        pda_update(predicted.modes[static_cast<std::size_t>(j)], innovations, mode_beta, mode_miss);
    const Gaussian& imm = posterior.modes[static_cast<std::size_t>(j)];
    EXPECT_LT((imm.mean - pdaf.mean).norm(), 1e-9) << "mode " << j;
    EXPECT_LT((imm.covariance - pdaf.covariance).norm(), 1e-9 * pdaf.covariance.norm())
        << "mode " << j;
  }
  // AND unusable weights (all zero) fall back to exactly this isolated-track form
  const std::array<double, 2> zero = {0.0, 0.0};
  const ImmEstimate fallback = filter.update(predicted, hypotheses, zero, 0.0, pd, pg, lambda);
  EXPECT_NEAR(fallback.probabilities[0], posterior.probabilities[0], 1e-12);
  EXPECT_LT((filter.combine(fallback).mean - filter.combine(posterior).mean).norm(), 1e-12);
}

TEST(ImmFilter, APlotThatFitsOnlyTheTurnMovesTheTurnModeThoughTheTrackWeighsItLow) {
  // GIVEN CV + a 4 g left turn, a track flying east at 250 m/s predicted 6 s on, a plot at
  // the straight prediction weighed 0.9 (say clutter) and one at the turn's weighed 0.1
  Eigen::MatrixXd p(2, 2);
  p << 0.9, 0.1, 0.2, 0.8;
  const auto filter =
      ImmFilter::create({ConstantVelocity{2.0, 1.0}, CoordinatedTurn{0.157, 6.0, 1.0}},
                        {"cv", "ct"}, p, test::layout_2d(), {});
  ASSERT_TRUE(filter);
  StateMat start = StateMat::Zero(4, 4);
  start.diagonal() << 900, 100, 900, 100;
  const ImmEstimate predicted = filter->predict(
      filter->initial(test::gaussian({0, 250, 0, 0}, start), Eigen::Vector2d(0.8, 0.2), 0.0), 6.0);
  const Eigen::VectorXd straight = predicted.modes[0].mean, turn = predicted.modes[1].mean;
  ASSERT_GT(std::hypot(straight[0] - turn[0], straight[2] - turn[2]), 500.0);
  const std::array<PlotHypothesis, 2> hypotheses = {
      filter->hypothesise(predicted, test::cartesian_xy(straight[0], straight[2], 30.0)),
      filter->hypothesise(predicted, test::cartesian_xy(turn[0], turn[2], 30.0))};
  const std::array<double, 2> beta = {0.9, 0.1};
  // WHEN updated
  const ImmEstimate posterior = filter->update(predicted, hypotheses, beta, 0.0, 0.9, 0.99, 1e-6);
  // THEN each mode follows the plot it explains (within a plot sigma), not the track's
  // likelier plot: the turn mode keeps the turn
  const auto distance = [](const Gaussian& g, const Eigen::VectorXd& at) {
    return std::hypot(g.mean[0] - at[0], g.mean[2] - at[2]);
  };
  EXPECT_LT(distance(posterior.modes[0], straight), 30.0);
  EXPECT_LT(distance(posterior.modes[1], turn), 30.0);
  // AND the mode probabilities are the beta-weighted ones (unchanged by this)
  EXPECT_NEAR(posterior.probabilities.sum(), 1.0, 1e-12);
}

TEST(ImmFilter, MissedDetectionKeepsPredictedProbabilities) {
  // GIVEN no plot (beta_0 = 1); THEN mu = c and every mode keeps its prediction
  const ImmFilter filter = two_cv_modes();
  const ImmEstimate predicted = filter.predict(test::two_mode_posterior(), 1.0);
  const ImmEstimate posterior = filter.update(predicted, {}, {}, 1.0, 0.9, 0.99, 1e-6);
  EXPECT_NEAR(posterior.probabilities[0], 0.69, 1e-12);
  EXPECT_EQ(posterior.modes[1].mean, predicted.modes[1].mean);
}

TEST(ImmFilter, NumericFailureKeepsThatModesPredictionAndIsFlagged) {
  // GIVEN a prediction whose mode 2 covariance is broken (negative variance)
  const ImmFilter filter = two_cv_modes();
  ImmEstimate predicted = filter.predict(test::two_mode_posterior(), 1.0);
  predicted.modes[1].covariance = -StateMat::Identity(4, 4) * 100.0;
  const std::array<PlotHypothesis, 1> hypotheses = {
      filter.hypothesise(predicted, test::cartesian_xy(13.0, 0.5, 2.0))};
  EXPECT_TRUE(hypotheses[0].usable);
  EXPECT_FALSE(hypotheses[0].per_mode[1].ok);
  const std::array<double, 1> beta = {0.9};
  // WHEN updated; THEN no throw, mode 2 is flagged and kept, probabilities still sum to 1
  const ImmEstimate posterior = filter.update(predicted, hypotheses, beta, 0.1, 0.9, 0.99, 1e-6);
  EXPECT_EQ(posterior.failed_modes, 2u);
  EXPECT_TRUE(posterior.numeric_failure());
  EXPECT_EQ(posterior.modes[1].mean, predicted.modes[1].mean);
  EXPECT_NEAR(posterior.probabilities.sum(), 1.0, 1e-12);
  EXPECT_GT(posterior.probabilities[0], predicted.probabilities[0]);
}

TEST(ImmFilter, TurnModeWinsInATurn) {
  // GIVEN CV + left/right turns at 3 deg/s (explicit, not the profile's defaults), and a
  // target flying east at 200 m/s that turns left at 3 deg/s after 60 s, plots every 2 s
  // with 20 m noise (fixed seed)
  Eigen::MatrixXd transition(3, 3);
  transition << 0.90, 0.05, 0.05, 0.20, 0.78, 0.02, 0.20, 0.02, 0.78;
  auto filter = ImmFilter::create({ConstantVelocity{1.0, 1.0}, CoordinatedTurn{0.05236, 3.0, 1.0},
                                   CoordinatedTurn{-0.05236, 3.0, 1.0}},
                                  {"cv", "ct_left", "ct_right"}, transition, test::layout_2d(), {});
  ASSERT_TRUE(filter);
  const CoordinatedTurn left{0.05236, 0.0, 0.0};
  const ConstantVelocity straight{0.0, 0.0};
  Gaussian truth = test::gaussian({0, 200, 0, 0}, StateMat::Zero(4, 4));
  ImmEstimate imm = filter->initial(test::gaussian({0, 200, 0, 0}, StateMat::Identity(4, 4) * 400),
                                    Eigen::Vector3d(0.8, 0.1, 0.1), 0.0);
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 20.0);
  double cv_before = 0.0, left_during = 0.0;
  for (int k = 1; k <= 50; ++k) {
    // WHEN the IMM follows it
    const double t = 2.0 * k;
    truth = t <= 60.0 ? predict(straight, test::layout_2d(), truth, 2.0)
                      : predict(left, test::layout_2d(), truth, 2.0);
    imm = filter->predict(imm, t);
    const double nx = noise(rng), ny = noise(rng);
    const std::array<PlotHypothesis, 1> h = {
        filter->hypothesise(imm, test::cartesian_xy(truth.mean[0] + nx, truth.mean[2] + ny, 20.0))};
    const std::array<double, 1> beta = {1.0};
    imm = filter->update(imm, h, beta, 0.0, 0.9, 0.99, 1e-6);
    if (k >= 6 && k <= 30) cv_before += imm.probabilities[0] / 25.0;
    if (k >= 36) left_during += imm.probabilities[1] / 15.0;
    // THEN the position error stays within a few plot sigmas throughout
    const Gaussian combined = filter->combine(imm);
    EXPECT_LT(std::hypot(combined.mean[0] - truth.mean[0], combined.mean[2] - truth.mean[2]), 60.0)
        << "k " << k;
  }
  // AND the CV mode leads on the straight leg, the left-turn mode in the turn
  EXPECT_GT(cv_before, 0.8);
  EXPECT_GT(left_during, 0.75);
}

TEST(ImmFilter, PredictCertainEqualsTheFullPredictionOfAOneModePosterior) {
  // GIVEN CV + a turn mode and a posterior that favours the turn, whose modes differ
  Eigen::MatrixXd transition(2, 2);
  transition << 0.9, 0.1, 0.3, 0.7;
  auto filter = ImmFilter::create({ConstantVelocity{1.0, 1.0}, CoordinatedTurn{0.05, 3.0, 1.0}},
                                  {"cv", "ct"}, transition, test::layout_2d(), {});
  ASSERT_TRUE(filter);
  ImmEstimate posterior = test::two_mode_posterior();
  posterior.probabilities = Eigen::Vector2d(0.4, 0.6);
  // WHEN it is predicted 4 s on as certain of the turn, and the same posterior made certain
  // by hand (mu = (0, 1), every mode the turn's estimate) goes through the full IMM prediction
  const ImmEstimate certain = filter->predict_certain(posterior, 1, 4.0);
  ImmEstimate by_hand = posterior;
  by_hand.modes = {posterior.modes[1], posterior.modes[1]};
  by_hand.probabilities = Eigen::Vector2d(0.0, 1.0);
  ImmEstimate full = filter->predict(by_hand, 4.0);
  full.modes[0] = full.modes[1];
  // THEN both give the same estimates and mode priors (the turn's row of the Markov matrix),
  // to round-off
  ASSERT_EQ(certain.modes.size(), 2U);
  EXPECT_DOUBLE_EQ(certain.time, 4.0);
  for (std::size_t j = 0; j < 2; ++j) {
    EXPECT_LT((certain.modes[j].mean - full.modes[j].mean).norm(), 1e-9);
    EXPECT_LT((certain.modes[j].covariance - full.modes[j].covariance).norm(), 1e-9);
  }
  EXPECT_NEAR(certain.probabilities[0], 0.3, 1e-12);
  EXPECT_NEAR(certain.probabilities[1], 0.7, 1e-12);
}

TEST(ImmFilter, CreateRejectsInconsistentSetups) {
  Eigen::MatrixXd good(2, 2), bad(2, 2);
  good << 0.9, 0.1, 0.2, 0.8;
  bad << 0.9, 0.2, 0.2, 0.8;
  const StateLayout l2 = test::layout_2d();
  EXPECT_FALSE(
      ImmFilter::create({ConstantVelocity{}, ConstantVelocity{}}, {"a", "b"}, bad, l2, {}));
  EXPECT_FALSE(ImmFilter::create({ConstantVelocity{}, ConstantVelocity{}}, {"a"}, good, l2, {}));
  EXPECT_FALSE(ImmFilter::create({ConstantVelocity{}, Singer{}}, {"a", "b"}, good, l2, {}));
  EXPECT_FALSE(ImmFilter::create({ConstantVelocity{}, CoordinatedTurnEstimated{}}, {"a", "b"}, good,
                                 StateLayout{2, true, false}, {}));
  EXPECT_FALSE(ImmFilter::create({ConstantVelocity{}, Singer{1.0, -2.0, 1.0}}, {"a", "b"}, good,
                                 StateLayout{2, true, false}, {}));
  EXPECT_TRUE(ImmFilter::create({ConstantVelocity{}, Singer{}}, {"a", "b"}, good,
                                StateLayout{2, true, false}, {}));
}

TEST(ImmFilter, AugmentedModesMixAndPredict) {
  // GIVEN CV, Singer and CT-with-rate modes sharing the full 3-D layout
  using config::MotionModelType;
  config::TrackingProfile profile;
  profile.motion_models = {
      {.name = "cv", .type = MotionModelType::kConstantVelocity},
      {.name = "singer", .type = MotionModelType::kSinger, .accel_sigma = 10.0},
      {.name = "ctw", .type = MotionModelType::kCoordinatedTurnEstimated, .accel_sigma = 2.0}};
  profile.mode_transition = {{0.9, 0.05, 0.05}, {0.1, 0.85, 0.05}, {0.1, 0.05, 0.85}};
  auto filter = ImmFilter::from_profile(profile);
  ASSERT_TRUE(filter) << filter.error().message;
  EXPECT_EQ(filter->layout().size(), 10);
  StateMat P0 = StateMat::Identity(10, 10) * 100.0;
  P0(9, 9) = 0.05 * 0.05;
  Gaussian start;
  start.mean = StateVec::Zero(10);
  start.mean << 0, 200, 0, 0, 3000, 0, 0, 0, 0, 0.01;
  start.covariance = P0;
  ImmEstimate imm = filter->initial(start, Eigen::Vector3d(0.6, 0.2, 0.2), 0.0);
  for (int k = 1; k <= 5; ++k) {
    imm = filter->predict(imm, 2.0 * k);
    // THEN the CV mode has zeroed acceleration, every mode stays finite and symmetric
    EXPECT_EQ(imm.modes[0].mean[6], 0.0);
    for (const Gaussian& mode : imm.modes) {
      EXPECT_TRUE(mode.covariance.allFinite());
      EXPECT_LT((mode.covariance - mode.covariance.transpose()).norm(), 1e-9);
    }
  }
}

}  // namespace
}  // namespace skytrack
