// Gaussian Wasserstein distance, paper 002 eq. 50 (see gaussian_wasserstein.hpp).
#include "skytrack/metrics/gaussian_wasserstein.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>  // determinant()

namespace skytrack::metrics {

double gaussian_wasserstein_squared(const Eigen::Vector2d& m1, const Eigen::Matrix2d& X1,
                                    const Eigen::Vector2d& m2, const Eigen::Matrix2d& X2) {
  // For a 2x2 PSD matrix A with eigenvalues l1, l2: tr(A^{1/2}) = sqrt(tr A + 2 sqrt(det A)).
  // Here A = X1^{1/2} X2 X1^{1/2}, so tr A = tr(X1 X2) and det A = det X1 det X2: no matrix
  // square roots are needed.
  const double trace_a = (X1 * X2).trace();
  const double det_a = std::max(0.0, X1.determinant()) * std::max(0.0, X2.determinant());
  const double trace_sqrt_a = std::sqrt(std::max(0.0, trace_a + 2.0 * std::sqrt(det_a)));
  const double shape = X1.trace() + X2.trace() - 2.0 * trace_sqrt_a;
  return (m1 - m2).squaredNorm() + std::max(0.0, shape);  // clamp rounding below zero
}

double gaussian_wasserstein_distance(const Eigen::Vector2d& m1, const Eigen::Matrix2d& X1,
                                     const Eigen::Vector2d& m2, const Eigen::Matrix2d& X2) {
  return std::sqrt(gaussian_wasserstein_squared(m1, X1, m2, X2));
}

}  // namespace skytrack::metrics
