#include "skytrack/filter/pda.hpp"

#include <array>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "filter_test_support.hpp"

namespace skytrack {
namespace {

const config::MeasurementSpec kEkf{};

Gaussian predicted_state() {
  StateMat A(4, 4);
  A << 3, 1, 0, 0.5, 0, 2, 0.3, 0, 0.1, 0, 4, 1, 0, 0.2, 0, 1;
  return test::gaussian({30, -2, 40, 1.5}, A * A.transpose() + StateMat::Identity(4, 4));
}

TEST(PdaUpdate, EqualsBarShalomPdaWhenSAndKAreCommon) {
  // GIVEN three Cartesian plots (common H, S, K) and weights beta_0 = 0.1, beta = .5 .3 .1
  const Gaussian predicted = predicted_state();
  const StateLayout layout = test::layout_2d();
  const std::array<PlotMeasurement, 3> plots = {test::cartesian_xy(33, 37, 2.5),
                                                test::cartesian_xy(28, 44, 2.5),
                                                test::cartesian_xy(31, 39, 2.5)};
  std::vector<Innovation> innovations;
  for (const PlotMeasurement& plot : plots) {
    innovations.push_back(innovate(predicted, layout, plot, kEkf));
  }
  const std::array<double, 3> beta = {0.5, 0.3, 0.1};
  const double beta0 = 0.1;
  // WHEN the mixture update runs
  const Gaussian got = pda_update(predicted, innovations, beta, beta0);
  // THEN it is Bar-Shalom's PDA: x = x- + K nu, nu = sum beta_i nu_i,
  //   P = beta0 P- + (1 - beta0) (P- - K S K') + K (sum beta_i nu_i nu_i' - nu nu') K'
  const GainMat& K = innovations[0].gain;
  const MeasMat& S = innovations[0].S;
  MeasVec nu = MeasVec::Zero(2);
  MeasMat spread = MeasMat::Zero(2, 2);
  for (int i = 0; i < 3; ++i) {
    nu += beta[i] * innovations[i].residual;
    spread += beta[i] * innovations[i].residual * innovations[i].residual.transpose();
  }
  spread -= nu * nu.transpose();
  const StateVec x = predicted.mean + K * nu;
  const StateMat Pc = predicted.covariance - K * S * K.transpose();
  const StateMat P = beta0 * predicted.covariance + (1 - beta0) * Pc + K * spread * K.transpose();
  EXPECT_LT((got.mean - x).norm(), 1e-12);
  EXPECT_LT((got.covariance - P).norm(), 1e-10);
}

TEST(PdaUpdate, CertainSinglePlotEqualsKalmanUpdate) {
  // GIVEN beta = (miss 0, plot 1); THEN PDA is the Kalman update
  const Gaussian predicted = predicted_state();
  const Innovation innovation =
      innovate(predicted, test::layout_2d(), test::polar_2d(52.0, 0.6, 1.0, 0.01), kEkf);
  ASSERT_TRUE(innovation.ok);
  const std::array<double, 1> beta = {1.0};
  const Gaussian pda = pda_update(predicted, std::span(&innovation, 1), beta, 0.0);
  const Gaussian kf = kalman_update(predicted, innovation);
  EXPECT_LT((pda.mean - kf.mean).norm(), 1e-12);
  EXPECT_LT((pda.covariance - kf.covariance).norm(), 1e-12);
}

TEST(PdaUpdate, CertainMissKeepsThePrediction) {
  const Gaussian predicted = predicted_state();
  const Innovation innovation =
      innovate(predicted, test::layout_2d(), test::cartesian_xy(33, 37, 2.5), kEkf);
  const std::array<double, 1> beta = {0.0};
  const Gaussian pda = pda_update(predicted, std::span(&innovation, 1), beta, 1.0);
  EXPECT_EQ(pda.mean, predicted.mean);
  EXPECT_LT((pda.covariance - predicted.covariance).norm(), 1e-12);
}

TEST(PdaUpdate, RenormalisesWeightsAndDropsFailedInnovations) {
  // GIVEN two plots, one of whose innovations failed, and unnormalised weights
  const Gaussian predicted = predicted_state();
  std::vector<Innovation> innovations = {
      innovate(predicted, test::layout_2d(), test::cartesian_xy(33, 37, 2.5), kEkf),
      innovate(predicted, test::layout_2d(), test::cartesian_xy(28, 44, 2.5), kEkf)};
  innovations[1].ok = false;
  const std::array<double, 2> beta = {0.6, 0.3};
  // WHEN updated; THEN it equals the update with the failed plot removed, weights (0.6, 0.2)
  // renormalised to (0.75, 0.25)
  const Gaussian got = pda_update(predicted, innovations, beta, 0.2);
  const std::array<double, 1> clean_beta = {0.75};
  const Gaussian expected =
      pda_update(predicted, std::span(innovations.data(), 1), clean_beta, 0.25);
  EXPECT_LT((got.mean - expected.mean).norm(), 1e-12);
  EXPECT_LT((got.covariance - expected.covariance).norm(), 1e-10);
}

TEST(PdaWeights, MatchTheParametricPdaFormula) {
  // GIVEN PD = 0.9, PG = 0.99, lambda = 1e-4 and likelihoods L = (2e-4, 5e-5)
  const std::array<double, 2> likelihoods = {2e-4, 5e-5};
  std::array<double, 2> beta{};
  const double beta0 = pda_weights(likelihoods, 0.9, 0.99, 1e-4, beta);
  // THEN by hand: D = 1 - 0.891 + 9000 * 2.5e-4 = 2.359,
  //   beta0 = 0.109 / 2.359, beta1 = 1.8 / 2.359, beta2 = 0.45 / 2.359
  EXPECT_NEAR(beta0, 0.109 / 2.359, 1e-14);
  EXPECT_NEAR(beta[0], 1.8 / 2.359, 1e-14);
  EXPECT_NEAR(beta[1], 0.45 / 2.359, 1e-14);
  // AND without clutter (lambda -> 0) all weight goes to the plots
  EXPECT_EQ(pda_weights(likelihoods, 0.9, 0.99, 0.0, beta), 0.0);
  EXPECT_NEAR(beta[0], 0.8, 1e-14);
  // AND with nothing usable the miss is certain
  const std::array<double, 2> nothing = {0.0, 0.0};
  EXPECT_EQ(pda_weights(nothing, 0.9, 0.99, 1e-4, beta), 1.0);
}

}  // namespace
}  // namespace skytrack
