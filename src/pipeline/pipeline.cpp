#include "skytrack/pipeline/pipeline.hpp"

#include <algorithm>
#include <cmath>

#include "skytrack/core/transponder.hpp"
#include "skytrack/geometry/frames.hpp"

namespace skytrack {
namespace {

constexpr double kPi = 3.141592653589793;

bool finite(const std::optional<double>& v) {
  return !v || std::isfinite(*v);
}

/// Adds a later look's counts to a batch's report; the track counts are the later look's.
void add_look(ScanReport& total, const ScanReport& look) {
  total.plots += look.plots;
  total.plots_invalid += look.plots_invalid;
  total.plots_rejected_clutter += look.plots_rejected_clutter;
  total.tentative = look.tentative;
  total.confirmed = look.confirmed;
  total.coasting = look.coasting;
  total.initiated += look.initiated;
  total.deleted += look.deleted;
  total.clusters += look.clusters;
  total.largest_cluster = std::max(total.largest_cluster, look.largest_cluster);
  total.approximated_clusters += look.approximated_clusters;
  total.numeric_failures += look.numeric_failures;
  total.branches = look.branches;
  total.branches_created += look.branches_created;
  total.branches_promoted += look.branches_promoted;
  total.branches_pruned += look.branches_pruned;
  total.predict += look.predict;
  total.associate += look.associate;
  total.manage += look.manage;
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
  for (const Plot& plot : first.plots) {
    if (plot.elevation || plot.z) return 3;
  }
  return 2;
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

void Pipeline::track_rotating(const PlotScan& batch, SensorState& sensor) {
  const AntennaSweep& antenna = sensor.antenna;
  // How far the beam is known to have swept: to the latest plot, to the batch's time when
  // that is later (a batch stamped when its sweep ended), to the end of its coverage.
  double reached = antenna.latest();
  double time = batch.time;
  for (const Plot& plot : batch.plots) time = std::max(time, plot_time(plot, batch));
  reached = std::max(reached, antenna.sweep_at(batch.time));
  if (batch.coverage) {
    const double end = antenna.sense() > 0 ? batch.coverage->to : batch.coverage->from;
    reached = std::max(reached, antenna.sweep_of(end, antenna.sweep_at(batch.time) - kPi));
  }
  sensor.looks.add(batch, sweeps_, reached);
  TrackFrame& frame = result_.frame;
  ScanReport& report = result_.report;
  bool looked = false;
  for (;;) {
    // Each search region as the beam sees it, from the tracks as they are now.
    tracker_->search_regions(batch, time, regions_);
    spans_.clear();
    for (const SearchRegion& region : regions_) {
      const PolarPoint polar = enu_to_polar(region.centre, batch.platform);
      const double half =
          region.radius < polar.range ? std::asin(region.radius / polar.range) : kPi;
      spans_.push_back({polar.azimuth, half});
    }
    if (!sensor.looks.take(spans_, antenna, look_)) break;
    const LookSources sources = look_.sources();
    if (!looked) {
      tracker_->process(look_.scan, frame, report, &sources);
      looked = true;
      continue;
    }
    // A batch that completes several looks gives one frame: every look's decisions, the
    // tracks after the last, and the tracks deleted on the way.
    ScanReport next;
    tracker_->process(look_.scan, look_frame_, next, &sources);
    for (TrackReport& track : frame.tracks) {
      if (track.status == TrackStatus::kDeleted) look_frame_.tracks.push_back(std::move(track));
    }
    frame.tracks.swap(look_frame_.tracks);
    frame.associations.insert(frame.associations.end(), look_frame_.associations.begin(),
                              look_frame_.associations.end());
    frame.events.insert(frame.events.end(), look_frame_.events.begin(), look_frame_.events.end());
    add_look(report, next);
  }
  if (!looked) tracker_->report_only(batch, frame, report);
  // The frame belongs to the batch that arrived.
  frame.scan = batch.scan;
  frame.time = batch.time;
}

const ScanResult& Pipeline::process(const PlotScan& scan) {
  result_.accepted = false;
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
  auto sensor =
      sensors_.try_emplace(scan.sensor, SensorState{0, 0.0, AntennaSweep(profile_.antenna), {}})
          .first;
  sensor->second.scan = scan.scan;
  sensor->second.time = scan.time;
  const PlotScan& usable = without_invalid_plots(scan);
  if (!tracker_)
    tracker_.emplace(*PointTracker::create(profile_, tracker_dimension(profile_, usable)));
  if (sensor->second.antenna.assign(usable, sweeps_)) {
    track_rotating(usable, sensor->second);
  } else {
    tracker_->process(usable, result_.frame, result_.report);
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
