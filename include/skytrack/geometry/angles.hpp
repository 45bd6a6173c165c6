#pragma once
// Angle helpers. All angles are radians.
#include <cmath>
#include <numbers>

namespace skytrack {

/// Wraps an angle to [-pi, pi).
inline double wrap_angle(double angle) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  double wrapped = std::fmod(angle + std::numbers::pi, kTwoPi);
  if (wrapped < 0.0) wrapped += kTwoPi;
  return wrapped - std::numbers::pi;
}

/// Wraps an angle to [0, 2 pi).
inline double wrap_angle_positive(double angle) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  double wrapped = std::fmod(angle, kTwoPi);
  if (wrapped < 0.0) wrapped += kTwoPi;
  return wrapped;
}

}  // namespace skytrack
