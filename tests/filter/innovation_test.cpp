#include "skytrack/filter/innovation.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <Eigen/LU>

#include "filter_test_support.hpp"
#include "skytrack/motion/motion_model.hpp"

namespace skytrack {
namespace {

constexpr double kPi = std::numbers::pi;
const config::MeasurementSpec kEkf{};
config::MeasurementSpec unscented_spec() {
  config::MeasurementSpec spec;
  spec.update = config::MeasurementUpdate::kUnscented;
  return spec;
}
const config::MeasurementSpec kUnscented = unscented_spec();

TEST(Innovation, KalmanStepMatchesHandComputation) {
  // GIVEN a CV prior at t = 0: x = 0, vx = 10, y = 100, vy = -5, P = diag(64, 16) per axis,
  // accel_sigma^2 = 3, and a Cartesian plot (16, 91) with sigma 9 at t = 1.
  const StateLayout layout = test::layout_2d();
  StateMat P0 = StateMat::Zero(4, 4);
  P0.diagonal() << 64, 16, 64, 16;
  const Gaussian prior = test::gaussian({0, 10, 100, -5}, P0);
  // WHEN predicted 1 s and updated.
  // By hand, per axis: F P F' = [80 16; 16 16], Q = 3 [1/3 1/2; 1/2 1] = [1 1.5; 1.5 3],
  //   P- = [81 17.5; 17.5 19]; S = 81 + 81 = 162; K = [0.5, 17.5/162];
  //   x: nu = 16 - 10 = 6 -> x = 13, vx = 10 + 6 * 17.5 / 162;
  //   y: nu = 91 - 95 = -4 -> y = 93, vy = -5 - 4 * 17.5 / 162;
  //   P+ = P- - K S K' = [40.5 8.75; 8.75 19 - 17.5^2 / 162].
  const Gaussian predicted = predict(ConstantVelocity{std::sqrt(3.0), 1.0}, layout, prior, 1.0);
  const Innovation innovation = innovate(predicted, layout, test::cartesian_xy(16, 91, 9), kEkf);
  const Gaussian posterior = kalman_update(predicted, innovation);
  // THEN every number matches
  ASSERT_TRUE(innovation.ok);
  EXPECT_NEAR(predicted.covariance(0, 0), 81.0, 1e-12);
  EXPECT_NEAR(predicted.covariance(0, 1), 17.5, 1e-12);
  EXPECT_NEAR(predicted.covariance(1, 1), 19.0, 1e-12);
  EXPECT_NEAR(innovation.S(0, 0), 162.0, 1e-12);
  EXPECT_NEAR(innovation.S(1, 1), 162.0, 1e-12);
  EXPECT_NEAR(innovation.gain(1, 0), 17.5 / 162.0, 1e-14);
  EXPECT_NEAR(innovation.residual[1], -4.0, 1e-12);
  const double vx = 10.0 + 6.0 * 17.5 / 162.0, vy = -5.0 - 4.0 * 17.5 / 162.0;
  EXPECT_NEAR(posterior.mean[0], 13.0, 1e-12);
  EXPECT_NEAR(posterior.mean[1], vx, 1e-12);
  EXPECT_NEAR(posterior.mean[2], 93.0, 1e-12);
  EXPECT_NEAR(posterior.mean[3], vy, 1e-12);
  EXPECT_NEAR(posterior.covariance(0, 0), 40.5, 1e-12);
  EXPECT_NEAR(posterior.covariance(0, 1), 8.75, 1e-12);
  EXPECT_NEAR(posterior.covariance(1, 1), 19.0 - 17.5 * 17.5 / 162.0, 1e-12);
  EXPECT_NEAR(posterior.covariance(2, 3), 8.75, 1e-12);
  EXPECT_EQ(posterior.covariance(0, 2), 0.0);
  // AND the NIS and log-likelihood: nu = (6, -4), S = 162 I
  EXPECT_NEAR(innovation.nis, 52.0 / 162.0, 1e-14);
  EXPECT_NEAR(innovation.log_likelihood,
              -0.5 * (2.0 * std::log(2.0 * kPi) + 2.0 * std::log(162.0) + 52.0 / 162.0), 1e-12);
}

TEST(Innovation, JosephFormEqualsTheShortFormForTheOptimalGain) {
  // GIVEN a polar EKF innovation with a full covariance; THEN Joseph = P - K S K'
  const StateLayout layout = test::layout_2d();
  StateMat A(4, 4);
  A << 3, 1, 0, 0.5, 0, 2, 0.3, 0, 0.1, 0, 4, 1, 0, 0.2, 0, 1;
  const Gaussian predicted = test::gaussian({3000, -20, 4000, 15}, A * A.transpose());
  const Innovation innovation =
      innovate(predicted, layout, test::polar_2d(5010.0, 0.65, 10.0, 0.002), kEkf);
  ASSERT_TRUE(innovation.ok);
  const StateMat short_form =
      predicted.covariance - innovation.gain * innovation.S * innovation.gain.transpose();
  EXPECT_LT((kalman_update(predicted, innovation).covariance - short_form).norm(), 1e-9);
}

TEST(Innovation, UnscentedEqualsEkfForALinearMeasurement) {
  // GIVEN a Cartesian (linear) measurement; THEN the unscented S, K, nu are the EKF's
  const StateLayout layout = test::layout_2d();
  StateMat A(4, 4);
  A << 3, 1, 0, 0.5, 0, 2, 0.3, 0, 0.1, 0, 4, 1, 0, 0.2, 0, 1;
  const Gaussian predicted = test::gaussian({30, -2, 40, 1.5}, A * A.transpose());
  const PlotMeasurement plot = test::cartesian_xy(33, 37, 2.5);
  for (const config::UnscentedSpec ut :
       {config::UnscentedSpec{1.0, 2.0, 0.0}, config::UnscentedSpec{0.5, 2.0, 1.0}}) {
    config::MeasurementSpec spec = kUnscented;
    spec.unscented = ut;
    const Innovation u = innovate(predicted, layout, plot, spec);
    const Innovation e = innovate(predicted, layout, plot, kEkf);
    ASSERT_TRUE(u.ok);
    EXPECT_LT((u.S - e.S).norm(), 1e-10);
    EXPECT_LT((u.gain - e.gain).norm(), 1e-12);
    EXPECT_LT((u.residual - e.residual).norm(), 1e-12);
    EXPECT_NEAR(u.log_likelihood, e.log_likelihood, 1e-12);
    EXPECT_EQ(u.H.rows(), 0);
    EXPECT_LT(
        (kalman_update(predicted, u).covariance - kalman_update(predicted, e).covariance).norm(),
        1e-9);
  }
}

TEST(Innovation, EkfAndUnscentedAgreeOnANearLinearPolarCase) {
  // GIVEN a target 50 km away known to within ~20 m (the polar map is nearly linear there),
  // observed across the +-pi azimuth cut (due south)
  const StateLayout layout = test::layout_2d();
  StateMat P = StateMat::Zero(4, 4);
  P.diagonal() << 400, 100, 400, 100;
  P(0, 2) = P(2, 0) = 120;
  for (double bearing : {0.7, kPi - 1e-4, -kPi + 1e-4}) {
    const Gaussian predicted =
        test::gaussian({50000 * std::sin(bearing), 100, 50000 * std::cos(bearing), -50}, P);
    const PlotMeasurement plot = test::polar_2d(50030.0, bearing + 0.0005, 15.0, 0.001);
    const Innovation e = innovate(predicted, layout, plot, kEkf);
    const Innovation u = innovate(predicted, layout, plot, kUnscented);
    // WHEN both innovate; THEN residual, S, K and the posteriors agree closely
    ASSERT_TRUE(e.ok && u.ok);
    EXPECT_LT(std::abs(u.residual[1] - e.residual[1]), 1e-6) << bearing;  // sigma_az 1e-3
    EXPECT_LT(std::abs(u.residual[0] - e.residual[0]), 1e-2) << bearing;
    EXPECT_LT((u.S - e.S).norm(), 1e-4 * e.S.norm()) << bearing;
    EXPECT_LT((u.gain - e.gain).norm(), 1e-4 * e.gain.norm()) << bearing;
    const Gaussian pe = kalman_update(predicted, e), pu = kalman_update(predicted, u);
    EXPECT_LT((pe.mean - pu.mean).norm(), 1e-2) << bearing;
    EXPECT_LT((pe.covariance - pu.covariance).norm(), 1e-3 * pe.covariance.norm()) << bearing;
    EXPECT_NEAR(std::abs(e.residual[1]), 0.0005, 1e-9) << bearing;  // wrapped, not 2 pi off
  }
}

TEST(Innovation, UnscentedAcceptsTheSemiDefiniteAugmentedCovariance) {
  // GIVEN a CV mode's prediction in a layout with acceleration (zero rows for ax, ay)
  StateLayout layout = test::layout_2d();
  layout.acceleration = true;
  Gaussian prior;
  prior.mean = StateVec::Zero(6);
  prior.mean << 1000, 10, 2000, -5, 1, 1;
  prior.covariance = StateMat::Identity(6, 6) * 25.0;
  const Gaussian predicted = predict(ConstantVelocity{}, layout, prior, 2.0);
  MeasVec z(2), s(2);
  z << 2250.0, 0.45;
  s << 10.0, 0.002;
  const PlotMeasurement plot{MeasurementModel::polar({}, false, false, 2, s), z, 0.0, 0};
  // WHEN the unscented innovation is formed; THEN it works and leaves ax, ay untouched
  const Innovation u = innovate(predicted, layout, plot, kUnscented);
  ASSERT_TRUE(u.ok);
  EXPECT_EQ(u.gain.row(4).norm(), 0.0);
  const Gaussian posterior = kalman_update(predicted, u);
  EXPECT_EQ(posterior.mean[4], 0.0);
  EXPECT_TRUE(posterior.covariance.allFinite());
}

TEST(Innovation, FailedFactorisationIsReportedNotThrown) {
  // GIVEN a zero prior covariance and a zero-sigma measurement: S = 0
  const Gaussian predicted = test::gaussian({1, 2, 3, 4}, StateMat::Zero(4, 4));
  const PlotMeasurement plot = test::cartesian_xy(1.5, 3.5, 0.0);
  for (const config::MeasurementSpec& spec : {kEkf, kUnscented}) {
    const Innovation innovation = innovate(predicted, test::layout_2d(), plot, spec);
    // THEN it is not ok, its likelihood is -inf, and the update keeps the prediction
    EXPECT_FALSE(innovation.ok);
    EXPECT_EQ(innovation.log_likelihood, -std::numeric_limits<double>::infinity());
    EXPECT_EQ(kalman_update(predicted, innovation).mean, predicted.mean);
  }
  // AND a measurement built for another tracker dimension is refused
  const Gaussian g3 = test::gaussian({1, 2, 3, 4, 5, 6}, StateMat::Identity(6, 6));
  EXPECT_FALSE(innovate(g3, test::layout_3d(), test::cartesian_xy(1, 3, 1.0), kEkf).ok);
}

TEST(Innovation, LogDetIsTheShapesToTheBitAndNanWithoutAFactor) {
  // GIVEN predictions of a 2-D track seen by a polar and a Cartesian plot, and of a 3-D track
  const StateLayout layout = test::layout_2d();
  StateMat P = StateMat::Zero(4, 4);
  P.diagonal() << 400, 100, 900, 64;
  P(0, 2) = P(2, 0) = 120;
  const Gaussian predicted = test::gaussian({30000, 100, 40000, -50}, P);
  const Gaussian g3 = test::gaussian({1000, 2, 3000, 4, 500, 1}, StateMat::Identity(6, 6) * 50.0);
  const PlotMeasurement polar = test::polar_2d(50030.0, 0.64, 15.0, 0.001);
  const PlotMeasurement cartesian = test::cartesian_xy(30010.0, 39990.0, 20.0);
  MeasVec sigma3(3);
  sigma3 << 10.0, 10.0, 30.0;
  const MeasurementModel cartesian_3d = MeasurementModel::cartesian(3, 3, sigma3);
  // WHEN log det S is formed alone; THEN it is the innovation shape's, to the bit
  for (const PlotMeasurement* plot : {&polar, &cartesian}) {
    const InnovationShape shape = innovation_shape(predicted, layout, plot->model);
    ASSERT_TRUE(shape.shared.ok);
    EXPECT_EQ(innovation_log_det(predicted, layout, plot->model), shape.log_det);
    // AND it is log det S of the innovation
    EXPECT_NEAR(innovation_log_det(predicted, layout, plot->model),
                std::log(innovate(predicted, layout, *plot, kEkf).S.determinant()), 1e-9);
  }
  EXPECT_EQ(innovation_log_det(g3, test::layout_3d(), cartesian_3d),
            innovation_shape(g3, test::layout_3d(), cartesian_3d).log_det);
  // AND S = 0 (no factor) or a model of another dimension gives NaN
  const Gaussian certain = test::gaussian({1, 2, 3, 4}, StateMat::Zero(4, 4));
  EXPECT_TRUE(
      std::isnan(innovation_log_det(certain, layout, test::cartesian_xy(1.5, 3.5, 0.0).model)));
  EXPECT_TRUE(std::isnan(innovation_log_det(g3, test::layout_3d(), cartesian.model)));
}

}  // namespace
}  // namespace skytrack
