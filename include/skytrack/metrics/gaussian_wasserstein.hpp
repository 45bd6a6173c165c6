#pragma once
// Gaussian Wasserstein distance between two ellipses (centre m, SPD shape matrix X), the
// extent metric of paper 002 (Liu et al. 2023, set-membership EOT), eq. 50:
//   d_GW^2 = |m1 - m2|^2 + tr( X1 + X2 - 2 (X1^{1/2} X2 X1^{1/2})^{1/2} ).
// Eq. 50 applies it to the shape matrix X itself (CONTRACTS.md: semi-axes = sqrt(eig X)),
// not to a scaled covariance, and prints the right-hand side without an outer root while
// its Table 2 reports metres; we return both: the squared form [m^2] exactly as printed and
// its root [m], which is the 2-Wasserstein distance between N(m1, X1) and N(m2, X2).
#include <Eigen/Core>

namespace skytrack::metrics {

/// Eq. 50 as printed [m^2]. X1, X2 symmetric positive semi-definite.
double gaussian_wasserstein_squared(const Eigen::Vector2d& m1, const Eigen::Matrix2d& X1,
                                    const Eigen::Vector2d& m2, const Eigen::Matrix2d& X2);

/// sqrt of eq. 50 [m]: identical ellipses 0, a translation t gives |t|, concentric circles
/// X = r^2 I give sqrt(2) |r1 - r2|.
double gaussian_wasserstein_distance(const Eigen::Vector2d& m1, const Eigen::Matrix2d& X1,
                                     const Eigen::Vector2d& m2, const Eigen::Matrix2d& X2);

}  // namespace skytrack::metrics
