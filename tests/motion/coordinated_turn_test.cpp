#include "skytrack/motion/coordinated_turn.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "motion_test_support.hpp"
#include "skytrack/motion/constant_velocity.hpp"
#include "skytrack/motion/motion_model.hpp"

namespace skytrack {
namespace {

using test::make_layout;

TEST(CoordinatedTurn, TransitionAndNoiseMatchHandValues) {
  // GIVEN w = 0.1 rad/s, accel_sigma = 3 (q = 9), dt = 2 s: u = 0.2, by hand
  //   sin(u)/w = 1.9866933079506122, (1-cos u)/w = 0.19933422158758374,
  //   cos u = 0.9800665778412416, sin u = 0.19866933079506122,
  //   Q_pp = 9 * 2 (u - sin u)/w^3 = 23.9520456888983, Q_{x,vx} = 9 (1-cos u)/w^2 =
  //   17.940079942882534, Q_{x,vy} = 9 (u - sin u)/w^2 = 1.197602284444915, Q_vv = 18
  const CoordinatedTurn ct{.turn_rate = 0.1, .accel_sigma = 3.0};
  const StateLayout layout = make_layout(2);
  // WHEN F and Q are built
  const StateMat F = ct.transition(layout, 2.0);
  const StateMat Q = ct.process_noise(layout, 2.0);
  // THEN they match ([x vx y vy] order)
  const double a = 1.9866933079506122, b = 0.19933422158758374;
  const double c = 0.9800665778412416, s = 0.19866933079506122;
  StateMat F_hand(4, 4);
  F_hand << 1, a, 0, -b,  //
      0, c, 0, -s,        //
      0, b, 1, a,         //
      0, s, 0, c;
  EXPECT_LT((F - F_hand).norm(), 1e-12);
  const double pp = 23.9520456888983, same = 17.940079942882534, cross = 1.197602284444915;
  StateMat Q_hand(4, 4);
  Q_hand << pp, same, 0, cross,  //
      same, 18, -cross, 0,       //
      0, -cross, pp, same,       //
      cross, 0, same, 18;
  EXPECT_LT((Q - Q_hand).norm(), 1e-10);
}

TEST(CoordinatedTurn, NoiseIsTheExactDiscretisation) {
  // GIVEN a right turn and a 3-D layout; WHEN Q(T) is built
  // THEN it equals integral_0^T F(s) Qc F(s)' ds (white acceleration on vx, vy, vz)
  const CoordinatedTurn ct{.turn_rate = -0.3, .accel_sigma = 2.0, .vertical_accel_sigma = 0.7};
  const StateLayout layout = make_layout(3);
  StateMat Qc = StateMat::Zero(6, 6);
  Qc(1, 1) = Qc(3, 3) = 4.0;
  Qc(5, 5) = 0.49;
  const StateMat expected =
      test::van_loan_noise([&](double t) { return ct.transition(layout, t); }, Qc, 7.0);
  EXPECT_LT((ct.process_noise(layout, 7.0) - expected).norm(), 1e-8 * expected.norm());
}

TEST(CoordinatedTurn, NoiseFreeStateMovesOnTheRightCircle) {
  // GIVEN a target at the origin flying east at 100 m/s turning LEFT at 0.1 rad/s:
  //   the circle's centre is 1000 m north of it, at (0, 1000)
  const CoordinatedTurn ct{.turn_rate = 0.1, .accel_sigma = 0.0};
  const StateLayout layout = make_layout(2);
  Gaussian state;
  state.mean = StateVec::Zero(4);
  state.mean[1] = 100.0;
  state.covariance = StateMat::Zero(4, 4);
  for (int step = 1; step <= 20; ++step) {
    // WHEN it is predicted in 1.3 s steps
    state = predict(ct, layout, state, 1.3);
    const double t = 1.3 * step;
    // THEN it stays on the circle at x = R sin(wt), y = R (1 - cos wt), speed 100
    EXPECT_NEAR(std::hypot(state.mean[0], state.mean[2] - 1000.0), 1000.0, 1e-8);
    EXPECT_NEAR(state.mean[0], 1000.0 * std::sin(0.1 * t), 1e-8);
    EXPECT_NEAR(state.mean[2], 1000.0 * (1.0 - std::cos(0.1 * t)), 1e-8);
    EXPECT_NEAR(std::hypot(state.mean[1], state.mean[3]), 100.0, 1e-9);
  }
}

TEST(CoordinatedTurn, ZeroTurnRateIsConstantVelocity) {
  // GIVEN w = 0 and w = 1e-9; THEN F and Q are the CV ones (same sigmas)
  const StateLayout layout = make_layout(3, true, true);
  const ConstantVelocity cv{.accel_sigma = 2.0, .vertical_accel_sigma = 0.5};
  for (double w : {0.0, 1e-9, -1e-7}) {
    const CoordinatedTurn ct{.turn_rate = w, .accel_sigma = 2.0, .vertical_accel_sigma = 0.5};
    EXPECT_LT((ct.transition(layout, 4.0) - cv.transition(layout, 4.0)).norm(), 1e-5);
    EXPECT_LT((ct.process_noise(layout, 4.0) - cv.process_noise(layout, 4.0)).norm(), 1e-5);
  }
}

}  // namespace
}  // namespace skytrack
