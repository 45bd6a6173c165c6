#include "skytrack/metrics/gaussian_wasserstein.hpp"

#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

namespace skytrack::metrics {
namespace {

Eigen::Matrix2d sqrtm(const Eigen::Matrix2d& a) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(a);
  return eig.eigenvectors() * eig.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal() *
         eig.eigenvectors().transpose();
}

// Eq. 50 with explicit matrix square roots, as a reference for the closed form.
double reference_squared(const Eigen::Vector2d& m1, const Eigen::Matrix2d& X1,
                         const Eigen::Vector2d& m2, const Eigen::Matrix2d& X2) {
  const Eigen::Matrix2d s1 = sqrtm(X1);
  const Eigen::Matrix2d inner = s1 * X2 * s1;
  return (m1 - m2).squaredNorm() +
         (X1 + X2 - 2.0 * sqrtm(0.5 * (inner + inner.transpose()))).trace();
}

TEST(GaussianWasserstein, IdenticalEllipsesAreZeroApart) {
  Eigen::Matrix2d X;
  X << 2500.0, 300.0, 300.0, 900.0;
  const Eigen::Vector2d m(800.0, -200.0);
  EXPECT_NEAR(gaussian_wasserstein_squared(m, X, m, X), 0.0, 1e-9);
  EXPECT_NEAR(gaussian_wasserstein_distance(m, X, m, X), 0.0, 1e-4);
}

TEST(GaussianWasserstein, PureTranslationIsTheCentreDistance) {
  Eigen::Matrix2d X;
  X << 400.0, 50.0, 50.0, 100.0;
  EXPECT_NEAR(gaussian_wasserstein_distance({0, 0}, X, {30, 40}, X), 50.0, 1e-6);
}

TEST(GaussianWasserstein, ConcentricCirclesDifferBySqrtTwoTimesRadiusDifference) {
  // X = r^2 I: tr(X1 + X2 - 2 (r1 r2) I) = 2 (r1^2 + r2^2 - 2 r1 r2) = 2 (r1 - r2)^2
  const double r1 = 30.0, r2 = 12.0;
  const Eigen::Matrix2d X1 = r1 * r1 * Eigen::Matrix2d::Identity();
  const Eigen::Matrix2d X2 = r2 * r2 * Eigen::Matrix2d::Identity();
  EXPECT_NEAR(gaussian_wasserstein_distance({5, 5}, X1, {5, 5}, X2), std::sqrt(2.0) * 18.0, 1e-9);
}

TEST(GaussianWasserstein, ClosedFormMatchesMatrixSquareRootsAndIsSymmetric) {
  std::mt19937 rng(3);
  std::normal_distribution<double> n(0.0, 20.0);
  for (int trial = 0; trial < 100; ++trial) {
    Eigen::Matrix2d A, B;
    A << n(rng), n(rng), n(rng), n(rng);
    B << n(rng), n(rng), n(rng), n(rng);
    const Eigen::Matrix2d X1 = A * A.transpose() + Eigen::Matrix2d::Identity();
    const Eigen::Matrix2d X2 = B * B.transpose() + Eigen::Matrix2d::Identity();
    // Each draw is its own step, last argument first: the order GCC used when the scenes were
    // measured (C++ leaves the evaluation order of arguments unspecified).
    const double m1_y = n(rng), m1_x = n(rng);
    const Eigen::Vector2d m1(m1_x, m1_y);
    const double m2_y = n(rng), m2_x = n(rng);
    const Eigen::Vector2d m2(m2_x, m2_y);
    const double d2 = gaussian_wasserstein_squared(m1, X1, m2, X2);
    EXPECT_NEAR(d2, reference_squared(m1, X1, m2, X2), 1e-6 * (1.0 + d2));
    EXPECT_NEAR(d2, gaussian_wasserstein_squared(m2, X2, m1, X1), 1e-6 * (1.0 + d2));
  }
}

}  // namespace
}  // namespace skytrack::metrics
