#pragma once
// Altitude of a point of the tracking frame, for flight-level (pressure altitude) plots.
// The tracking frame is flat East-North-Up; its z = 0 is taken as mean sea level, so a
// ground radar's platform position carries its antenna's height above sea level. The sea
// surface is a sphere of the mean earth radius touching the frame at its origin, so a point
// at height z above the plane and horizontal distance s lies about s^2 / (2 R) higher above
// the sea than z: 5.7 km at 270 km (an en-route radar's reach), 2 m at 5 km. A flight level is
// a pressure altitude (standard atmosphere), taken here as the altitude above the sphere: the
// two differ by the day's deviation from the standard atmosphere, a bias shared by the
// aircraft round one place.
#include <algorithm>
#include <cmath>

#include <Eigen/Core>

namespace skytrack {

inline constexpr double kEarthRadius = 6371000.0;  // [m] mean radius

/// Altitude [m] above the sea sphere of a tracking-frame point.
inline double altitude_of(const Eigen::Vector3d& p) {
  return std::sqrt(p.x() * p.x() + p.y() * p.y() +
                   (p.z() + kEarthRadius) * (p.z() + kEarthRadius)) -
         kEarthRadius;
}

/// d altitude / d position at p.
inline Eigen::Vector3d altitude_gradient(const Eigen::Vector3d& p) {
  const double h = altitude_of(p) + kEarthRadius;
  return Eigen::Vector3d(p.x(), p.y(), p.z() + kEarthRadius) / h;
}

/// Height above the platform [m] (tracking-frame z difference) of a point at slant range
/// `range` whose altitude is `altitude`, seen from a platform at `platform`: exact for a
/// platform on the frame's vertical axis; off it, the local vertical tilts by the platform's
/// horizontal offset over the earth radius (1 mrad per 6 km), so it is a first guess there.
/// Clamped to [-range, range].
inline double height_above_platform(double range, double altitude,
                                    const Eigen::Vector3d& platform) {
  const double platform_radius = altitude_of(platform) + kEarthRadius;
  const double target_radius = altitude + kEarthRadius;
  // With the earth's centre straight below the platform at platform_radius:
  // target_radius^2 = range^2 + platform_radius^2 + 2 platform_radius dz.
  const double dz =
      ((target_radius - platform_radius) * (target_radius + platform_radius) - range * range) /
      (2.0 * platform_radius);
  return std::clamp(dz, -range, range);
}

}  // namespace skytrack
