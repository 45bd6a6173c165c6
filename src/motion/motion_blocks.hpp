#pragma once
// Building blocks shared by the motion models: one axis of nearly-constant velocity or
// constant acceleration, the horizontal coordinated turn, and the treatment of the states a
// model does not use. Continuous white-noise models, exactly discretised (Bar-Shalom, Li &
// Kirubarajan 2001, §6.2.2 (CV) and §6.2.3 (CA)); the exact
// coordinated-turn Q is derived in coordinated_turn.cpp. Process noise uses |dt| (see
// motion_model.hpp for negative dt).
#include <cmath>

#include "skytrack/filter/state.hpp"
#include "turn_functions.hpp"

namespace skytrack::motion_detail {

/// Zero F and Q of the layout's size; w is carried unchanged (F_ww = 1, Q_ww = 0) unless a
/// model overwrites it.
inline void start_blocks(const StateLayout& layout, StateMat& F, StateMat& Q) noexcept {
  const int n = layout.size();
  F.setZero(n, n);
  Q.setZero(n, n);
  if (layout.turn_rate) F(layout.turn_rate_index(), layout.turn_rate_index()) = 1.0;
}

/// Nearly-constant velocity on one axis: F = [1 T; 0 1],
/// Q = q [T^3/3 T^2/2; T^2/2 T], q the acceleration PSD [m^2/s^3].
inline void set_cv_axis(int axis, double q, double dt, StateMat& F, StateMat& Q) noexcept {
  const int p = StateLayout::position(axis), v = StateLayout::velocity(axis);
  const double t = std::abs(dt);
  F(p, p) = 1.0;
  F(p, v) = dt;
  F(v, v) = 1.0;
  Q(p, p) = q * t * t * t / 3.0;
  Q(p, v) = Q(v, p) = q * t * t / 2.0;
  Q(v, v) = q * t;
}

/// Constant acceleration (Wiener-process acceleration) on one axis, states (p, v, a):
/// F = [1 T T^2/2; 0 1 T; 0 0 1], Q = q [T^5/20 T^4/8 T^3/6; . T^3/3 T^2/2; . . T],
/// q the jerk PSD [m^2/s^5].
inline void set_ca_axis(const StateLayout& layout, int axis, double q, double dt, StateMat& F,
                        StateMat& Q) noexcept {
  const int idx[3] = {StateLayout::position(axis), StateLayout::velocity(axis),
                      layout.acceleration_index(axis)};
  const double t = std::abs(dt);
  const double f[3][3] = {{1.0, dt, dt * dt / 2.0}, {0.0, 1.0, dt}, {0.0, 0.0, 1.0}};
  const double t2 = t * t, t3 = t2 * t;
  const double qm[3][3] = {{t2 * t3 / 20.0, t2 * t2 / 8.0, t3 / 6.0},
                           {t2 * t2 / 8.0, t3 / 3.0, t2 / 2.0},
                           {t3 / 6.0, t2 / 2.0, t}};
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      F(idx[r], idx[c]) = f[r][c];
      Q(idx[r], idx[c]) = q * qm[r][c];
    }
  }
}

/// Horizontal coordinated turn at rate w [rad/s] (positive = anticlockwise) over [x vx y vy]:
/// Bar-Shalom et al. 2001 ch. 11, with the exact white-acceleration Q (PSD q):
///   Q_pp = q 2 (wT - sin wT) / w^3 I,  Q_vv = q T I,
///   Q_{x,vx} = Q_{y,vy} = q (1 - cos wT) / w^2,  Q_{x,vy} = -Q_{y,vx} = q (wT - sin wT) / w^2.
inline void set_ct_horizontal(double w, double q, double dt, StateMat& F, StateMat& Q) noexcept {
  const int x = StateLayout::position(0), vx = StateLayout::velocity(0);
  const int y = StateLayout::position(1), vy = StateLayout::velocity(1);
  const double u = w * dt, s = std::sin(u), c = std::cos(u);
  const double a = dt * sinc(u), b = dt * cosc(u);  // sin(wT)/w, (1 - cos wT)/w
  F(x, x) = 1.0;
  F(x, vx) = a;
  F(x, vy) = -b;
  F(vx, vx) = c;
  F(vx, vy) = -s;
  F(y, y) = 1.0;
  F(y, vx) = b;
  F(y, vy) = a;
  F(vy, vx) = s;
  F(vy, vy) = c;

  const double t = std::abs(dt), ut = w * t;
  const double g = u_minus_sin_over_u3(ut);  // (u - sin u) / u^3
  const double half_sinc = sinc(0.5 * ut);
  const double pp = q * 2.0 * t * t * t * g;                       // 2 (wT - sin wT) / w^3
  const double pv_same = q * 0.5 * t * t * half_sinc * half_sinc;  // (1 - cos wT) / w^2
  const double pv_cross = q * t * t * ut * g;                      // (wT - sin wT) / w^2
  Q(x, x) = Q(y, y) = pp;
  Q(vx, vx) = Q(vy, vy) = q * t;
  Q(x, vx) = Q(vx, x) = Q(y, vy) = Q(vy, y) = pv_same;
  Q(x, vy) = Q(vy, x) = pv_cross;
  Q(y, vx) = Q(vx, y) = -pv_cross;
}

}  // namespace skytrack::motion_detail
