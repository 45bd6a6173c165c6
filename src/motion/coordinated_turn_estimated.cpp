// Coordinated turn with the turn rate in the state (Bar-Shalom, Li & Kirubarajan 2001,
// ch. 11, coordinated turn with unknown rate). With u = wT, s = sin u, c = cos u,
// sinc(u) = s/u and cosc(u) = (1-c)/u:
//   x'  = x + T sinc(u) vx - T cosc(u) vy      d/dw = T^2 (sinc'(u) vx - cosc'(u) vy)
//   vx' = c vx - s vy                           d/dw = -T (s vx + c vy)
//   y'  = y + T cosc(u) vx + T sinc(u) vy      d/dw = T^2 (cosc'(u) vx + sinc'(u) vy)
//   vy' = s vx + c vy                           d/dw =  T (c vx - s vy)
// At w = 0: sinc' = 0 and cosc' = 1/2, so dx'/dw = -T^2 vy / 2 and dy'/dw = T^2 vx / 2.
#include "skytrack/motion/coordinated_turn_estimated.hpp"

#include <cmath>

#include "motion_blocks.hpp"

namespace skytrack {
namespace {

double turn_rate_of(const StateLayout& layout, const StateVec& x) noexcept {
  return layout.turn_rate ? x[layout.turn_rate_index()] : 0.0;
}

}  // namespace

void CoordinatedTurnEstimated::linearise(const StateLayout& layout, const StateVec& x, double dt,
                                         StateMat& F, StateMat& Q) const noexcept {
  motion_detail::start_blocks(layout, F, Q);
  const double w = turn_rate_of(layout, x);
  motion_detail::set_ct_horizontal(w, accel_sigma * accel_sigma, dt, F, Q);
  if (layout.dims == 3) {
    motion_detail::set_cv_axis(2, vertical_accel_sigma * vertical_accel_sigma, dt, F, Q);
  }
  if (!layout.turn_rate) return;  // no w state: a fixed turn at w = 0
  const int xi = StateLayout::position(0), vxi = StateLayout::velocity(0);
  const int yi = StateLayout::position(1), vyi = StateLayout::velocity(1);
  const int wi = layout.turn_rate_index();
  const double vx = x[vxi], vy = x[vyi];
  const double u = w * dt, s = std::sin(u), c = std::cos(u);
  const double ds = dt * dt * motion_detail::sinc_derivative(u);
  const double dc = dt * dt * motion_detail::cosc_derivative(u);
  F(xi, wi) = ds * vx - dc * vy;
  F(vxi, wi) = -dt * (s * vx + c * vy);
  F(yi, wi) = dc * vx + ds * vy;
  F(vyi, wi) = dt * (c * vx - s * vy);
  Q(wi, wi) = turn_rate_sigma * turn_rate_sigma * std::abs(dt);
}

StateVec CoordinatedTurnEstimated::propagate(const StateLayout& layout, const StateVec& x,
                                             double dt) const noexcept {
  // f(x) = F_w x where F_w is the fixed-rate turn at the state's own w (w' = w).
  StateMat F, Q;
  motion_detail::start_blocks(layout, F, Q);
  motion_detail::set_ct_horizontal(turn_rate_of(layout, x), 0.0, dt, F, Q);
  if (layout.dims == 3) motion_detail::set_cv_axis(2, 0.0, dt, F, Q);
  StateVec out;
  out.noalias() = F * x;
  return out;
}

StateMat CoordinatedTurnEstimated::jacobian(const StateLayout& layout, const StateVec& x,
                                            double dt) const noexcept {
  StateMat F, Q;
  linearise(layout, x, dt, F, Q);
  return F;
}

StateMat CoordinatedTurnEstimated::process_noise(const StateLayout& layout, const StateVec& x,
                                                 double dt) const noexcept {
  StateMat F, Q;
  linearise(layout, x, dt, F, Q);
  return Q;
}

}  // namespace skytrack
