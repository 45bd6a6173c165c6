// From a scan's PlotMeasurements (measurement/plot_measurement.hpp) to prepared ScanPlots.
#include "skytrack/bernoulli/plot_history.hpp"

#include <algorithm>
#include <cmath>

namespace skytrack::bernoulli {

PlotHistory::PlotHistory(const BernoulliSpec& spec) : spec_(spec) {
  for (auto& buffer : buffers_) buffer.reserve(64);
}

int PlotHistory::load(std::span<const PlotMeasurement> plots,
                      const Eigen::Vector2d& platform) noexcept {
  std::vector<ScanPlot>& out = buffers_[slot(0)];
  out.clear();
  int rejected = 0;
  for (const PlotMeasurement& m : plots) {
    const MeasurementModel& model = m.model;
    ScanPlot plot;
    bool ok = false;
    if (model.state_dims != 2 || m.z.size() < 2 || model.sigma.size() < 2) {
      ok = false;
    } else if (model.kind == MeasurementKind::kPolar && model.position_components == 2) {
      // The azimuth is measured from the platform's heading: turn it into the tracking frame.
      const double az = m.z[1];
      const Eigen::Vector3d body(std::sin(az), std::cos(az), 0.0);
      const Eigen::Vector3d enu = model.enu_to_body.transpose() * body;
      const Eigen::Vector2d origin = model.platform.position.head<2>();
      ok = make_polar_plot(origin, m.z[0], std::atan2(enu.x(), enu.y()), model.sigma[0],
                           model.sigma[1], spec_.clutter_intensity, spec_.gate_distance_squared,
                           plot);
    } else if (model.kind == MeasurementKind::kCartesian) {
      const Eigen::Vector2d p(m.z[0], m.z[1]);
      const double range = std::max((p - platform).norm(), 1.0);
      ok = make_cartesian_plot(p, model.sigma[0], model.sigma[1], spec_.clutter_intensity / range,
                               spec_.gate_distance_squared, plot);
    }
    if (ok) {
      out.push_back(plot);
    } else {
      ++rejected;
    }
  }
  return rejected;
}

int PlotHistory::load(const Eigen::Vector2d& platform,
                      std::span<const PolarPlot2d> plots) noexcept {
  std::vector<ScanPlot>& out = buffers_[slot(0)];
  out.clear();
  int rejected = 0;
  for (const PolarPlot2d& p : plots) {
    ScanPlot plot;
    if (make_polar_plot(platform, p.range, p.azimuth, p.sigma_range, p.sigma_azimuth,
                        spec_.clutter_intensity, spec_.gate_distance_squared, plot)) {
      out.push_back(plot);
    } else {
      ++rejected;
    }
  }
  return rejected;
}

void PlotHistory::advance(double time) noexcept {
  times_[slot(0)] = time;
  head_ = (head_ + 1) % 3;
  buffers_[slot(0)].clear();
  scans_ = std::min(scans_ + 1, 3);
}

void PlotHistory::clear() noexcept {
  for (auto& buffer : buffers_) buffer.clear();
  times_ = {};
  scans_ = 0;
}

}  // namespace skytrack::bernoulli
