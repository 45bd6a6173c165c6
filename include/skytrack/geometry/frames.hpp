#pragma once
// Sensor geometry. Tracking frame: local East-North-Up (x east, y north, z up).
// Body frame of the platform: x right wing, y nose, z up; with zero attitude it coincides
// with ENU. A polar plot (range r, azimuth az clockwise from the nose, elevation el up from
// the body horizontal) is the body vector r [sin az cos el, cos az cos el, sin el].
// Attitude [heading psi (clockwise from north), pitch theta (nose up), roll phi (right wing
// down)] rotates body into ENU as R = Rz(-psi) Rx(theta) Ry(phi) (yaw, then pitch, then roll).
#include <Eigen/Core>

#include "skytrack/core/plot.hpp"

namespace skytrack {

/// Body -> ENU rotation for an attitude [heading, pitch, roll].
Eigen::Matrix3d body_to_enu(const Eigen::Vector3d& attitude);

/// Polar measurement in the body frame.
struct PolarPoint {
  double range = 0.0;      // [m]
  double azimuth = 0.0;    // [rad] clockwise from the nose, in [-pi, pi)
  double elevation = 0.0;  // [rad]
};

/// Body-frame polar -> body-frame Cartesian (right, forward, up).
Eigen::Vector3d polar_to_body(const PolarPoint& polar);
/// Body-frame Cartesian -> polar. Undefined direction at the origin gives zero angles.
PolarPoint body_to_polar(const Eigen::Vector3d& body);

/// Polar plot relative to the platform -> ENU position.
Eigen::Vector3d polar_to_enu(const PolarPoint& polar, const PlatformState& platform);
/// ENU position -> polar relative to the platform (the measurement function h(x)).
PolarPoint enu_to_polar(const Eigen::Vector3d& position, const PlatformState& platform);

/// Range-rate of a target seen from the platform: relative velocity along the line of sight,
/// positive when the range opens.
double range_rate(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity,
                  const PlatformState& platform);

/// A plot's position in the tracking frame (polar plots without elevation lie in the
/// platform's horizontal body plane, el = 0; Cartesian plots without z have z = 0).
Eigen::Vector3d plot_position_enu(const Plot& plot, const PlatformState& platform);

}  // namespace skytrack
