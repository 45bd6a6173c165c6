#include "skytrack/motion/singer.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "motion_test_support.hpp"
#include "skytrack/motion/constant_acceleration.hpp"

namespace skytrack {
namespace {

using test::make_layout;

TEST(Singer, TransitionAndNoiseMatchHandValues) {
  // GIVEN tau = 5 s (alpha = 0.2), sigma_m = 3, dt = 2 s (u = 0.4). By hand from Singer's
  //   closed forms: F13 = (u - 1 + e^-u)/alpha^2 = 1.7580011508909834,
  //   F23 = (1 - e^-u)/alpha = 1.6483997698218034, F33 = e^-u = 0.6703200460356393,
  //   Q = 2 alpha sigma^2 * g: Q11 = 4.644162519873706, Q12 = 5.563022483761226,
  //   Q13 = 3.243374787210054, Q22 = 7.189024505700502, Q23 = 4.89099924206743,
  //   Q33 = 4.956039322945006
  const Singer singer{.accel_sigma = 3.0, .time_constant = 5.0};
  const StateLayout layout = make_layout(2, true);
  const StateMat F = singer.transition(layout, 2.0);
  const StateMat Q = singer.process_noise(layout, 2.0);
  const int idx[3] = {0, 1, 4};  // x, vx, ax
  const double F_hand[3][3] = {
      {1, 2, 1.7580011508909834}, {0, 1, 1.6483997698218034}, {0, 0, 0.6703200460356393}};
  const double Q_hand[3][3] = {{4.644162519873706, 5.563022483761226, 3.243374787210054},
                               {5.563022483761226, 7.189024505700502, 4.89099924206743},
                               {3.243374787210054, 4.89099924206743, 4.956039322945006}};
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(F(idx[r], idx[c]), F_hand[r][c], 1e-12) << r << "," << c;
      EXPECT_NEAR(Q(idx[r], idx[c]), Q_hand[r][c], 1e-11) << r << "," << c;
    }
  }
}

TEST(Singer, NoiseIsTheExactDiscretisationOnBothSidesOfTheSeriesSwitch) {
  // GIVEN u = alpha T around 1 (the switch between the series and the closed form), and far
  // THEN Q equals integral F(s) Qc F(s)' with Qc = 2 alpha sigma^2 on ax, ay
  const StateLayout layout = make_layout(2, true);
  for (double tau : {0.5, 2.0, 2.5, 3.0, 50.0}) {
    const Singer singer{.accel_sigma = 2.0, .time_constant = tau};
    StateMat Qc = StateMat::Zero(6, 6);
    Qc(4, 4) = Qc(5, 5) = 2.0 / tau * 4.0;
    const StateMat expected =
        test::van_loan_noise([&](double t) { return singer.transition(layout, t); }, Qc, 2.5);
    EXPECT_LT((singer.process_noise(layout, 2.5) - expected).norm(), 1e-9 * expected.norm())
        << "tau " << tau;
  }
}

TEST(Singer, ContinuousAcrossTheSeriesSwitch) {
  // GIVEN u just below and above 1; THEN F and Q differ only by the change in u
  const StateLayout layout = make_layout(2, true);
  const Singer singer{.accel_sigma = 2.0, .time_constant = 1.0};
  const StateMat dq =
      singer.process_noise(layout, 1.0 + 1e-9) - singer.process_noise(layout, 1.0 - 1e-9);
  const StateMat df = singer.transition(layout, 1.0 + 1e-9) - singer.transition(layout, 1.0 - 1e-9);
  EXPECT_LT(dq.norm(), 1e-7);
  EXPECT_LT(df.norm(), 1e-7);
}

TEST(Singer, LongTimeConstantBehavesLikeConstantAccelerationWithItsNoise) {
  // GIVEN tau -> infinity with 2 sigma_m^2 / tau = q = 9 held fixed (jerk PSD of CA)
  const StateLayout layout = make_layout(3, true);
  const ConstantAcceleration ca{.jerk_sigma = 3.0, .vertical_accel_sigma = 0.5};
  for (double tau : {1e4, 1e6, 1e8}) {
    const Singer singer{.accel_sigma = std::sqrt(9.0 * tau / 2.0),
                        .time_constant = tau,
                        .vertical_accel_sigma = 0.5};
    // THEN F and Q approach CA's: the relative difference is O(u) = O(T / tau)
    const double u = 2.0 / tau;
    const StateMat F_ca = ca.transition(layout, 2.0), Q_ca = ca.process_noise(layout, 2.0);
    const StateMat dF = singer.transition(layout, 2.0) - F_ca;
    const StateMat dQ = singer.process_noise(layout, 2.0) - Q_ca;
    EXPECT_LT(dF.norm(), 2.0 * u * F_ca.norm()) << tau;
    EXPECT_LT(dQ.norm(), 2.0 * u * Q_ca.norm()) << tau;
  }
}

TEST(Singer, ShortTimeConstantDecorrelatesAcceleration) {
  // GIVEN tau = 0.1 s and dt = 5 s; THEN the acceleration forgets itself (F33 = e^-50)
  //   and its variance tends to the stationary sigma_m^2
  const Singer singer{.accel_sigma = 2.0, .time_constant = 0.1};
  const StateLayout layout = make_layout(2, true);
  EXPECT_LT(singer.transition(layout, 5.0)(4, 4), 1e-20);
  EXPECT_NEAR(singer.process_noise(layout, 5.0)(4, 4), 4.0, 1e-12);
}

}  // namespace
}  // namespace skytrack
