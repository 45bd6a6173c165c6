#pragma once
// Trigonometric kernels of the coordinated-turn model (Bar-Shalom, Li & Kirubarajan 2001,
// ch. 11; Li & Jilkov 2003, "Survey of maneuvering target tracking, part I", CT model),
// written as functions of u = w T so that the w -> 0 limit is continuous: each switches to
// its Taylor series for small |u|, where the closed form cancels catastrophically.
#include <cmath>

namespace skytrack::motion_detail {

inline constexpr double kSeriesBelow = 0.5;  // |u| below which the series are used

/// sin(u) / u.
inline double sinc(double u) noexcept {
  if (std::abs(u) >= 1e-4) return std::sin(u) / u;
  return 1.0 - u * u / 6.0;
}

/// (1 - cos u) / u = 2 sin^2(u / 2) / u (no cancellation).
inline double cosc(double u) noexcept {
  const double half = 0.5 * u;
  return half * sinc(half) * sinc(half);
}

/// d/du [sin(u) / u] = (u cos u - sin u) / u^2 = sum_k (-1)^k 2k / (2k+1)! u^(2k-1).
inline double sinc_derivative(double u) noexcept {
  if (std::abs(u) >= kSeriesBelow) return (u * std::cos(u) - std::sin(u)) / (u * u);
  double sum = 0.0, power = u, factorial = 6.0, sign = -1.0;  // k = 1: -2/3! u
  for (int k = 1; k <= 8; ++k) {
    sum += sign * 2.0 * k / factorial * power;
    power *= u * u;
    factorial *= (2.0 * k + 2.0) * (2.0 * k + 3.0);
    sign = -sign;
  }
  return sum;
}

/// d/du [(1 - cos u) / u] = (u sin u - (1 - cos u)) / u^2
///   = sum_k (-1)^(k+1) (2k-1) / (2k)! u^(2k-2).
inline double cosc_derivative(double u) noexcept {
  if (std::abs(u) >= kSeriesBelow) return (u * std::sin(u) - (1.0 - std::cos(u))) / (u * u);
  double sum = 0.0, power = 1.0, factorial = 2.0, sign = 1.0;  // k = 1: 1/2!
  for (int k = 1; k <= 8; ++k) {
    sum += sign * (2.0 * k - 1.0) / factorial * power;
    power *= u * u;
    factorial *= (2.0 * k + 1.0) * (2.0 * k + 2.0);
    sign = -sign;
  }
  return sum;
}

/// (u - sin u) / u^3 = sum_k (-1)^(k+1) u^(2k-2) / (2k+1)!.
inline double u_minus_sin_over_u3(double u) noexcept {
  if (std::abs(u) >= kSeriesBelow) return (u - std::sin(u)) / (u * u * u);
  double sum = 0.0, power = 1.0, factorial = 6.0, sign = 1.0;  // k = 1: 1/3!
  for (int k = 1; k <= 8; ++k) {
    sum += sign / factorial * power;
    power *= u * u;
    factorial *= (2.0 * k + 2.0) * (2.0 * k + 3.0);
    sign = -sign;
  }
  return sum;
}

}  // namespace skytrack::motion_detail
