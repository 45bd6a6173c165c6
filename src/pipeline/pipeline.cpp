#include "skytrack/pipeline/pipeline.hpp"

#include <algorithm>
#include <cmath>

#include "skytrack/core/transponder.hpp"

namespace skytrack {
namespace {

bool finite(const std::optional<double>& v) {
  return !v || std::isfinite(*v);
}

/// True when a plot of the batch measures height: an elevation, a z, or a polar plot's
/// flight level.
bool carries_height(const PlotScan& batch) {
  return std::any_of(batch.plots.begin(), batch.plots.end(), [](const Plot& plot) {
    return plot.elevation || plot.z || (plot.form == PlotForm::kPolar && plot.flight_level);
  });
}

}  // namespace

std::optional<std::string> invalid_plot_reason(const Plot& plot) {
  if (!finite(plot.time) || !finite(plot.snr_db) || !finite(plot.amplitude)) {
    return "non-finite time or strength";
  }
  if (plot.flight_level && !plausible_flight_level(*plot.flight_level)) {
    return "flight level not finite or outside -15 to 1500";
  }
  const MeasurementSigma& s = plot.sigma;
  for (const auto* v : {&s.range, &s.azimuth, &s.elevation, &s.range_rate, &s.x, &s.y, &s.z}) {
    if (*v && !(std::isfinite(**v) && **v > 0.0)) return "sigma not positive and finite";
  }
  if (plot.form == PlotForm::kPolar) {
    if (!std::isfinite(plot.range) || !std::isfinite(plot.azimuth) || !finite(plot.elevation) ||
        !finite(plot.range_rate)) {
      return "non-finite polar value";
    }
    if (plot.range < 0.0) return "negative range";
  } else if (!std::isfinite(plot.x) || !std::isfinite(plot.y) || !finite(plot.z)) {
    return "non-finite Cartesian value";
  }
  return std::nullopt;
}

int tracker_dimension(const config::TrackingProfile& profile, const PlotScan& first) {
  if (profile.dimension == 2 || profile.dimension == 3) return profile.dimension;
  return carries_height(first) ? 3 : 2;
}

std::optional<std::string> dimension_refusal(const config::TrackingProfile& profile,
                                             const PlotScan& first) {
  if (profile.dimension != 3 || first.plots.empty() || carries_height(first)) return std::nullopt;
  return "profile '" + profile.identity.name + "' asks for 3-D tracking (dimension: 3), but " +
         "sensor " + std::to_string(first.sensor) + "'s plots carry no height (no elevation, " +
         "z or flight level): a 3-D track of them is useless; batch refused (use dimension: " +
         "auto or 2 for this sensor)";
}

Expected<Pipeline> Pipeline::create(const config::TrackingProfile& profile) {
  if (profile.mode != config::TrackingMode::kPoint) {
    return make_error("profile '" + profile.identity.name + "': mode '" +
                      std::string(config::to_string(profile.mode)) +
                      "' is not implemented yet (only point)");
  }
  // Build one tracker now so a bad model set fails at start, not at the first batch.
  if (auto probe = PointTracker::create(profile, 2); !probe) return unexpected(probe.error());
  return Pipeline(profile);
}

std::optional<std::string> Pipeline::check_order(const PlotScan& scan) const {
  if (!std::isfinite(scan.time)) return "non-finite batch time";
  const auto it = sensors_.find(scan.sensor);
  if (it == sensors_.end()) return std::nullopt;
  if (scan.scan == it->second.scan) return "duplicate scan " + std::to_string(scan.scan);
  if (scan.scan < it->second.scan) {
    return "scan " + std::to_string(scan.scan) + " after scan " + std::to_string(it->second.scan);
  }
  if (scan.time < it->second.time) return "time goes backwards";
  return std::nullopt;
}

const PlotScan& Pipeline::without_invalid_plots(const PlotScan& scan) {
  const auto invalid = [](const Plot& plot) { return invalid_plot_reason(plot).has_value(); };
  if (std::none_of(scan.plots.begin(), scan.plots.end(), invalid)) return scan;
  // Copy the whole batch, so every field (present or added later) travels with the plots.
  clean_ = scan;
  std::erase_if(clean_.plots, invalid);
  return clean_;
}

const ScanResult& Pipeline::process(const PlotScan& scan) {
  result_.accepted = false;
  result_.refused = false;
  result_.rejection.clear();
  result_.report = ScanReport{};
  if (auto reason = check_order(scan)) {
    ++counters_.scans_rejected;
    result_.rejection = "sensor " + std::to_string(scan.sensor) + ": " + *reason;
    return result_;
  }
  if (!scan.platform.position.allFinite() || !scan.platform.velocity.allFinite() ||
      !scan.platform.attitude.allFinite()) {
    ++counters_.scans_rejected;
    result_.rejection = "sensor " + std::to_string(scan.sensor) + ": non-finite platform state";
    return result_;
  }
  SensorState& sensor =
      sensors_.try_emplace(scan.sensor, SensorState{0, 0.0, SensorFeed(profile_.antenna)})
          .first->second;
  sensor.scan = scan.scan;
  sensor.time = scan.time;
  const PlotScan& usable = without_invalid_plots(scan);
  if (!tracker_) {
    // The first batch with plots sets the dimension (an empty one says nothing of it).
    if (auto refusal = dimension_refusal(profile_, usable)) {
      ++counters_.scans_rejected;
      result_.rejection = std::move(*refusal);
      result_.refused = true;
      return result_;
    }
    if (!usable.plots.empty()) {
      tracker_.emplace(*PointTracker::create(profile_, tracker_dimension(profile_, usable)));
    }
  }
  if (tracker_) {
    sensor.feed.feed(usable, *tracker_, result_.frame, result_.report);
  } else {
    result_.frame = TrackFrame{};
    result_.frame.sensor = usable.sensor;
    result_.frame.scan = usable.scan;
    result_.frame.time = usable.time;
  }
  result_.report.plots_invalid += static_cast<int>(scan.plots.size() - usable.plots.size());
  counters_.plots_processed += scan.plots.size();
  counters_.plots_invalid += static_cast<std::uint64_t>(result_.report.plots_invalid);
  counters_.plots_rejected_clutter +=
      static_cast<std::uint64_t>(result_.report.plots_rejected_clutter);
  ++counters_.scans_processed;
  result_.accepted = true;
  return result_;
}

}  // namespace skytrack
