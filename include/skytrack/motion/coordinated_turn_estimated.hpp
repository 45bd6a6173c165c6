#pragma once
// Coordinated turn with the turn rate as a state (Bar-Shalom, Li & Kirubarajan 2001, ch. 11,
// coordinated turn with unknown rate; Li & Jilkov 2003, survey part I, CT model with w).
// Non-linear: the prediction is an EKF step with the analytic Jacobian, continuous through
// w -> 0 (series expansions in turn_functions.hpp). Needs a layout with the turn rate.
#include "skytrack/filter/state.hpp"

namespace skytrack {

/// f(x): the CoordinatedTurn transition with w read from the state, w' = w.
/// Q: the exact coordinated-turn white-acceleration noise at the current w (PSD
/// accel_sigma^2), plus turn_rate_sigma^2 |T| on w (w a random walk; turn_rate_sigma is the
/// white turn acceleration over one second). Vertical channel (3-D): nearly-constant
/// velocity with vertical_accel_sigma; acceleration states set to 0 with zero noise.
struct CoordinatedTurnEstimated {
  double accel_sigma = 1.0;               // [m/s^2] x and y
  double turn_rate_sigma = 0.005;         // [rad/s^2]
  double vertical_accel_sigma = 1.0;      // [m/s^2] z (3-D)
  double initial_turn_rate_sigma = 0.05;  // [rad/s] for initiators; not used in prediction

  /// f(x, dt).
  StateVec propagate(const StateLayout& layout, const StateVec& x, double dt) const noexcept;
  /// df/dx at x, and Q(x, |dt|), in one pass.
  void linearise(const StateLayout& layout, const StateVec& x, double dt, StateMat& F,
                 StateMat& Q) const noexcept;
  StateMat jacobian(const StateLayout& layout, const StateVec& x, double dt) const noexcept;
  StateMat process_noise(const StateLayout& layout, const StateVec& x, double dt) const noexcept;
};

}  // namespace skytrack
