#include "skytrack/motion/constant_velocity.hpp"

#include <gtest/gtest.h>

#include "motion_test_support.hpp"
#include "skytrack/motion/motion_model.hpp"

namespace skytrack {
namespace {

using test::make_layout;

TEST(ConstantVelocity, TransitionAndNoiseMatchHandValuesIn2d) {
  // GIVEN accel_sigma = 2 (q = 4 m^2/s^3) and dt = 2 s
  const ConstantVelocity cv{.accel_sigma = 2.0, .vertical_accel_sigma = 1.0};
  const StateLayout layout = make_layout(2);
  // WHEN F and Q are built
  const StateMat F = cv.transition(layout, 2.0);
  const StateMat Q = cv.process_noise(layout, 2.0);
  // THEN per axis F = [1 2; 0 1], Q = 4 [8/3 2; 2 2] and the axes are uncoupled
  StateMat F_hand(4, 4), Q_hand(4, 4);
  F_hand << 1, 2, 0, 0,  //
      0, 1, 0, 0,        //
      0, 0, 1, 2,        //
      0, 0, 0, 1;
  Q_hand << 32.0 / 3, 8, 0, 0,  //
      8, 8, 0, 0,               //
      0, 0, 32.0 / 3, 8,        //
      0, 0, 8, 8;
  EXPECT_LT((F - F_hand).norm(), 1e-12);
  EXPECT_LT((Q - Q_hand).norm(), 1e-12);
}

TEST(ConstantVelocity, VerticalChannelUsesVerticalSigma) {
  // GIVEN a 3-D layout, horizontal sigma 2 and vertical sigma 0.5 (q_z = 0.25)
  const ConstantVelocity cv{.accel_sigma = 2.0, .vertical_accel_sigma = 0.5};
  // WHEN Q is built for dt = 2
  const StateMat Q = cv.process_noise(make_layout(3), 2.0);
  // THEN the z block is 0.25 [8/3 2; 2 2]
  EXPECT_NEAR(Q(4, 4), 0.25 * 8.0 / 3.0, 1e-12);
  EXPECT_NEAR(Q(4, 5), 0.5, 1e-12);
  EXPECT_NEAR(Q(5, 5), 0.5, 1e-12);
  EXPECT_NEAR(Q(0, 0), 32.0 / 3.0, 1e-12);
}

TEST(ConstantVelocity, ZeroesUnusedAccelerationAndKeepsTurnRate) {
  // GIVEN a full 2-D layout [x vx y vy ax ay w] with non-zero acceleration and turn rate
  const StateLayout layout = make_layout(2, true, true);
  Gaussian prior;
  prior.mean.resize(7);
  prior.mean << 10, 1, 20, 2, 3, 4, 0.1;
  prior.covariance = StateMat::Identity(7, 7);
  // WHEN a CV mode predicts 1 s
  const Gaussian predicted = predict(ConstantVelocity{}, layout, prior, 1.0);
  // THEN acceleration and its covariance are 0, w and its variance unchanged,
  //      position moved by velocity only
  EXPECT_EQ(predicted.mean[4], 0.0);
  EXPECT_EQ(predicted.mean[5], 0.0);
  EXPECT_EQ(predicted.covariance.row(4).norm(), 0.0);
  EXPECT_EQ(predicted.covariance.col(5).norm(), 0.0);
  EXPECT_DOUBLE_EQ(predicted.mean[6], 0.1);
  EXPECT_DOUBLE_EQ(predicted.covariance(6, 6), 1.0);
  EXPECT_DOUBLE_EQ(predicted.mean[0], 11.0);
  EXPECT_DOUBLE_EQ(predicted.mean[2], 22.0);
}

TEST(ConstantVelocity, ZeroDtIsIdentity) {
  // GIVEN any prior; WHEN dt = 0; THEN the prediction is the prior, bit for bit
  Gaussian prior;
  prior.mean = StateVec::LinSpaced(4, 1.0, 4.0);
  prior.covariance = 3.0 * StateMat::Identity(4, 4);
  const Gaussian predicted = predict(ConstantVelocity{}, make_layout(2), prior, 0.0);
  EXPECT_EQ(predicted.mean, prior.mean);
  EXPECT_EQ(predicted.covariance, prior.covariance);
}

TEST(ConstantVelocity, NegativeDtRetrodicts) {
  // GIVEN a prior at t = 5 s
  const ConstantVelocity cv{.accel_sigma = 1.5};
  const StateLayout layout = make_layout(2);
  Gaussian prior;
  prior.mean.resize(4);
  prior.mean << 100, 10, -50, 5;
  prior.covariance = StateMat::Identity(4, 4) * 4.0;
  // WHEN it is predicted back to t = 2 s
  const Gaussian back = predict(cv, layout, prior, -3.0);
  // THEN the mean moves back along the velocity and P = F(-3) (P + Q(3)) F(-3)'
  EXPECT_NEAR(back.mean[0], 70.0, 1e-12);
  EXPECT_NEAR(back.mean[2], -65.0, 1e-12);
  const StateMat F = cv.transition(layout, -3.0);
  const StateMat expected = F * (prior.covariance + cv.process_noise(layout, 3.0)) * F.transpose();
  EXPECT_LT((back.covariance - expected).norm(), 1e-10);
  EXPECT_LT((F * cv.transition(layout, 3.0) - StateMat::Identity(4, 4)).norm(), 1e-12);
}

}  // namespace
}  // namespace skytrack
