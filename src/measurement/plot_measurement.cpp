// Plot -> measurement conversion; the rules and their reasons are in plot_measurement.hpp.
#include "skytrack/measurement/plot_measurement.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "skytrack/core/transponder.hpp"
#include "skytrack/geometry/altitude.hpp"
#include "skytrack/geometry/angles.hpp"
#include "skytrack/geometry/frames.hpp"

namespace skytrack {
namespace {

bool finite(double value) {
  return std::isfinite(value);
}
bool finite(const std::optional<double>& value) {
  return !value || std::isfinite(*value);
}

Expected<double> sigma_of(const std::optional<double>& given, double fallback, const char* name) {
  const double sigma = given.value_or(fallback);
  if (!(sigma > 0.0) || !std::isfinite(sigma)) {
    return make_error(std::string("measurement sigma '") + name + "' must be positive");
  }
  return sigma;
}

Expected<PlotMeasurement> cartesian_measurement(const Plot& plot, const MeasurementSigma& sigma,
                                                const config::MeasurementSigmas& defaults,
                                                int dims) {
  if (!finite(plot.x) || !finite(plot.y) || !finite(plot.z)) {
    return make_error("Cartesian plot has a non-finite coordinate");
  }
  const int components = (dims == 3 && plot.z) ? 3 : 2;
  const auto sx = sigma_of(sigma.x, defaults.x, "x");
  const auto sy = sigma_of(sigma.y, defaults.y, "y");
  const auto sz = components == 3 ? sigma_of(sigma.z, defaults.z, "z") : Expected<double>(1.0);
  for (const auto* sv : {&sx, &sy, &sz}) {
    if (!*sv) return unexpected(sv->error());
  }
  MeasVec z(components), s(components);
  z[0] = plot.x;
  z[1] = plot.y;
  s[0] = *sx;
  s[1] = *sy;
  if (components == 3) {
    z[2] = *plot.z;
    s[2] = *sz;
  }
  return PlotMeasurement{MeasurementModel::cartesian(components, dims, s), z, 0.0, plot.id};
}

struct PolarSigmas {
  double range, azimuth, elevation, range_rate, height;
};

/// The body elevation [rad] at which a plot at slant range r and body azimuth az from a
/// platform at `position` lies at `altitude`. Started from the platform's own vertical
/// (exact for a level platform on the frame's vertical axis), then Newton steps on
/// d altitude / d el = r cos el: a platform tilted or tens of kilometres off the origin
/// converges to a millimetre in three.
double elevation_for_altitude(double r, double az, double altitude, const Eigen::Vector3d& position,
                              const Eigen::Matrix3d& to_enu) {
  constexpr double kHalfPi = std::numbers::pi / 2;
  double el = std::asin(std::clamp(height_above_platform(r, altitude, position) / r, -1.0, 1.0));
  for (int step = 0; step < 4; ++step) {
    const double error = altitude - altitude_of(position + to_enu * polar_to_body({r, az, el}));
    el = std::clamp(el + error / (r * std::max(std::cos(el), 0.1)), -kHalfPi, kHalfPi);
  }
  return el;
}

/// The body elevation of a plot with a flight level and no elevation.
double flight_level_elevation(const Plot& plot, const PlatformState& platform,
                              const Eigen::Matrix3d& to_enu) {
  return elevation_for_altitude(plot.range, plot.azimuth,
                                flight_level_to_metres(*plot.flight_level), platform.position,
                                to_enu);
}

/// Whether the plot's height comes from its flight level (polar, no elevation).
bool uses_flight_level(const Plot& plot) {
  return plot.flight_level.has_value() && !plot.elevation.has_value();
}

/// A 3-D tracker measures a plot with a flight level and no elevation as slant range,
/// azimuth and altitude.
PlotMeasurement polar_height(const Plot& plot, const PlatformState& platform,
                             const PolarSigmas& s) {
  const bool rr = plot.range_rate.has_value();
  MeasVec z(rr ? 4 : 3), sigma(rr ? 4 : 3);
  z << plot.range, wrap_angle(plot.azimuth), flight_level_to_metres(*plot.flight_level);
  sigma << s.range, s.azimuth, s.height;
  if (rr) {
    z[3] = *plot.range_rate;
    sigma[3] = s.range_rate;
  }
  return {MeasurementModel::polar_height(platform, rr, sigma), z, 0.0, plot.id};
}

/// A 3-D tracker measures the plot as given.
PlotMeasurement polar_3d(const Plot& plot, const PlatformState& platform, const PolarSigmas& s) {
  if (uses_flight_level(plot)) return polar_height(plot, platform, s);
  const bool el = plot.elevation.has_value(), rr = plot.range_rate.has_value();
  const int n = 2 + (el ? 1 : 0) + (rr ? 1 : 0);
  MeasVec z(n), sigma(n);
  z[0] = plot.range;
  z[1] = wrap_angle(plot.azimuth);
  sigma[0] = s.range;
  sigma[1] = s.azimuth;
  if (el) {
    z[2] = *plot.elevation;
    sigma[2] = s.elevation;
  }
  if (rr) {
    z[n - 1] = *plot.range_rate;
    sigma[n - 1] = s.range_rate;
  }
  return {MeasurementModel::polar(platform, el, rr, 3, sigma), z, 0.0, plot.id};
}

/// A 2-D tracker measures the plot's horizontal projection (plot_measurement.hpp).
Expected<PlotMeasurement> polar_2d(const Plot& plot, const PlatformState& platform,
                                   const PolarSigmas& s) {
  const double r = plot.range;
  const Eigen::Matrix3d to_enu = body_to_enu(platform.attitude);
  const bool height = uses_flight_level(plot);
  const double elevation =
      height ? flight_level_elevation(plot, platform, to_enu) : plot.elevation.value_or(0.0);
  const Eigen::Vector3d d = to_enu * polar_to_body({r, plot.azimuth, elevation});
  const double rho = d.head<2>().norm();
  if (!(rho > 1e-9 * r)) return make_error("polar plot is vertical: no horizontal position");
  const bool rr = plot.range_rate.has_value();
  MeasVec z(rr ? 3 : 2), sigma(rr ? 3 : 2);
  z[0] = rho;
  z[1] = wrap_angle(std::atan2(d.x(), d.y()) - platform.attitude[0]);
  // rho = sqrt(r^2 - dz^2): from an elevation, d rho = (rho / r) dr - dz d el; from a height,
  // with r and dz measured apart, d rho = (r dr - dz d dz) / rho.
  if (height) {
    sigma[0] = std::hypot(s.range * r, d.z() * s.height) / rho;
  } else {
    const double elevation_term = plot.elevation ? d.z() * s.elevation : 0.0;
    sigma[0] = std::hypot(s.range * rho / r, elevation_term);
  }
  sigma[1] = s.azimuth;
  if (rr) {
    z[2] = (r * *plot.range_rate + d.z() * platform.velocity.z()) / rho;
    sigma[2] = s.range_rate * r / rho;
  }
  return PlotMeasurement{MeasurementModel::polar(platform, false, rr, 2, sigma), z, 0.0, plot.id};
}

Expected<PlotMeasurement> polar_measurement(const Plot& plot, const PlotScan& scan,
                                            const MeasurementSigma& sigma,
                                            const config::MeasurementSigmas& defaults, int dims) {
  if (!finite(plot.range) || !finite(plot.azimuth) || !finite(plot.elevation) ||
      !finite(plot.range_rate) || !finite(plot.flight_level)) {
    return make_error("polar plot has a non-finite value");
  }
  if (!(plot.range > 0.0)) return make_error("polar plot range must be positive");
  if (plot.elevation && std::abs(*plot.elevation) > std::numbers::pi / 2) {
    return make_error("polar plot elevation must lie in [-pi/2, pi/2]");
  }
  const auto sr = sigma_of(sigma.range, defaults.range, "range");
  const auto sa = sigma_of(sigma.azimuth, defaults.azimuth, "azimuth");
  const auto se = plot.elevation ? sigma_of(sigma.elevation, defaults.elevation, "elevation")
                                 : Expected<double>(1.0);
  const auto sd = plot.range_rate ? sigma_of(sigma.range_rate, defaults.range_rate, "range_rate")
                                  : Expected<double>(1.0);
  const auto sh = uses_flight_level(plot) ? sigma_of(std::nullopt, defaults.height, "height")
                                          : Expected<double>(1.0);
  for (const auto* sv : {&sr, &sa, &se, &sd, &sh}) {
    if (!*sv) return unexpected(sv->error());
  }
  const PolarSigmas s{*sr, *sa, *se, *sd, *sh};
  if (dims == 3) return polar_3d(plot, scan.platform, s);
  return polar_2d(plot, scan.platform, s);
}

}  // namespace

Expected<PlotMeasurement> measurement_from_plot(const Plot& plot, const PlotScan& scan,
                                                const config::MeasurementSigmas& defaults,
                                                int tracker_dims) {
  if (tracker_dims != 2 && tracker_dims != 3) return make_error("tracker dims must be 2 or 3");
  const double time = plot_time(plot, scan);
  if (!std::isfinite(time)) return make_error("plot time is not finite");
  const MeasurementSigma sigma = merged(plot.sigma, scan.sigma);
  Expected<PlotMeasurement> out =
      plot.form == PlotForm::kCartesian
          ? cartesian_measurement(plot, sigma, defaults, tracker_dims)
          : polar_measurement(plot, scan, sigma, defaults, tracker_dims);
  if (out) out->time = time;
  return out;
}

Eigen::Vector3d approximate_position(const PlotMeasurement& measurement) noexcept {
  const MeasurementModel& model = measurement.model;
  const MeasVec& z = measurement.z;
  if (model.kind == MeasurementKind::kCartesian) {
    return {z[0], z[1], model.position_components == 3 ? z[2] : 0.0};
  }
  const Eigen::Matrix3d to_enu = model.enu_to_body.transpose();
  double elevation = model.position_components == 3 ? z[2] : 0.0;
  if (model.kind == MeasurementKind::kPolarHeight) {
    elevation = elevation_for_altitude(z[0], z[1], z[2], model.platform.position, to_enu);
  }
  Eigen::Vector3d position =
      model.platform.position + to_enu * polar_to_body({z[0], z[1], elevation});
  if (model.state_dims == 2) position.z() = 0.0;
  return position;
}

}  // namespace skytrack
