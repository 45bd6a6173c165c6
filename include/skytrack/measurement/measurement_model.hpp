#pragma once
// Measurement models h(x), their analytic Jacobians H(x), residuals and noise R
// (Bar-Shalom, Li & Kirubarajan 2001, §10.3, EKF with polar measurements).
// Frames (DESIGN.md, geometry/frames.hpp): tracking frame local ENU; a polar measurement is
// relative to the sensor platform, in its body frame (azimuth clockwise from the nose,
// elevation up from the body horizontal), with r = |p - p_s|, and range-rate the RELATIVE
// velocity (v - v_s) projected on the line of sight, positive when opening. A flight level
// is measured as the altitude above the sea sphere of geometry/altitude.hpp.
#include <cstdint>

#include <Eigen/Core>

#include "skytrack/core/plot.hpp"
#include "skytrack/filter/state.hpp"

namespace skytrack {

/// kPolarHeight: a secondary-radar plot with a flight level and no elevation, measured as
/// slant range, azimuth and altitude (3-D trackers only).
enum class MeasurementKind : std::uint8_t { kCartesian, kPolar, kPolarHeight };

/// Range and azimuth about the platform lead the components.
constexpr bool is_polar(MeasurementKind kind) {
  return kind != MeasurementKind::kCartesian;
}

/// One plot's measurement geometry. Components, in order:
///   Cartesian: x, y (, z)                               [m]
///   polar:     range, azimuth (, elevation) (, range-rate)   [m, rad, rad, m/s]
///   polar height: range, azimuth, altitude (, range-rate)    [m, rad, m, m/s]
/// `state_dims` is the tracker's (2 or 3). With 3, polar geometry is 3-D (slant range, full
/// attitude). With 2, it is horizontal: the target and the sensor are taken at the same
/// height, the attitude is levelled to the heading alone, range is horizontal range and
/// range-rate the horizontal one (measurement_from_plot converts 3-D plots to this).
/// Build with the factories, which cache the rotation.
struct MeasurementModel {
  MeasurementKind kind = MeasurementKind::kCartesian;
  int state_dims = 2;
  int position_components = 2;  // Cartesian: 2 (x, y) or 3 (x, y, z); polar: 2 or 3 (+ el);
                                // polar height: 3
  bool has_range_rate = false;  // polar kinds only
  PlatformState platform;       // polar only; 2-D: attitude = [heading, 0, 0]
  Eigen::Matrix3d enu_to_body = Eigen::Matrix3d::Identity();  // R(attitude)'
  MeasVec sigma;  // standard deviation of each component

  static MeasurementModel cartesian(int components, int state_dims, const MeasVec& sigma);
  static MeasurementModel polar(const PlatformState& platform, bool elevation, bool range_rate,
                                int state_dims, const MeasVec& sigma);
  /// Slant range, azimuth and altitude of a 3-D state (sigma: range, azimuth, altitude
  /// (, range-rate)).
  static MeasurementModel polar_height(const PlatformState& platform, bool range_rate,
                                       const MeasVec& sigma);

  int size() const noexcept { return position_components + (has_range_rate ? 1 : 0); }
  /// Index of the azimuth component, -1 when there is none.
  int azimuth_index() const noexcept { return is_polar(kind) ? 1 : -1; }

  /// h(x). The layout's dims must equal state_dims.
  MeasVec measure(const StateLayout& layout, const StateVec& x) const noexcept;
  /// H = dh/dx at x (size() x layout.size()); rows are 0 where a derivative is undefined
  /// (the target on the sensor, or on its vertical axis for the azimuth).
  MeasJacobian jacobian(const StateLayout& layout, const StateVec& x) const noexcept;
  /// z - zhat with the azimuth difference wrapped to [-pi, pi).
  MeasVec residual(const MeasVec& z, const MeasVec& zhat) const noexcept;
  /// R = diag(sigma^2).
  MeasMat noise() const noexcept;
  /// |d(tracking frame)/d(position components)| at z: converts a density per m^k in the
  /// tracking frame to one per unit of the measurement's position space (polar: r, or
  /// r^2 cos el with elevation; polar height: r, since the horizontal range is
  /// sqrt(r^2 - dz^2); Cartesian: 1).
  double volume_element(const MeasVec& z) const noexcept;
};

}  // namespace skytrack
