#include "skytrack/motion/coordinated_turn_estimated.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "motion_test_support.hpp"
#include "skytrack/motion/coordinated_turn.hpp"
#include "skytrack/motion/motion_model.hpp"

namespace skytrack {
namespace {

using test::make_layout;

StateMat numerical_jacobian(const CoordinatedTurnEstimated& model, const StateLayout& layout,
                            const StateVec& x, double dt) {
  const int n = layout.size();
  StateMat J(n, n);
  for (int k = 0; k < n; ++k) {
    const double h = 1e-5 * std::max(1.0, std::abs(x[k]));
    StateVec plus = x, minus = x;
    plus[k] += h;
    minus[k] -= h;
    J.col(k) = (model.propagate(layout, plus, dt) - model.propagate(layout, minus, dt)) / (2 * h);
  }
  return J;
}

StateVec state_with_turn_rate(const StateLayout& layout, double w) {
  StateVec x = StateVec::Zero(layout.size());
  x[0] = 1200.0;
  x[1] = 180.0;
  x[2] = -300.0;
  x[3] = -95.0;
  if (layout.dims == 3) {
    x[4] = 5000.0;
    x[5] = 3.0;
  }
  x[layout.turn_rate_index()] = w;
  return x;
}

TEST(CoordinatedTurnEstimated, JacobianEqualsNumericalJacobianIncludingNearZeroTurnRate) {
  const CoordinatedTurnEstimated model{.accel_sigma = 2.0, .turn_rate_sigma = 0.01};
  for (int dims : {2, 3}) {
    const StateLayout layout = make_layout(dims, dims == 3, true);
    for (double w : {0.2, -0.05, 1e-2, 1e-4, 1e-7, 0.0, -3e-6}) {
      for (double dt : {0.5, 4.0, -2.0}) {
        // GIVEN a state turning at w; WHEN the analytic Jacobian is built
        const StateVec x = state_with_turn_rate(layout, w);
        const StateMat analytic = model.jacobian(layout, x, dt);
        // THEN it equals central differences of f (to their own accuracy)
        const StateMat numeric = numerical_jacobian(model, layout, x, dt);
        EXPECT_LT((analytic - numeric).cwiseAbs().maxCoeff(), 2e-5)
            << "dims " << dims << " w " << w << " dt " << dt << "\n"
            << analytic - numeric;
      }
    }
  }
}

TEST(CoordinatedTurnEstimated, ZeroTurnRateLimitOfTheTurnRateColumn) {
  // GIVEN w = 0 exactly; THEN dx'/dw = -T^2 vy / 2, dy'/dw = T^2 vx / 2,
  //   dvx'/dw = -T vy, dvy'/dw = T vx
  const CoordinatedTurnEstimated model;
  const StateLayout layout = make_layout(2, false, true);
  const StateVec x = state_with_turn_rate(layout, 0.0);
  const StateMat F = model.jacobian(layout, x, 2.0);
  const int w = layout.turn_rate_index();
  EXPECT_NEAR(F(0, w), -4.0 * -95.0 / 2.0, 1e-9);
  EXPECT_NEAR(F(2, w), 4.0 * 180.0 / 2.0, 1e-9);
  EXPECT_NEAR(F(1, w), -2.0 * -95.0, 1e-9);
  EXPECT_NEAR(F(3, w), 2.0 * 180.0, 1e-9);
  EXPECT_EQ(F(w, w), 1.0);
}

TEST(CoordinatedTurnEstimated, PropagationIsTheFixedRateTurnAtTheStateRate) {
  // GIVEN w = 0.08 in the state; THEN f(x) = F_ct(0.08) x and w is unchanged
  const StateLayout layout = make_layout(3, false, true);
  const StateVec x = state_with_turn_rate(layout, 0.08);
  const CoordinatedTurn fixed{.turn_rate = 0.08};
  const StateVec expected = fixed.transition(layout, 3.0) * x;
  const StateVec got = CoordinatedTurnEstimated{}.propagate(layout, x, 3.0);
  EXPECT_LT((got - expected).norm(), 1e-9);
  EXPECT_EQ(got[layout.turn_rate_index()], 0.08);
}

TEST(CoordinatedTurnEstimated, NoiseAddsTurnRateRandomWalk) {
  // GIVEN turn_rate_sigma = 0.01 rad/s^2; WHEN Q over 4 s; THEN Q_ww = 1e-4 * 4 and the
  //   kinematic block is the fixed-rate turn's Q at the state's w
  const CoordinatedTurnEstimated model{.accel_sigma = 2.0, .turn_rate_sigma = 0.01};
  const StateLayout layout = make_layout(2, false, true);
  const StateVec x = state_with_turn_rate(layout, 0.05);
  const StateMat Q = model.process_noise(layout, x, 4.0);
  const int w = layout.turn_rate_index();
  EXPECT_NEAR(Q(w, w), 4e-4, 1e-15);
  const StateMat Q_ct =
      CoordinatedTurn{.turn_rate = 0.05, .accel_sigma = 2.0}.process_noise(layout, 4.0);
  EXPECT_LT((Q.topLeftCorner(4, 4) - Q_ct.topLeftCorner(4, 4)).norm(), 1e-12);
}

TEST(CoordinatedTurnEstimated, EkfPredictionUsesTheJacobian) {
  // GIVEN a Gaussian with w; WHEN predicted; THEN P' = J P J' + Q and x' = f(x)
  const CoordinatedTurnEstimated model{.accel_sigma = 1.0, .turn_rate_sigma = 0.02};
  const StateLayout layout = make_layout(2, false, true);
  Gaussian prior;
  prior.mean = state_with_turn_rate(layout, 0.03);
  prior.covariance = StateMat::Identity(5, 5);
  prior.covariance(4, 4) = 0.01 * 0.01;
  const Gaussian predicted = predict(model, layout, prior, 2.0);
  const StateMat J = model.jacobian(layout, prior.mean, 2.0);
  const StateMat expected =
      J * prior.covariance * J.transpose() + model.process_noise(layout, prior.mean, 2.0);
  EXPECT_LT((predicted.covariance - expected).norm(), 1e-9 * expected.norm());
  EXPECT_LT((predicted.mean - model.propagate(layout, prior.mean, 2.0)).norm(), 1e-12);
}

}  // namespace
}  // namespace skytrack
