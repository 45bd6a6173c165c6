// The IMM's Markov chain in time: the matrix is given per interval, and a prediction over
// several intervals lets the modes switch once in each.
#include <gtest/gtest.h>

#include "filter_test_support.hpp"
#include "skytrack/filter/imm_filter.hpp"

namespace skytrack {
namespace {

TEST(ImmFilter, MarkovMatrixScalesWithThePredictionInterval) {
  // GIVEN p = [0.9 0.1; 0.2 0.8] given per 4 s
  Eigen::MatrixXd p(2, 2);
  p << 0.9, 0.1, 0.2, 0.8;
  const auto filter = ImmFilter::create({ConstantVelocity{0.0, 1.0}, ConstantVelocity{1.0, 1.0}},
                                        {"quiet", "noisy"}, p, test::layout_2d(), {}, 4.0);
  ASSERT_TRUE(filter) << filter.error().message;
  const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(2, 2);
  // THEN 0 s switches nothing, 4 s is P, 8 s is P^2, 2 s is halfway between I and P, and
  // 6 s is P (I + (P - I) / 2); a backward prediction switches nothing.
  EXPECT_LT((filter->transition_over(0.0) - identity).norm(), 1e-15);
  EXPECT_LT((filter->transition_over(4.0) - p).norm(), 1e-15);
  EXPECT_LT((filter->transition_over(8.0) - p * p).norm(), 1e-15);
  Eigen::MatrixXd half(2, 2);
  half << 0.95, 0.05, 0.1, 0.9;
  EXPECT_LT((filter->transition_over(2.0) - half).norm(), 1e-15);
  EXPECT_LT((filter->transition_over(6.0) - p * half).norm(), 1e-15);
  EXPECT_LT((filter->transition_over(-1.0) - identity).norm(), 1e-15);
  // Every interval gives a stochastic matrix; a long one reaches the stationary mix (2/3, 1/3).
  for (const double dt : {0.3, 3.9, 17.0, 1e6}) {
    const Eigen::MatrixXd t = filter->transition_over(dt);
    EXPECT_LT((t.rowwise().sum() - Eigen::Vector2d::Ones()).norm(), 1e-12) << dt;
    EXPECT_GE(t.minCoeff(), 0.0) << dt;
  }
  EXPECT_NEAR(filter->transition_over(1e6)(1, 0), 2.0 / 3.0, 1e-9);
  // AND predict mixes with the interval's matrix: c = T(dt)' mu.
  const ImmEstimate predicted = filter->predict(test::two_mode_posterior(), 2.0);
  EXPECT_NEAR(predicted.probabilities[0], 0.95 * 0.7 + 0.1 * 0.3, 1e-12);
  // WITHOUT an interval the matrix applies once per prediction, whatever its length.
  const auto per_prediction =
      ImmFilter::create({ConstantVelocity{0.0, 1.0}, ConstantVelocity{1.0, 1.0}},
                        {"quiet", "noisy"}, p, test::layout_2d(), {});
  ASSERT_TRUE(per_prediction);
  EXPECT_LT((per_prediction->transition_over(0.5) - p).norm(), 1e-15);
}

TEST(ImmFilter, APredictionOverSeveralIntervalsIsMadeInStepsThatCompose) {
  // GIVEN CV + a turn mode, p = [0.9 0.1; 0.2 0.8] given per 4 s, and a posterior whose modes
  // differ
  Eigen::MatrixXd p(2, 2);
  p << 0.9, 0.1, 0.2, 0.8;
  const auto filter =
      ImmFilter::create({ConstantVelocity{1.0, 1.0}, CoordinatedTurn{0.05, 3.0, 1.0}}, {"cv", "ct"},
                        p, test::layout_2d(), {}, 4.0);
  ASSERT_TRUE(filter) << filter.error().message;
  const ImmEstimate posterior = test::two_mode_posterior();
  // WHEN it is predicted 8 s on in one call, and 4 s then 4 s more
  const ImmEstimate whole = filter->predict(posterior, 8.0);
  const ImmEstimate twice = filter->predict(filter->predict(posterior, 4.0), 8.0);
  // THEN both are the same (the modes interact once per interval), to round-off
  for (std::size_t j = 0; j < 2; ++j) {
    EXPECT_LT((whole.modes[j].mean - twice.modes[j].mean).norm(), 1e-9);
    EXPECT_LT((whole.modes[j].covariance - twice.modes[j].covariance).norm(), 1e-9);
  }
  // AND the mode priors are the chain's over two intervals, c = (P^2)' mu
  const Eigen::Vector2d c = (p * p).transpose() * posterior.probabilities;
  EXPECT_NEAR(whole.probabilities[0], c[0], 1e-12);
  EXPECT_NEAR(whole.probabilities[1], c[1], 1e-12);
  // AND a 6 s prediction is one interval, then the 2 s left: its priors are the chain's over
  // 6 s, c = T(6)' mu (transition_over), and its estimates those of 4 s then 2 s
  const Eigen::Vector2d c6 = filter->transition_over(6.0).transpose() * posterior.probabilities;
  const ImmEstimate six = filter->predict(posterior, 6.0);
  EXPECT_NEAR(six.probabilities[0], c6[0], 1e-12);
  const ImmEstimate steps = filter->predict(filter->predict(posterior, 4.0), 6.0);
  for (std::size_t j = 0; j < 2; ++j) {
    EXPECT_LT((six.modes[j].mean - steps.modes[j].mean).norm(), 1e-9);
  }
  // AND just over one interval is just over one step: 4.001 s differs from 4 s by no more
  // than the motion over the extra millisecond (the prediction is continuous in dt)
  const ImmEstimate over = filter->predict(posterior, 4.001);
  const ImmEstimate at = filter->predict(posterior, 4.0);
  for (std::size_t j = 0; j < 2; ++j) {
    EXPECT_LT((over.modes[j].mean - at.modes[j].mean).norm(), 0.05);
  }
}

TEST(ImmFilter, ATurnBegunWithinALongPredictionIsLikelierThanWithOneSwitch) {
  // GIVEN CV + a 4 g left turn (0.157 rad/s at 250 m/s), the switching given per 4 s, and a
  // track flying east, sure of straight flight (mu 0.9 / 0.1), plots good to 30 m
  Eigen::MatrixXd p(2, 2);
  p << 0.9, 0.1, 0.2, 0.8;
  const auto stepped =
      ImmFilter::create({ConstantVelocity{2.0, 1.0}, CoordinatedTurn{0.157, 6.0, 1.0}},
                        {"cv", "ct"}, p, test::layout_2d(), {}, 4.0);
  // AND the same filter whose matrix is given for the whole 6 s look, so it switches once
  const auto once =
      ImmFilter::create({ConstantVelocity{2.0, 1.0}, CoordinatedTurn{0.157, 6.0, 1.0}},
                        {"cv", "ct"}, stepped->transition_over(6.0), test::layout_2d(), {}, 6.0);
  ASSERT_TRUE(stepped && once);
  StateMat start = StateMat::Zero(4, 4);
  start.diagonal() << 900, 100, 900, 100;
  const ImmEstimate posterior =
      stepped->initial(test::gaussian({0, 250, 0, 0}, start), Eigen::Vector2d(0.9, 0.1), 0.0);
  // WHEN the target flies straight 2 s, then turns for 4 s, and is seen 6 s on
  Gaussian truth = test::gaussian({0, 250, 0, 0}, StateMat::Zero(4, 4));
  truth = predict(ConstantVelocity{0.0, 0.0}, test::layout_2d(), truth, 2.0);
  truth = predict(CoordinatedTurn{0.157, 0.0, 0.0}, test::layout_2d(), truth, 4.0);
  const PlotMeasurement plot = test::cartesian_xy(truth.mean[0], truth.mean[2], 30.0);
  const PlotHypothesis with_steps = stepped->hypothesise(stepped->predict(posterior, 6.0), plot);
  const PlotHypothesis with_one = once->hypothesise(once->predict(posterior, 6.0), plot);
  // THEN the turn mode, having mixed the straight flight in after the first 3 s, explains the
  // plot far better (its NIS smaller), and so does the track as a whole (its likelihood)
  ASSERT_TRUE(with_steps.usable && with_one.usable);
  EXPECT_LT(with_steps.per_mode[1].nis, 0.5 * with_one.per_mode[1].nis);
  EXPECT_GT(with_steps.log_likelihood, with_one.log_likelihood + 3.0);
}

}  // namespace
}  // namespace skytrack
