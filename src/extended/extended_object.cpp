// Kinematics of extended objects: paper 002 eq. 49 (Singer-like transition).
#include "skytrack/extended/extended_object.hpp"

#include <cmath>

namespace skytrack::extended {
namespace {

constexpr int kPos[2] = {0, 2};
constexpr int kVel[2] = {1, 3};
constexpr int kAcc[2] = {4, 5};

}  // namespace

KinMat transition(const MotionSpec& motion, double dt) noexcept {
  KinMat F = KinMat::Identity();
  const double decay = motion.time_constant > 0.0 ? std::exp(-dt / motion.time_constant) : 1.0;
  for (int axis = 0; axis < 2; ++axis) {
    F(kPos[axis], kVel[axis]) = dt;
    F(kPos[axis], kAcc[axis]) = 0.5 * dt * dt;
    F(kVel[axis], kAcc[axis]) = dt;
    F(kAcc[axis], kAcc[axis]) = decay;
  }
  return F;
}

KinMat process_noise(const MotionSpec& motion, double dt) noexcept {
  KinMat Q = KinMat::Zero();
  const double g[3] = {0.5 * dt * dt, dt, 1.0};
  const double q2 = motion.accel_noise * motion.accel_noise;
  for (int axis = 0; axis < 2; ++axis) {
    const int idx[3] = {kPos[axis], kVel[axis], kAcc[axis]};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) Q(idx[i], idx[j]) = g[i] * g[j] * q2;
    }
  }
  return Q;
}

void coast_constant_velocity(KinVec& x, const Eigen::Vector2d& prior_accel, double dt) noexcept {
  for (int axis = 0; axis < 2; ++axis) {
    x[kPos[axis]] -= 0.5 * dt * dt * prior_accel[axis];
    x[kVel[axis]] -= dt * prior_accel[axis];
    x[kAcc[axis]] = 0.0;
  }
}

PosMat position_matrix() noexcept {
  PosMat H = PosMat::Zero();
  H(0, 0) = 1.0;
  H(1, 2) = 1.0;
  return H;
}

}  // namespace skytrack::extended
