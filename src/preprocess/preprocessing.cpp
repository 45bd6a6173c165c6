#include "skytrack/preprocess/preprocessing.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "skytrack/tracking/initiator.hpp"

namespace skytrack {
namespace {

std::optional<clutter::ClutterMapCells> clutter_map_cells(const config::ClutterMapSpec& map) {
  if (!map.enabled) return std::nullopt;
  return clutter::ClutterMapCells{
      .range = map.range_cell, .azimuth = map.azimuth_cell, .cartesian = map.cartesian_cell};
}

}  // namespace

double sparse_clutter_density(int position_dims) {
  return std::pow(1e-4, position_dims);
}

Preprocessing::Preprocessing(const config::TrackingProfile& profile, int dims)
    : profile_(profile),
      dims_(dims),
      rejector_(profile.clutter_rejection),
      density_(clutter_map_cells(profile.association.clutter_map)) {}

void Preprocessing::prepare(const PlotScan& look, const LookSources* sources, ScanReport& report) {
  ++looks_;
  plots_.clear();
  positions_.clear();
  report.plots = static_cast<int>(look.plots.size());
  sensor_ = look.sensor;
  windowed_ = sources != nullptr && !profile_.association.clutter_density;
  counted_.assign(look.plots.size(), 0);
  // A snapshot look is one revolution's worth of sweep after the last.
  const double snapshot_sweep = 2.0 * std::numbers::pi * static_cast<double>(looks_);
  sweep_ = sources != nullptr ? sources->sweep_to : snapshot_sweep;
  for (std::size_t i = 0; i < look.plots.size(); ++i) {
    const int from = sources != nullptr ? sources->batch_of[i] : -1;
    const PlotScan& header = from >= 0 ? sources->batches[static_cast<std::size_t>(from)] : look;
    auto measurement =
        measurement_from_plot(look.plots[i], header, profile_.measurement.default_sigma, dims_);
    if (!measurement) {
      ++report.plots_invalid;
      continue;
    }
    measurement->sensor = look.sensor;
    measurement->scan = header.scan;
    measurement->sweep = sources != nullptr ? sources->sweep[i] : snapshot_sweep;
    positions_.push_back(approximate_position(*measurement));
    plots_.push_back(std::move(*measurement));
  }
  rejected_.assign(plots_.size(), 0);
  estimate_.assign(plots_.size(), 0.0);
  const bool heightless =
      dims_ == 3 && std::any_of(plots_.begin(), plots_.end(), [](const PlotMeasurement& p) {
        return is_polar(p.model.kind) && p.model.position_components != 3;
      });
  cloud_radii_.clear();
  for (const PlotMeasurement& p : plots_) cloud_radii_.push_back(kCloudSigmas * position_sigma(p));
  crowd_.assign(plots_.size(), 0);
  // Cells of the median cloud radius (the answers do not depend on it, only the work).
  double cell = 0.0;
  if (!plots_.empty()) {
    cloud_median_ = cloud_radii_;
    const auto median =
        cloud_median_.begin() + static_cast<std::ptrdiff_t>(cloud_median_.size() / 2);
    std::nth_element(cloud_median_.begin(), median, cloud_median_.end());
    cell = *median;
  }
  index_.build(positions_, heightless ? 2 : dims_, cell);
  for (std::size_t j = 0; j < plots_.size(); ++j) {
    crowd_[j] = index_.more_than(positions_[j], cloud_radii_[j], kCloudPlots);
  }
}

const clutter::ClutterRejectionResult& Preprocessing::reject_clutter(
    std::span<const std::uint8_t> protect) {
  const clutter::ClutterRejectionResult& result = rejector_.apply(positions_, dims_, protect);
  for (std::size_t j = 0; j < plots_.size(); ++j) rejected_[j] = result.keep[j] ? 0 : 1;
  return result;
}

void Preprocessing::estimate_density(std::span<const std::uint8_t> false_plots) {
  estimate_.assign(plots_.size(), 0.0);
  own_.assign(plots_.size(), 0);
  if (profile_.association.clutter_density) return;
  counted_.assign(plots_.size(), 0);
  if (profile_.association.clutter_map.enabled) {
    for (std::size_t j = 0; j < plots_.size(); ++j) {
      counted_[j] = !rejected_[j] && j < false_plots.size() && false_plots[j] ? 1 : 0;
    }
  }
  boxed_.resize(plots_.size());
  for (std::size_t j = 0; j < plots_.size(); ++j) boxed_[j] = rejected_[j] || crowd_[j] ? 0 : 1;
  density_.estimate(sensor_, windowed_, plots_, boxed_, counted_, estimate_);
  for (std::size_t j = 0; j < plots_.size(); ++j) own_[j] = estimate_[j] > 0.0 ? 1 : 0;
}

void Preprocessing::share_density(std::span<const int> gate) {
  if (own_.size() != estimate_.size()) return;  // no estimate made yet
  double shared = 0.0;
  for (const int j : gate) {
    if (own_[static_cast<std::size_t>(j)]) {
      shared = std::max(shared, estimate_[static_cast<std::size_t>(j)]);
    }
  }
  if (!(shared > 0.0)) return;
  for (const int j : gate) {
    double& estimate = estimate_[static_cast<std::size_t>(j)];
    if (!own_[static_cast<std::size_t>(j)]) estimate = std::max(estimate, shared);
  }
}

double Preprocessing::density(const PlotMeasurement& plot, int index) const {
  if (index >= 0 && estimate_[static_cast<std::size_t>(index)] > 0.0) {
    return estimate_[static_cast<std::size_t>(index)];
  }
  const MeasurementModel& m = plot.model;
  double value =
      profile_.association.clutter_density.value_or(sparse_clutter_density(m.position_components));
  value *= m.volume_element(plot.z);
  if (m.has_range_rate) value /= 2.0 * profile_.point.initiation.max_speed;
  return value;
}

void Preprocessing::finish() {
  if (!windowed_) return;
  boxed_.resize(plots_.size());
  for (std::size_t j = 0; j < plots_.size(); ++j) boxed_[j] = rejected_[j] || crowd_[j] ? 0 : 1;
  density_.remember(sensor_, plots_, rejected_, boxed_, counted_);
}

}  // namespace skytrack
