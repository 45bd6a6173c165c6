// Plot -> measurement conversion; the rules and their reasons are in plot_measurement.hpp.
#include "skytrack/measurement/plot_measurement.hpp"

#include <cmath>
#include <numbers>
#include <optional>
#include <string>

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
  double range, azimuth, elevation, range_rate;
};

/// A 3-D tracker measures the plot as given.
PlotMeasurement polar_3d(const Plot& plot, const PlatformState& platform, const PolarSigmas& s) {
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
  const Eigen::Vector3d d = body_to_enu(platform.attitude) *
                            polar_to_body({r, plot.azimuth, plot.elevation.value_or(0.0)});
  const double rho = d.head<2>().norm();
  if (!(rho > 1e-9 * r)) return make_error("polar plot is vertical: no horizontal position");
  const bool rr = plot.range_rate.has_value();
  MeasVec z(rr ? 3 : 2), sigma(rr ? 3 : 2);
  z[0] = rho;
  z[1] = wrap_angle(std::atan2(d.x(), d.y()) - platform.attitude[0]);
  const double elevation_term = plot.elevation ? d.z() * s.elevation : 0.0;
  sigma[0] = std::hypot(s.range * rho / r, elevation_term);
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
      !finite(plot.range_rate)) {
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
  for (const auto* sv : {&sr, &sa, &se, &sd}) {
    if (!*sv) return unexpected(sv->error());
  }
  const PolarSigmas s{*sr, *sa, *se, *sd};
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
  const double elevation = model.position_components == 3 ? z[2] : 0.0;
  Eigen::Vector3d position = model.platform.position +
                             model.enu_to_body.transpose() * polar_to_body({z[0], z[1], elevation});
  if (model.state_dims == 2) position.z() = 0.0;
  return position;
}

}  // namespace skytrack
