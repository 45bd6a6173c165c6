#include "skytrack/pipeline/pipeline.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

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

/// The modes whose estimators track in the plane.
bool two_dimensional(config::TrackingMode mode) {
  return mode != config::TrackingMode::kPoint;
}

}  // namespace

std::optional<std::string> invalid_plot_reason(const Plot& plot,
                                               const config::InputLimitsSpec& limits,
                                               double batch_time) {
  if (!finite(plot.time) || !finite(plot.snr_db) || !finite(plot.amplitude)) {
    return "non-finite time or strength";
  }
  if (plot.time && std::abs(*plot.time - batch_time) > limits.max_time_jump) {
    return "plot time beyond max_time_jump of its batch's";
  }
  if (plot.flight_level && !plausible_flight_level(*plot.flight_level)) {
    return "flight level not finite or outside -15 to 1500";
  }
  const MeasurementSigma& s = plot.sigma;
  for (const auto* v : {&s.range, &s.azimuth, &s.elevation, &s.range_rate, &s.x, &s.y, &s.z}) {
    if (*v && !(std::isfinite(**v) && **v > 0.0)) return "sigma not positive and finite";
  }
  // The profile's own bounds on its default sigmas: below them a variance squares to zero.
  for (const auto* v : {&s.range, &s.range_rate, &s.x, &s.y, &s.z}) {
    if (*v && **v > limits.max_range) return "sigma beyond max_range";
    if (*v && **v < 1e-3) return "sigma below 1 mm (or 1 mm/s)";
  }
  for (const auto* v : {&s.azimuth, &s.elevation}) {
    if (*v && **v > std::numbers::pi) return "angle sigma beyond pi";
    if (*v && **v < 1e-6) return "angle sigma below 1 microradian";
  }
  if (plot.form == PlotForm::kPolar) {
    if (!std::isfinite(plot.range) || !std::isfinite(plot.azimuth) || !finite(plot.elevation) ||
        !finite(plot.range_rate)) {
      return "non-finite polar value";
    }
    if (plot.range < 0.0) return "negative range";
    if (plot.range > limits.max_range) return "range beyond max_range";
    if (std::abs(plot.azimuth) > 2.0 * std::numbers::pi) return "azimuth outside -2pi to 2pi";
    if (plot.elevation && std::abs(*plot.elevation) > std::numbers::pi / 2.0) {
      return "elevation outside -pi/2 to pi/2";
    }
    if (plot.range_rate && std::abs(*plot.range_rate) > limits.max_range) {
      return "range rate beyond max_range per second";
    }
  } else {
    if (!std::isfinite(plot.x) || !std::isfinite(plot.y) || !finite(plot.z)) {
      return "non-finite Cartesian value";
    }
    if (std::hypot(plot.x, plot.y, plot.z.value_or(0.0)) > limits.max_range) {
      return "range beyond max_range";
    }
  }
  return std::nullopt;
}

std::string timeline_change(const ScanResult& result) {
  if (!result.accepted || !(result.clock_restarted || result.tracks_restarted)) return {};
  std::string what = result.clock_restarted
                         ? "the sensor's clock restarted (three batches in a row that follow "
                           "each other, not its latest)"
                         : "the sensor's clock disagreed with the tracks' time";
  return what + (result.tracks_restarted
                     ? "; no other sensor is on the tracks' time (or none was heard over "
                       "max_time_jump of its clock): all tracks restart on its clock"
                     : "; its looks restart, on the other sensors' clock");
}

int tracker_dimension(const config::TrackingProfile& profile, const PlotScan& first) {
  if (two_dimensional(profile.mode)) return 2;
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
  // Build the stages of every dimension the first batch may choose now, so a bad model set
  // or mode fails at start, not at the first batch (which takes them).
  std::array<std::optional<EstimatorStages>, 2> built;
  for (const int dims : {2, 3}) {
    if (profile.dimension != 0 && profile.dimension != dims) continue;
    if (dims == 3 && two_dimensional(profile.mode)) continue;
    auto made = EstimatorStages::create(profile, dims);
    if (!made) return unexpected(made.error());
    built[dims - 2].emplace(std::move(*made));
  }
  return Pipeline(profile, std::move(built));
}

bool Pipeline::place_on_timeline(const PlotScan& scan, bool restarted, SensorFeed& feed) {
  using enum SensorTimeline::Placement;
  const auto placement =
      timeline_.place(scan.sensor, scan.time, restarted, profile_.input_limits.max_time_jump);
  if (placement == kHeld) return false;
  if (placement == kRejoins) feed = SensorFeed(profile_.antenna);
  if (placement == kNewTimeline) {
    // No track's time compares with this sensor's batches.
    result_.tracks_restarted = true;
    stages_.reset();
    for (auto& [id, state] : sensors_) state.feed = SensorFeed(profile_.antenna);
  }
  return true;
}

