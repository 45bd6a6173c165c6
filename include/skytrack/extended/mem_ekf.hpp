#pragma once
// MEM-EKF*: the multiplicative error model with an EKF for the orientation and semi-axes of
// an elliptical object (Yang & Baum 2019, "Tracking the orientation and axes lengths of an
// elliptical extended object", IEEE Trans. SP 67(18), 4720-4729, Table I).
// Each plot is y = H r + S(p) h + v, S(p) = R(alpha) diag(l1, l2), h ~ N(0, c_h I),
// v ~ N(0, C_v); plots are processed one at a time:
//   C_I = S C_h S', C_II(m, n) = tr(C_p J_n' C_h J_m), C_y = H C_r H' + C_I + C_II + C_v,
//   r += C_r H' C_y^-1 (y - H r), C_r -= C_r H' C_y^-1 H C_r,
//   pseudo-measurement Y = [e1^2, e2^2, e1 e2] (e = y - H r, prior r), Ybar = [Cy11, Cy22, Cy12],
//   M = [2 S1 C_h J1; 2 S2 C_h J2; S1 C_h J2 + S2 C_h J1], C_pY = C_p M',
//   C_Y = F (C_y (x) C_y)(F + F~)', p += C_pY C_Y^-1 (Y - Ybar), C_p -= C_pY C_Y^-1 C_pY'.
// The extent is X = S S' = R(alpha) diag(l1^2, l2^2) R(alpha)'.
// Not in the paper: after a scan's plots each semi-axis is capped by their spread along it
// (MemEkfSpec::spread_bound_sigmas, mem_ekf.cpp), so a centre error is not read as extent.
#include <span>

#include "skytrack/extended/extended_object.hpp"

namespace skytrack::extended {

void mem_ekf_predict(const MotionSpec& motion, const MemEkfSpec& spec, ExtendedObject& object,
                     double dt) noexcept;

/// `noise` is the plots' measurement noise covariance C_v [m^2].
UpdateStatus mem_ekf_update(const MemEkfSpec& spec, ExtendedObject& object,
                            std::span<const Eigen::Vector2d> plots,
                            const Eigen::Matrix2d& noise) noexcept;

/// X = S S' from p = [orientation, l1, l2].
Eigen::Matrix2d mem_ekf_extent(const Eigen::Vector3d& shape) noexcept;

}  // namespace skytrack::extended
