#include "skytrack/motion/constant_acceleration.hpp"

#include <gtest/gtest.h>

#include "motion_test_support.hpp"
#include "skytrack/motion/motion_model.hpp"

namespace skytrack {
namespace {

using test::make_layout;

TEST(ConstantAcceleration, TransitionAndNoiseMatchHandValues) {
  // GIVEN jerk_sigma = 3 (q = 9 m^2/s^5), dt = 2 s, the 2-D layout [x vx y vy ax ay]
  const ConstantAcceleration ca{.jerk_sigma = 3.0, .vertical_accel_sigma = 1.0};
  const StateLayout layout = make_layout(2, true);
  // WHEN F and Q are built
  const StateMat F = ca.transition(layout, 2.0);
  const StateMat Q = ca.process_noise(layout, 2.0);
  // THEN on x (indices 0, 1, 4): F = [1 2 2; 0 1 2; 0 0 1],
  //      Q = 9 [32/20 16/8 8/6; 16/8 8/3 4/2; 8/6 4/2 2] = [14.4 18 12; 18 24 18; 12 18 18]
  const int idx[3] = {0, 1, 4};
  const double F_hand[3][3] = {{1, 2, 2}, {0, 1, 2}, {0, 0, 1}};
  const double Q_hand[3][3] = {{14.4, 18, 12}, {18, 24, 18}, {12, 18, 18}};
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(F(idx[r], idx[c]), F_hand[r][c], 1e-12) << r << "," << c;
      EXPECT_NEAR(Q(idx[r], idx[c]), Q_hand[r][c], 1e-12) << r << "," << c;
    }
  }
  // AND y (2, 3, 5) has the same blocks, uncoupled from x
  EXPECT_NEAR(F(2, 5), 2.0, 1e-12);
  EXPECT_NEAR(Q(2, 5), 12.0, 1e-12);
  EXPECT_EQ(Q(0, 2), 0.0);
  EXPECT_EQ(F(0, 5), 0.0);
}

TEST(ConstantAcceleration, VerticalChannelIsNearlyConstantVelocityAndAzStaysZero) {
  // GIVEN a 3-D layout with az, a state with az = 2 m/s^2
  const ConstantAcceleration ca{.jerk_sigma = 1.0, .vertical_accel_sigma = 0.5};
  const StateLayout layout = make_layout(3, true);
  Gaussian prior;
  prior.mean = StateVec::Zero(9);
  prior.mean[5] = 10.0;                            // vz
  prior.mean[layout.acceleration_index(2)] = 2.0;  // az
  prior.covariance = StateMat::Identity(9, 9);
  // WHEN predicted 2 s
  const Gaussian predicted = predict(ca, layout, prior, 2.0);
  // THEN z moves at constant vz, az is 0 with zero variance, z noise is 0.25 [8/3 2; 2 2]
  EXPECT_NEAR(predicted.mean[4], 20.0, 1e-12);
  EXPECT_EQ(predicted.mean[layout.acceleration_index(2)], 0.0);
  EXPECT_EQ(predicted.covariance(8, 8), 0.0);
  const StateMat Q = ca.process_noise(layout, 2.0);
  EXPECT_NEAR(Q(4, 4), 0.25 * 8.0 / 3.0, 1e-12);
  EXPECT_NEAR(Q(5, 5), 0.5, 1e-12);
}

TEST(ConstantAcceleration, PredictsAParabola) {
  // GIVEN x = 0, vx = 10, ax = 2 and no noise
  const StateLayout layout = make_layout(2, true);
  Gaussian prior;
  prior.mean = StateVec::Zero(6);
  prior.mean[1] = 10.0;
  prior.mean[4] = 2.0;
  prior.covariance = StateMat::Zero(6, 6);
  // WHEN predicted 3 s
  const Gaussian predicted = predict(ConstantAcceleration{.jerk_sigma = 0.0}, layout, prior, 3.0);
  // THEN x = 10*3 + 2*9/2 = 39, vx = 16
  EXPECT_NEAR(predicted.mean[0], 39.0, 1e-12);
  EXPECT_NEAR(predicted.mean[1], 16.0, 1e-12);
  EXPECT_NEAR(predicted.mean[4], 2.0, 1e-12);
}

}  // namespace
}  // namespace skytrack
