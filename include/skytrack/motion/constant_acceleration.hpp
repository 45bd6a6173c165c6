#pragma once
// Constant acceleration (Wiener-process acceleration): continuous white-noise jerk, exactly
// discretised (Bar-Shalom, Li & Kirubarajan 2001, §6.2.3, Wiener-process acceleration). Needs a
// layout with acceleration states. State: the shared StateLayout (filter/state.hpp), local ENU.
#include "skytrack/filter/state.hpp"

namespace skytrack {

/// Horizontal axes (p, v, a): F = [1 T T^2/2; 0 1 T; 0 0 1],
/// Q = q [T^5/20 T^4/8 T^3/6; T^4/8 T^3/3 T^2/2; T^3/6 T^2/2 T], q = jerk_sigma^2 [m^2/s^5].
/// Vertical channel (3-D): nearly-constant velocity with vertical_accel_sigma (as the
/// profile specifies for every model), az set to 0 with zero noise. w, if present, is carried
/// unchanged with zero noise.
struct ConstantAcceleration {
  double jerk_sigma = 1.0;            // [m/s^3] x and y
  double vertical_accel_sigma = 1.0;  // [m/s^2] z (3-D)

  void discretise(const StateLayout& layout, double dt, StateMat& F, StateMat& Q) const noexcept;
  StateMat transition(const StateLayout& layout, double dt) const noexcept;
  StateMat process_noise(const StateLayout& layout, double dt) const noexcept;
};

}  // namespace skytrack
