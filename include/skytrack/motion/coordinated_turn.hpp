#pragma once
// Coordinated turn with a known, fixed turn rate (Bar-Shalom, Li & Kirubarajan 2001, ch. 11,
// coordinated turn model; Li & Jilkov 2003, survey part I, CT model), with the exact
// discretisation of continuous white acceleration for the process noise.
// State: the shared StateLayout (filter/state.hpp), local ENU.
#include "skytrack/filter/state.hpp"

namespace skytrack {

/// Horizontal [x vx y vy] turns at `turn_rate` w (positive = left / anticlockwise seen from
/// above): with s = sin wT, c = cos wT
///   x' = x + s/w vx - (1-c)/w vy,   vx' = c vx - s vy,
///   y' = y + (1-c)/w vx + s/w vy,   vy' = s vx + c vy,
/// and Q = q integral_0^T Phi(t) G G' Phi(t)' dt with q = accel_sigma^2 [m^2/s^3]
/// (motion_blocks.hpp gives the closed form; w -> 0 gives the CV matrices).
/// Vertical channel (3-D): nearly-constant velocity with vertical_accel_sigma. Acceleration
/// states are set to 0 with zero noise; w, if present, is carried unchanged with zero noise.
struct CoordinatedTurn {
  double turn_rate = 0.0;             // [rad/s] positive = anticlockwise
  double accel_sigma = 1.0;           // [m/s^2] x and y
  double vertical_accel_sigma = 1.0;  // [m/s^2] z (3-D)

  void discretise(const StateLayout& layout, double dt, StateMat& F, StateMat& Q) const noexcept;
  StateMat transition(const StateLayout& layout, double dt) const noexcept;
  StateMat process_noise(const StateLayout& layout, double dt) const noexcept;
};

}  // namespace skytrack
