#include "skytrack/geometry/frames.hpp"

#include <cmath>

#include <Eigen/Geometry>

namespace skytrack {

Eigen::Matrix3d body_to_enu(const Eigen::Vector3d& attitude) {
  // A ground radar's level, north-facing body frame is ENU itself (the common case, asked
  // for per track per look).
  if (attitude.isZero()) return Eigen::Matrix3d::Identity();
  const double heading = attitude[0], pitch = attitude[1], roll = attitude[2];
  const Eigen::Matrix3d yaw = Eigen::AngleAxisd(-heading, Eigen::Vector3d::UnitZ()).matrix();
  const Eigen::Matrix3d nose_up = Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitX()).matrix();
  const Eigen::Matrix3d wing_down = Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitY()).matrix();
  return yaw * nose_up * wing_down;
}

Eigen::Vector3d polar_to_body(const PolarPoint& polar) {
  const double horizontal = polar.range * std::cos(polar.elevation);
  return {horizontal * std::sin(polar.azimuth), horizontal * std::cos(polar.azimuth),
          polar.range * std::sin(polar.elevation)};
}

PolarPoint body_to_polar(const Eigen::Vector3d& body) {
  PolarPoint polar;
  polar.range = body.norm();
  if (polar.range == 0.0) return polar;
  polar.azimuth = std::atan2(body.x(), body.y());
  polar.elevation = std::atan2(body.z(), body.head<2>().norm());
  return polar;
}

Eigen::Vector3d polar_to_enu(const PolarPoint& polar, const PlatformState& platform) {
  return platform.position + body_to_enu(platform.attitude) * polar_to_body(polar);
}

PolarPoint enu_to_polar(const Eigen::Vector3d& position, const PlatformState& platform) {
  const Eigen::Vector3d body =
      body_to_enu(platform.attitude).transpose() * (position - platform.position);
  return body_to_polar(body);
}

double range_rate(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity,
                  const PlatformState& platform) {
  const Eigen::Vector3d line_of_sight = position - platform.position;
  const double range = line_of_sight.norm();
  if (range == 0.0) return 0.0;
  return line_of_sight.dot(velocity - platform.velocity) / range;
}

Eigen::Vector3d plot_position_enu(const Plot& plot, const PlatformState& platform) {
  if (plot.form == PlotForm::kCartesian) return {plot.x, plot.y, plot.z.value_or(0.0)};
  return polar_to_enu({plot.range, plot.azimuth, plot.elevation.value_or(0.0)}, platform);
}

}  // namespace skytrack
