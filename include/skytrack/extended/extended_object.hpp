#pragma once
// One extended object's estimate, shared by the three estimators, and its kinematics.
// State [x, vx, y, vy, ax, ay] in the tracking frame (ENU, metres, seconds), the
// StateLayout{dims = 2, acceleration = true} order; extent X: the object's ellipse as a
// shape matrix, E(centre, X), semi-axes sqrt(eig X) [m^2].
#include <cstdint>

#include <Eigen/Core>

#include "skytrack/extended/extended_spec.hpp"

namespace skytrack::extended {

using KinVec = Eigen::Matrix<double, 6, 1>;
using KinMat = Eigen::Matrix<double, 6, 6>;
using PosMat = Eigen::Matrix<double, 2, 6>;  // H: the centre's position from the state

struct ExtendedObject {
  KinVec x = KinVec::Zero();
  KinMat P = KinMat::Identity();  // covariance (SMF-EOT: the P of its gain, eq. 23, 33)
  KinMat S = KinMat::Identity();  // SMF-EOT only: the state set's bound E(x, S) (eq. 27, 35)
  Eigen::Matrix2d extent = Eigen::Matrix2d::Identity();  // X [m^2]
  double dof = 10.0;  // random matrix only: alpha, the extent's degrees of freedom
  // MEM-EKF only: p = [orientation (rad, major axis from x to y), semi-axis l1, l2 (m)].
  Eigen::Vector3d shape = Eigen::Vector3d(0.0, 1.0, 1.0);
  Eigen::Matrix3d shape_cov = Eigen::Matrix3d::Identity();

  Eigen::Vector2d position() const { return {x[0], x[2]}; }
  Eigen::Vector2d velocity() const { return {x[1], x[3]}; }
};

/// Paper 002 eq. 49 per axis, Phi = F (x) I_2 in our state order.
KinMat transition(const MotionSpec& motion, double dt) noexcept;
/// G Q2 G', G = [dt^2/2, dt, 1]' per axis, Q2 = diag(q^2, q^2).
KinMat process_noise(const MotionSpec& motion, double dt) noexcept;
/// A coast without the acceleration state: x predicted over dt from a state whose
/// acceleration was `prior_accel` becomes the constant-velocity prediction of that state
/// (position less dt^2/2 a, velocity less dt a, acceleration 0); the covariance is kept.
void coast_constant_velocity(KinVec& x, const Eigen::Vector2d& prior_accel, double dt) noexcept;
/// H = [1 0 0 0 0 0; 0 0 1 0 0 0].
PosMat position_matrix() noexcept;

/// How an update went; a numeric failure leaves the object as predicted.
enum class UpdateStatus : std::uint8_t { kUpdated, kNoPlots, kNumericFailure };

}  // namespace skytrack::extended