void Pipeline::set_input_limits(const config::InputLimitsSpec& limits) {
  profile_.input_limits = limits;
}

const PlotScan& Pipeline::without_invalid_plots(const PlotScan& scan) {
  const auto invalid = [&](const Plot& plot) {
    return invalid_plot_reason(plot, profile_.input_limits, scan.time).has_value();
  };
  if (std::none_of(scan.plots.begin(), scan.plots.end(), invalid)) return scan;
  // Copy the whole batch, so every field (present or added later) travels with the plots.
  clean_ = scan;
  std::erase_if(clean_.plots, invalid);
  return clean_;
}

// noexcept: the daemon's per-batch call. Everything it calls reports bad input and numeric
// trouble as values (rejections, NumericStatus, counters); what could throw has been
// checked: the tracker's ClutterRejector checks its spec when built, and create() built one
// from the same profile; BranchTree's map::at only looks up nodes its invariants keep;
// nanoflann throws only for queries on an unbuilt index, and PlotIndex and ClutterRejector
// build theirs first (empty ones too). What remains is std::bad_alloc from the strings,
// vectors and maps of a batch: it terminates, by design, as a daemon out of memory cannot
// go on with its tracks half updated.
const ScanResult& Pipeline::process(const PlotScan& scan) noexcept {
  result_.accepted = false;
  result_.refused = false;
  result_.rejection.clear();
  result_.report = ScanReport{};
  result_.reason = {};
  result_.clock_restarted = false;
  result_.tracks_restarted = false;
  const auto reject = [&](std::string_view reason,
                          const BatchClock* clock = nullptr) -> const ScanResult& {
    ++counters_.scans_rejected;
    result_.reason = reason;
    result_.rejection = "sensor " + std::to_string(scan.sensor) + " scan " +
                        std::to_string(scan.scan) + ": " + std::string(reason);
    if (clock != nullptr && clock->latest()) {
      result_.rejection += " (t = " + std::to_string(scan.time) + " s; latest accepted: scan " +
                           std::to_string(clock->latest()->scan) +
                           ", t = " + std::to_string(clock->latest()->time) + " s)";
    }
    return result_;
  };
  if (!std::isfinite(scan.time)) return reject(batch_reason::kNonFiniteTime);
  if (!scan.platform.position.allFinite() || !scan.platform.velocity.allFinite() ||
      !scan.platform.attitude.allFinite()) {
    return reject(batch_reason::kNonFinitePlatform);
  }
  SensorState& sensor =
      sensors_.try_emplace(scan.sensor, SensorState{BatchClock{}, SensorFeed(profile_.antenna)})
          .first->second;
  const BatchClock::Verdict verdict =
      sensor.clock.admit(scan.scan, scan.time, profile_.input_limits.max_time_jump);
  if (!verdict.refusal.empty()) return reject(verdict.refusal, &sensor.clock);
  if (verdict.restarted) {
    ++counters_.clock_restarts;
    result_.clock_restarted = true;
  }
  if (!place_on_timeline(scan, verdict.restarted, sensor.feed)) {
    reject(batch_reason::kClockDisagrees);
    result_.rejection += " (t = " + std::to_string(scan.time) +
                         " s; the tracks' time: " + std::to_string(*timeline_.time()) + " s)";
    return result_;
  }
  const PlotScan& usable = without_invalid_plots(scan);
  if (!stages_) {
    // The first batch with plots sets the dimension (an empty one says nothing of it).
    if (auto refusal = dimension_refusal(profile_, usable)) {
      ++counters_.scans_rejected;
      result_.rejection = std::move(*refusal);
      result_.reason = kProfileRefusal;
      result_.refused = true;
      return result_;
    }
    if (!usable.plots.empty()) {
      const int dims = tracker_dimension(profile_, usable);
      if (auto& ready = built_[dims - 2]) {
        stages_.emplace(std::move(*ready));
      } else {
        stages_.emplace(*EstimatorStages::create(profile_, dims));
      }
      for (auto& unused : built_) unused.reset();
    }
  }
  if (stages_) {
    sensor.feed.feed(usable, *stages_, result_.frame, result_.report);
    timeline_.fed(scan.sensor, scan.time);
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
  counters_.numeric_failures += static_cast<std::uint64_t>(result_.report.numeric_failures);
  ++counters_.scans_processed;
  result_.accepted = true;
  return result_;
}

}  // namespace skytrack
