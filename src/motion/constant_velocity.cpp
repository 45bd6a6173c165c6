// Nearly-constant velocity, exactly discretised white acceleration
// (Bar-Shalom, Li & Kirubarajan 2001, §6.2.2, continuous white-noise acceleration).
#include "skytrack/motion/constant_velocity.hpp"

#include "motion_blocks.hpp"

namespace skytrack {

void ConstantVelocity::discretise(const StateLayout& layout, double dt, StateMat& F,
                                  StateMat& Q) const noexcept {
  motion_detail::start_blocks(layout, F, Q);
  const double q = accel_sigma * accel_sigma;
  motion_detail::set_cv_axis(0, q, dt, F, Q);
  motion_detail::set_cv_axis(1, q, dt, F, Q);
  if (layout.dims == 3) {
    motion_detail::set_cv_axis(2, vertical_accel_sigma * vertical_accel_sigma, dt, F, Q);
  }
}

StateMat ConstantVelocity::transition(const StateLayout& layout, double dt) const noexcept {
  StateMat F, Q;
  discretise(layout, dt, F, Q);
  return F;
}

StateMat ConstantVelocity::process_noise(const StateLayout& layout, double dt) const noexcept {
  StateMat F, Q;
  discretise(layout, dt, F, Q);
  return Q;
}

}  // namespace skytrack
