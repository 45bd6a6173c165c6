// Singer model (Singer 1970, IEEE Trans. AES-6(4), its F and Q;
// Li & Jilkov 2003, survey part I). Per axis, with alpha = 1/tau, u = alpha T and
// phi(t) = F(t) e3 = [(alpha t - 1 + e^-alpha t)/alpha^2, (1 - e^-alpha t)/alpha, e^-alpha t]:
//   Q_ij = 2 alpha sigma_m^2 int_0^T phi_i phi_j dt.
// Closed forms (E1 = e^-u, E2 = e^-2u), each int_0^T phi_i phi_j = T^(k) g_ij(u):
//   g33 = (1 - E2) / (2u)                       g23 = (1 - 2 E1 + E2) / (2u^2)
//   g13 = (1 - E2 - 2u E1) / (2u^3)             g22 = (2u - 3 + 4 E1 - E2) / (2u^3)
//   g12 = (u^2 - 2u + 1 - 2E1 + 2u E1 + E2) / (2u^4)
//   g11 = (2u^3/3 - 2u^2 + 2u + 1 - E2 - 4u E1) / (2u^5)
// For |u| < 1 these cancel, so the same integrals are summed as power series: with
// phi_i(t) = t^a_i sum_n c_in (-alpha t)^n (a = 2, 1, 0; c_in = 1/(n+a_i)!),
//   int_0^T phi_i phi_j = T^(a_i+a_j+1) sum_m (-u)^m d_m / (a_i + a_j + m + 1),
//   d_m = sum_{n<=m} c_in c_j(m-n).
#include "skytrack/motion/singer.hpp"

#include <array>
#include <cmath>

#include "motion_blocks.hpp"

namespace skytrack {
namespace {

constexpr int kTerms = 26;
constexpr int kPower[3] = {2, 1, 0};  // phi_i(t) = t^kPower[i] (1 + O(alpha t))
using Axis3 = std::array<std::array<double, 3>, 3>;
using SeriesTable = std::array<std::array<std::array<double, kTerms>, 3>, 3>;

/// e[i][j][m] = d_m / (a_i + a_j + m + 1): the series of int phi_i phi_j, without T and u.
constexpr SeriesTable make_series_table() {
  std::array<std::array<double, kTerms>, 3> c{};  // c[i][n] = 1 / (n + a_i)!
  for (int i = 0; i < 3; ++i) {
    double factorial = 1.0;
    for (int k = 2; k <= kPower[i]; ++k) factorial *= k;
    for (int n = 0; n < kTerms; ++n) {
      c[i][n] = 1.0 / factorial;
      factorial *= n + kPower[i] + 1;
    }
  }
  SeriesTable e{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int m = 0; m < kTerms; ++m) {
        double d = 0.0;
        for (int n = 0; n <= m; ++n) d += c[i][n] * c[j][m - n];
        e[i][j][m] = d / (kPower[i] + kPower[j] + m + 1);
      }
    }
  }
  return e;
}

constexpr SeriesTable kSeries = make_series_table();

/// int_0^T phi_i phi_j dt for T >= 0.
Axis3 noise_integrals(double alpha, double t) noexcept {
  const double u = alpha * t;
  Axis3 g{};
  if (u < 1.0) {
    const double t_power[6] = {1.0, t, t * t, t * t * t, t * t * t * t, t * t * t * t * t};
    for (int i = 0; i < 3; ++i) {
      for (int j = i; j < 3; ++j) {
        double sum = 0.0;
        for (int m = kTerms - 1; m >= 0; --m) sum = sum * -u + kSeries[i][j][m];  // Horner
        g[i][j] = g[j][i] = t_power[kPower[i] + kPower[j] + 1] * sum;
      }
    }
    return g;
  }
  const double e1 = std::exp(-u), e2 = std::exp(-2.0 * u);
  const double a2 = alpha * alpha, a3 = a2 * alpha, a4 = a3 * alpha, a5 = a4 * alpha;
  g[2][2] = (1.0 - e2) / (2.0 * alpha);
  g[1][2] = g[2][1] = (1.0 - 2.0 * e1 + e2) / (2.0 * a2);
  g[0][2] = g[2][0] = (1.0 - e2 - 2.0 * u * e1) / (2.0 * a3);
  g[1][1] = (2.0 * u - 3.0 + 4.0 * e1 - e2) / (2.0 * a3);
  g[0][1] = g[1][0] = (u * u - 2.0 * u + 1.0 - 2.0 * e1 + 2.0 * u * e1 + e2) / (2.0 * a4);
  g[0][0] = (2.0 * u * u * u / 3.0 - 2.0 * u * u + 2.0 * u + 1.0 - e2 - 4.0 * u * e1) / (2.0 * a5);
  return g;
}

/// Third column of F(dt): (phi1, phi2, phi3) at dt (any sign).
std::array<double, 3> acceleration_column(double alpha, double dt) noexcept {
  const double u = alpha * dt;
  if (std::abs(u) >= 1.0) {
    const double e = std::exp(-u);
    return {(u - 1.0 + e) / (alpha * alpha), (1.0 - e) / alpha, e};
  }
  double s1 = 0.0, s2 = 0.0, power = 1.0, f1 = 2.0, f2 = 1.0;  // (n+2)!, (n+1)!
  for (int n = 0; n < kTerms; ++n) {
    s1 += power / f1;
    s2 += power / f2;
    power *= -u;
    f1 *= n + 3;
    f2 *= n + 2;
  }
  return {dt * dt * s1, dt * s2, std::exp(-u)};
}

}  // namespace

void Singer::discretise(const StateLayout& layout, double dt, StateMat& F,
                        StateMat& Q) const noexcept {
  motion_detail::start_blocks(layout, F, Q);
  const double alpha = 1.0 / time_constant;
  const double q = 2.0 * alpha * accel_sigma * accel_sigma;
  const std::array<double, 3> column = acceleration_column(alpha, dt);
  const Axis3 g = noise_integrals(alpha, std::abs(dt));
  for (int axis = 0; axis < 2; ++axis) {
    const int idx[3] = {StateLayout::position(axis), StateLayout::velocity(axis),
                        layout.acceleration_index(axis)};
    F(idx[0], idx[0]) = 1.0;
    F(idx[0], idx[1]) = dt;
    F(idx[1], idx[1]) = 1.0;
    for (int r = 0; r < 3; ++r) {
      F(idx[r], idx[2]) = column[r];
      for (int c = 0; c < 3; ++c) Q(idx[r], idx[c]) = q * g[r][c];
    }
  }
  if (layout.dims == 3) {  // az (if present) stays 0: its F row and Q entries are zero
    motion_detail::set_cv_axis(2, vertical_accel_sigma * vertical_accel_sigma, dt, F, Q);
  }
}

StateMat Singer::transition(const StateLayout& layout, double dt) const noexcept {
  StateMat F, Q;
  discretise(layout, dt, F, Q);
  return F;
}

StateMat Singer::process_noise(const StateLayout& layout, double dt) const noexcept {
  StateMat F, Q;
  discretise(layout, dt, F, Q);
  return Q;
}

}  // namespace skytrack
