// Constant acceleration, exactly discretised white jerk
// (Bar-Shalom, Li & Kirubarajan 2001, §6.2.3, Wiener-process acceleration).
#include "skytrack/motion/constant_acceleration.hpp"

#include "motion_blocks.hpp"

namespace skytrack {

void ConstantAcceleration::discretise(const StateLayout& layout, double dt, StateMat& F,
                                      StateMat& Q) const noexcept {
  motion_detail::start_blocks(layout, F, Q);
  const double q = jerk_sigma * jerk_sigma;
  motion_detail::set_ca_axis(layout, 0, q, dt, F, Q);
  motion_detail::set_ca_axis(layout, 1, q, dt, F, Q);
  if (layout.dims == 3) {  // az (if present) stays 0: its F row and Q entries are zero
    motion_detail::set_cv_axis(2, vertical_accel_sigma * vertical_accel_sigma, dt, F, Q);
  }
}

StateMat ConstantAcceleration::transition(const StateLayout& layout, double dt) const noexcept {
  StateMat F, Q;
  discretise(layout, dt, F, Q);
  return F;
}

StateMat ConstantAcceleration::process_noise(const StateLayout& layout, double dt) const noexcept {
  StateMat F, Q;
  discretise(layout, dt, F, Q);
  return Q;
}

}  // namespace skytrack
