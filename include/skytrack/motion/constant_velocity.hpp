#pragma once
// Nearly-constant velocity: continuous white-noise acceleration, exactly discretised
// (Bar-Shalom, Li & Kirubarajan 2001, §6.2.2, continuous white-noise acceleration).
// State: the shared StateLayout (filter/state.hpp), local ENU [m, m/s].
#include "skytrack/filter/state.hpp"

namespace skytrack {

/// Per axis F = [1 T; 0 1], Q = q [T^3/3 T^2/2; T^2/2 T] with the acceleration PSD
/// q = accel_sigma^2 [m^2/s^3] (x, y) or vertical_accel_sigma^2 (z): `accel_sigma` is the
/// spread of the white acceleration over one second, so the velocity picks up a variance of
/// accel_sigma^2 * T per interval T. Acceleration states, if the layout has them, are set to
/// 0 with zero noise (their covariance rows become 0: the usual augmented-IMM treatment);
/// the turn rate w, if present, is carried unchanged with zero noise.
struct ConstantVelocity {
  double accel_sigma = 1.0;           // [m/s^2] x and y
  double vertical_accel_sigma = 1.0;  // [m/s^2] z (3-D)

  /// F(dt) and Q(|dt|) in one pass.
  void discretise(const StateLayout& layout, double dt, StateMat& F, StateMat& Q) const noexcept;
  StateMat transition(const StateLayout& layout, double dt) const noexcept;
  StateMat process_noise(const StateLayout& layout, double dt) const noexcept;
};

}  // namespace skytrack
