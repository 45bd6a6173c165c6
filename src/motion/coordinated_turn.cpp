// Coordinated turn at a fixed rate (Bar-Shalom, Li & Kirubarajan 2001, ch. 11).
// Exact process noise: with Phi(t) the turn transition and G selecting the velocity,
// Phi(t) G = [A(t); R(wt)], A(t) = [sin wt  -(1-cos wt); 1-cos wt  sin wt] / w, R the
// rotation, so Q = q int_0^T [A A'  A R'; R A'  R R'] dt with A A' = 2 (1 - cos wt)/w^2 I,
// A R' = [sin wt  1-cos wt; -(1-cos wt)  sin wt] / w and R R' = I; integrating gives the
// closed form in motion_blocks.hpp (set_ct_horizontal).
#include "skytrack/motion/coordinated_turn.hpp"

#include "motion_blocks.hpp"

namespace skytrack {

void CoordinatedTurn::discretise(const StateLayout& layout, double dt, StateMat& F,
                                 StateMat& Q) const noexcept {
  motion_detail::start_blocks(layout, F, Q);
  motion_detail::set_ct_horizontal(turn_rate, accel_sigma * accel_sigma, dt, F, Q);
  if (layout.dims == 3) {
    motion_detail::set_cv_axis(2, vertical_accel_sigma * vertical_accel_sigma, dt, F, Q);
  }
}

StateMat CoordinatedTurn::transition(const StateLayout& layout, double dt) const noexcept {
  StateMat F, Q;
  discretise(layout, dt, F, Q);
  return F;
}

StateMat CoordinatedTurn::process_noise(const StateLayout& layout, double dt) const noexcept {
  StateMat F, Q;
  discretise(layout, dt, F, Q);
  return Q;
}

}  // namespace skytrack
