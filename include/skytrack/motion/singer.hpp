#pragma once
// Singer manoeuvre model: acceleration is a first-order Gauss-Markov process with time
// constant tau and RMS sigma_m (Singer 1970, IEEE Trans. AES-6(4); Li & Jilkov 2003, survey
// part I, IEEE Trans. AES-39(4), Singer model). Needs a layout with acceleration states.
#include "skytrack/filter/state.hpp"

namespace skytrack {

/// Horizontal axes (p, v, a), alpha = 1/tau, u = alpha T:
///   F = [1 T (u - 1 + e^-u)/alpha^2; 0 1 (1 - e^-u)/alpha; 0 0 e^-u],
///   Q = 2 alpha sigma_m^2 integral_0^T phi(t) phi(t)' dt, phi(t) = F(t) [0 0 1]'
/// (the closed form of Singer's paper, evaluated by its power series for small u, where the
/// closed form cancels). As tau -> infinity with 2 sigma_m^2 / tau = q fixed it becomes
/// ConstantAcceleration with jerk PSD q. Vertical channel (3-D): nearly-constant velocity with
/// vertical_accel_sigma, az set to 0 with zero noise (as the profile specifies for every
/// model). w, if present, is carried unchanged with zero noise.
struct Singer {
  double accel_sigma = 1.0;           // [m/s^2] sigma_m
  double time_constant = 20.0;        // [s] tau > 0
  double vertical_accel_sigma = 1.0;  // [m/s^2] z (3-D)

  void discretise(const StateLayout& layout, double dt, StateMat& F, StateMat& Q) const noexcept;
  StateMat transition(const StateLayout& layout, double dt) const noexcept;
  StateMat process_noise(const StateLayout& layout, double dt) const noexcept;
};

}  // namespace skytrack
