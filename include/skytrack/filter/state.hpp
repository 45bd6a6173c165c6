#pragma once
// Track state shared by every motion model of one tracker, so IMM modes can be mixed.
// Layout (fixed per tracker, chosen from the profile's model set):
//   [x, vx, y, vy]            2-D position and velocity (the CONTRACTS covariance order)
//   [.., z, vz]               3-D adds height
//   [.., ax, ay (, az)]       when a model needs acceleration (constant acceleration, Singer)
//   [.., w]                   when a model estimates the turn rate [rad/s, positive = left]
// Sizes are bounded (10 states, 4 measurement components), so the matrices live on the stack.
#include <Eigen/Core>

namespace skytrack {

inline constexpr int kMaxStateDim = 10;
inline constexpr int kMaxMeasurementDim = 4;

using StateVec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxStateDim, 1>;
using StateMat =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxStateDim, kMaxStateDim>;
using MeasVec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxMeasurementDim, 1>;
using MeasMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxMeasurementDim,
                              kMaxMeasurementDim>;
/// Measurement Jacobian H (meas x state).
using MeasJacobian =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxMeasurementDim, kMaxStateDim>;
/// Kalman gain K (state x meas).
using GainMat =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxStateDim, kMaxMeasurementDim>;

struct StateLayout {
  int dims = 2;               // 2 or 3 position components
  bool acceleration = false;  // ax, ay (, az) present
  bool turn_rate = false;     // w present

  int size() const { return 2 * dims + (acceleration ? dims : 0) + (turn_rate ? 1 : 0); }
  /// Index of position / velocity / acceleration component `axis` (0 x, 1 y, 2 z).
  static int position(int axis) { return 2 * axis; }
  static int velocity(int axis) { return 2 * axis + 1; }
  int acceleration_index(int axis) const { return 2 * dims + axis; }
  int turn_rate_index() const { return 2 * dims + (acceleration ? dims : 0); }

  bool operator==(const StateLayout&) const = default;
};

/// A Gaussian density over the state.
struct Gaussian {
  StateVec mean;
  StateMat covariance;
};

}  // namespace skytrack
