// Hand-computed steps of SMF-EOT (paper 002 eq. 27-37), the random-matrix filter (Feldmann
// et al. 2011) and MEM-EKF* (Yang & Baum 2019), and their behaviour on a known object.
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "skytrack/extended/ellipse_geometry.hpp"
#include "skytrack/extended/extended_estimator.hpp"
#include "skytrack/extended/mem_ekf.hpp"
#include "skytrack/extended/random_matrix_filter.hpp"
#include "skytrack/extended/smf_eot.hpp"

namespace skytrack::extended {
namespace {

TEST(Kinematics, TransitionIsPaperEquation49PerAxis) {
  const KinMat F = transition(MotionSpec{.time_constant = 40.0, .accel_noise = 0.5}, 10.0);
  EXPECT_DOUBLE_EQ(F(0, 1), 10.0);  // x <- vx T
  EXPECT_DOUBLE_EQ(F(0, 4), 50.0);  // x <- ax T^2 / 2
  EXPECT_DOUBLE_EQ(F(1, 4), 10.0);  // vx <- ax T
  EXPECT_DOUBLE_EQ(F(4, 4), std::exp(-0.25));
  EXPECT_DOUBLE_EQ(F(2, 3), 10.0);  // y <- vy T
  EXPECT_DOUBLE_EQ(F(0, 2), 0.0);   // axes independent
}

TEST(SmfEot, PredictBoundIsTheMinimumTraceMinkowskiSum) {
  // GIVEN S = I and a static model (T small enough that we can write F S F' by hand: T = 1,
  // theta -> infinity, so F = [1 1 0.5; 0 1 1; 0 0 1] per axis), q = 1.
  const MotionSpec motion{.time_constant = 0.0, .accel_noise = 1.0};  // 0: no decay
  ExtendedObject object;
  object.S = KinMat::Identity();
  object.P = KinMat::Identity();
  smf_predict(motion, object, 1.0);
  // tr(F S F') = 2 * (1 + 1 + 0.25 + 1 + 1 + 1) = 10.5; tr Q = 2 * (0.25 + 1 + 1) = 4.5;
  // p = sqrt(10.5 / 4.5) (eq. 29); S(0,0) = (1 + 1/p) * 2.25 + (1 + p) * 0.25 (eq. 27).
  const double p = std::sqrt(10.5 / 4.5);
  EXPECT_NEAR(object.S(0, 0), (1.0 + 1.0 / p) * 2.25 + (1.0 + p) * 0.25, 1e-12);
  EXPECT_NEAR(object.S(4, 4), (1.0 + 1.0 / p) * 1.0 + (1.0 + p) * 1.0, 1e-12);
  // AND P is the Kalman prediction F P F' + Q (eq. 23).
  EXPECT_NEAR(object.P(0, 0), 2.25 + 0.25, 1e-12);
}

TEST(SmfEot, UpdateMovesTheCentreByTheGainOfEquation32) {
  // GIVEN P = S = 100 I, lambda X = diag(100, 100), U = diag(100, 100): C = lambda X (+) U =
  // 400 I (p = 1, two circles of radius 10), H P H' + C = 500 I, so K = 0.2 on position.
  ExtendedObject object;
  object.P = KinMat::Identity() * 100.0;
  object.S = object.P;
  object.extent = Eigen::Matrix2d::Identity() * 400.0;
  const std::vector<Eigen::Vector2d> plots = {{0.0, 10.0}, {20.0, -10.0}};  // mean (10, 0)
  SmfWorkspace workspace;
  const SmfSpec spec;  // lambda = 0.25
  ASSERT_EQ(smf_update(spec, object, plots, Eigen::Matrix2d::Identity() * 100.0, workspace),
            UpdateStatus::kUpdated);
  EXPECT_NEAR(object.x[0], 2.0, 1e-12);  // 0.2 * 10 (eq. 35)
  EXPECT_NEAR(object.x[2], 0.0, 1e-12);
  EXPECT_NEAR(object.x[1], 0.0, 1e-12);     // P diagonal: velocity untouched
  EXPECT_NEAR(object.P(0, 0), 80.0, 1e-9);  // (1 - 0.2) 100 (eq. 33)
  // S (eq. 35-37): (I - KH) S (I - KH)' = 64 and K C K' = 16 on position, p = sqrt(...),
  // and both terms' traces include the four untouched states of S = 100 I.
  const double t1 = 2 * 64.0 + 4 * 100.0, t2 = 2 * 16.0;
  const double p = std::sqrt(t1 / t2);
  EXPECT_NEAR(object.S(0, 0), (1.0 + 1.0 / p) * 64.0 + (1.0 + p) * 16.0, 1e-9);
}

TEST(SmfEot, ExtentOfPlotsOnTheObjectsOutlineIsTheObject) {
  // GIVEN 72 plots on the outline of an object with semi-axes 100 m and 40 m at 30 degrees,
  // with no noise beyond a tiny bound, and the centre known to 1 m
  const Eigen::Matrix2d X = shape_from_axes(100.0, 40.0, std::numbers::pi / 6.0);
  std::vector<Eigen::Vector2d> plots;
  append_ellipse_boundary(Eigen::Vector2d(500.0, -300.0), X, 72, plots);
  SmfSpec spec;
  SmfWorkspace workspace;
  const Eigen::Matrix2d tiny = Eigen::Matrix2d::Identity() * 1e-6;
  const Eigen::Matrix2d measured = smf_extent_measurement(
      spec, plots, Eigen::Matrix2d::Identity(), Eigen::Matrix2d(0.25 * X + tiny), tiny, workspace);
  // THEN the hull, enclosing ellipse and two Minkowski differences give back the object
  // (within 3 %: the difference of non-homothetic ellipses is not an ellipse).
  const EllipseAxes axes = ellipse_axes(measured);
  EXPECT_NEAR(axes.major, 100.0, 3.0);
  EXPECT_NEAR(axes.minor, 40.0, 1.2);
  EXPECT_NEAR(std::remainder(axes.orientation - std::numbers::pi / 6.0, std::numbers::pi), 0.0,
              0.02);
}

TEST(RandomMatrix, OneUpdateByHand) {
  // GIVEN position variance 50, X = 100 I, alpha = 10, z = 1/4, R = 75 I: Y = 100 I. Two
  // plots at (+-10, 0), the prediction at the origin: eps = 0, Z = diag(200, 0).
  RandomMatrixSpec spec;
  ExtendedObject object;
  object.P = KinMat::Identity();
  object.P(0, 0) = object.P(2, 2) = 50.0;
  object.extent = Eigen::Matrix2d::Identity() * 100.0;
  object.dof = 10.0;
  const std::vector<Eigen::Vector2d> plots = {{-10.0, 0.0}, {10.0, 0.0}};
  ASSERT_EQ(random_matrix_update(spec, object, plots, Eigen::Matrix2d::Identity() * 75.0),
            UpdateStatus::kUpdated);
  // S = 50 + 100 / 2 = 100, K = 0.5, P = 50 - 0.25 * 100 = 25.
  EXPECT_NEAR(object.P(0, 0), 25.0, 1e-9);
  EXPECT_NEAR(object.x[0], 0.0, 1e-12);
  // X = (10 * 100 I + X^1/2 Y^-1/2 Z Y^-1/2 X^1/2) / 12 = (1000 I + diag(200, 0)) / 12.
  EXPECT_NEAR(object.extent(0, 0), 100.0, 1e-9);
  EXPECT_NEAR(object.extent(1, 1), 1000.0 / 12.0, 1e-9);
  EXPECT_NEAR(object.dof, 12.0, 1e-12);
}

// A static object, plots uniform over it plus Gaussian noise, 40 scans of 20 plots.
ExtendedObject track_static_object(EstimatorKind kind, const Eigen::Matrix2d& X) {
  ExtendedSpec spec;
  spec.kind = kind;
  spec.smf.bound_sigmas = 3.0;
  ExtendedEstimator estimator(spec);
  KinMat P = KinMat::Identity() * 100.0;
  ExtendedObject object =
      estimator.initiate(KinVec::Zero(), P, Eigen::Matrix2d::Identity() * 2500.0);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> normal(0.0, 2.0);
  const EllipseAxes axes = ellipse_axes(X);
  std::vector<Eigen::Vector2d> plots;
  for (int k = 0; k < 40; ++k) {
    if (k > 0) estimator.predict(object, 1.0);
    plots.clear();
    for (int i = 0; i < 20; ++i) {
      const double r = std::sqrt(u(rng)), phi = 2.0 * std::numbers::pi * u(rng);
      const Eigen::Vector2d local(axes.major * r * std::cos(phi), axes.minor * r * std::sin(phi));
      const double c = std::cos(axes.orientation), s = std::sin(axes.orientation);
      // Each draw is its own step, last argument first: the order GCC used when the scenes were
      // measured (C++ leaves the evaluation order of arguments unspecified).
      const double noise_y = normal(rng), noise_x = normal(rng);
      plots.emplace_back(c * local.x() - s * local.y() + noise_x,
                         s * local.x() + c * local.y() + noise_y);
    }
    estimator.update(object, plots, Eigen::Matrix2d::Identity() * 4.0);
  }
  return object;
}

TEST(ExtendedEstimator, EveryEstimatorFindsAStaticObjectsCentreAndExtent) {
  const Eigen::Matrix2d X = shape_from_axes(80.0, 30.0, 0.4);
  for (EstimatorKind kind :
       {EstimatorKind::kSmf, EstimatorKind::kRandomMatrix, EstimatorKind::kMemEkf}) {
    const ExtendedObject object = track_static_object(kind, X);
    SCOPED_TRACE(static_cast<int>(kind));
    EXPECT_LT(object.position().norm(), 6.0);  // [m]
    const EllipseAxes axes = ellipse_axes(object.extent);
    EXPECT_NEAR(std::remainder(axes.orientation - 0.4, std::numbers::pi), 0.0, 0.15);
    if (kind == EstimatorKind::kSmf) {
      // SMF-EOT's extent is the last scan's hull of 20 plots less the noise bound: an inner
      // estimate (scatterers lie inside the outline), between 70 % and 105 % of the object.
      EXPECT_GT(axes.major, 0.70 * 80.0);
      EXPECT_LT(axes.major, 1.05 * 80.0);
      EXPECT_GT(axes.minor, 0.70 * 30.0);
      EXPECT_LT(axes.minor, 1.05 * 30.0);
    } else {  // moment-based: unbiased for scatterers uniform over the ellipse
      EXPECT_NEAR(axes.major, 80.0, 8.0);  // 10 %
      EXPECT_NEAR(axes.minor, 30.0, 4.5);  // 15 %
    }
  }
}

TEST(ExtendedEstimator, NoPlotsLeavesThePredictionAndIsReported) {
  ExtendedSpec spec;
  for (EstimatorKind kind :
       {EstimatorKind::kSmf, EstimatorKind::kRandomMatrix, EstimatorKind::kMemEkf}) {
    spec.kind = kind;
    ExtendedEstimator estimator(spec);
    ExtendedObject object =
        estimator.initiate(KinVec::Ones(), KinMat::Identity(), Eigen::Matrix2d::Identity() * 100.0);
    const ExtendedObject before = object;
    EXPECT_EQ(estimator.update(object, {}, Eigen::Matrix2d::Identity()), UpdateStatus::kNoPlots);
    EXPECT_EQ(object.x, before.x);
    EXPECT_EQ(object.extent, before.extent);
  }
}

}  // namespace
}  // namespace skytrack::extended
