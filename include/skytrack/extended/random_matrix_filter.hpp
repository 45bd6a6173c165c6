#pragma once
// Random-matrix extended object filter with sensor noise: Feldmann, Fraenken & Koch 2011,
// "Tracking of extended objects and group targets using random matrices", IEEE Trans. SP
// 59(4), 1409-1420 (section III-B predict, III-C update with Y = z X + R).
//   predict  x = F x, P = F P F' + Q, X unchanged, alpha = 2 + e^{-T/tau} (alpha - 2);
//   update   with n plots, mean zbar, scatter Z = sum (z_r - zbar)(z_r - zbar)':
//            Y = z X + R, S = H P H' + Y / n, K = P H' S^-1, eps = zbar - H x,
//            x += K eps, P -= K S K',
//            N = X^{1/2} S^{-1/2} eps eps' S^{-1/2}' X^{1/2}',
//            Zh = X^{1/2} Y^{-1/2} Z Y^{-1/2}' X^{1/2}',
//            X = (alpha X + N + Zh) / (alpha + n), alpha += n.
#include <span>

#include "skytrack/extended/extended_object.hpp"

namespace skytrack::extended {

void random_matrix_predict(const MotionSpec& motion, const RandomMatrixSpec& spec,
                           ExtendedObject& object, double dt) noexcept;

/// `noise` is the plots' measurement noise covariance R [m^2].
UpdateStatus random_matrix_update(const RandomMatrixSpec& spec, ExtendedObject& object,
                                  std::span<const Eigen::Vector2d> plots,
                                  const Eigen::Matrix2d& noise) noexcept;

}  // namespace skytrack::extended
