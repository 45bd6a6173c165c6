#pragma once
// From a plot of a scan to a measurement the filters use (CONTRACTS.md §1 plot fields).
//
// Which model a plot gives (tracker_dims = the tracker's position dimensions):
//   Cartesian x, y, z   3-D tracker: (x, y, z).           2-D tracker: (x, y), z dropped.
//   Cartesian x, y      3-D tracker: (x, y) of the 3-D state.   2-D tracker: (x, y).
//   polar r, az (, el)  3-D tracker: 3-D polar (slant range, az (, el)) relative to the
//                       platform with its full attitude; without elevation the plot measures
//                       the slant range and azimuth of the 3-D state.
//                       2-D tracker: the plot is placed in ENU with the full attitude
//                       (el = 0 when absent), then re-expressed as horizontal polar
//                       (rho, az_h) about the platform's horizontal position, az_h from the
//                       heading. For a level platform this is exactly (r cos el, az).
//   polar r, az, flight level, no elevation (a secondary-radar reply with Mode C / S altitude)
//                       3-D tracker: slant range, azimuth and altitude (MeasurementKind::
//                       kPolarHeight), sigma_h = the profile's default_sigma.height.
//                       2-D tracker: as a polar plot at the elevation that puts it at its
//                       altitude (geometry/altitude.hpp), so rho = sqrt(r^2 - dz^2) instead
//                       of the slant range: 6.5 instead of 9.8 km for FL 220 at 9.8 km.
//                       Cartesian plots ignore the flight level.
//   (+ range-rate)      kept as the last component. 2-D tracker: projected on the horizontal
//                       line of sight assuming the target flies level,
//                       rdot_h = (r rdot + dz v_sz) / rho, sigma scaled by r / rho.
// Sigma precedence: plot.sigma > scan.sigma > the profile's defaults. 2-D horizontal range
// sigma: sigma_rho^2 = (sigma_r rho / r)^2 + (dz sigma_el)^2 (first-order propagation); from a
// flight level, sigma_rho^2 = ((r sigma_r)^2 + (dz sigma_h)^2) / rho^2.
#include <cstdint>

#include <Eigen/Core>

#include "skytrack/config/profile.hpp"
#include "skytrack/core/expected.hpp"
#include "skytrack/core/plot.hpp"
#include "skytrack/measurement/measurement_model.hpp"

namespace skytrack {

struct PlotMeasurement {
  MeasurementModel model;
  MeasVec z;
  double time = 0.0;  // [s] plot_time(plot, scan)
  std::int64_t plot_id = 0;
  std::uint32_t sensor = 0;  // the sensor that saw it
  std::uint64_t scan = 0;    // the batch the plot arrived in
  // The antenna's sweep when the plot was seen [rad]: a rotating antenna's cumulative
  // azimuth, or 2 pi per look of a snapshot sensor; (b - a) / 2 pi counts one sensor's
  // looks between two of its plots (set by the tracker).
  double sweep = 0.0;
};

/// Fails on non-finite values, a non-positive range or sigma, |elevation| > pi/2, a 2-D
/// tracker's plot straight above or below the platform, or tracker_dims not 2 or 3.
Expected<PlotMeasurement> measurement_from_plot(const Plot& plot, const PlotScan& scan,
                                                const config::MeasurementSigmas& defaults,
                                                int tracker_dims);

/// The plot's position in the tracking frame, for gating indexes and initiation. Polar plots
/// without elevation are placed at el = 0 in the body frame (as plot_position_enu does), with
/// a flight level at its altitude; 2-D measurements (state_dims == 2) return z = 0.
Eigen::Vector3d approximate_position(const PlotMeasurement& measurement) noexcept;

}  // namespace skytrack
