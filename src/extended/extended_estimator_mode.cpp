#include "skytrack/extended/extended_estimator_mode.hpp"

#include <string>

namespace skytrack::extended {

Expected<ExtendedMode> ExtendedMode::create(const config::TrackingProfile& profile) {
  const ExtendedSpec& spec = profile.extended;
  if (spec.confirm_hits < 1 || spec.delete_misses < 1 || spec.tentative_max_misses < 1 ||
      spec.min_partition_plots < 1) {
    return make_error("profile '" + profile.identity.name +
                      "', mode extended: confirm_hits, delete_misses, tentative_max_misses and "
                      "min_partition_plots must be at least 1");
  }
  const ExistenceSpec& e = spec.existence;
  auto open_unit = [](double p) { return p > 0.0 && p < 1.0; };
  if (e.enabled &&
      (!(e.detection_probability > 0.0 && e.detection_probability <= 1.0) ||
       !(e.survival > 0.0 && e.survival <= 1.0) || !open_unit(e.birth) ||
       !open_unit(e.delete_below) || !(e.expected_plots > 0.0) || !(e.clutter_density > 0.0))) {
    return make_error("profile '" + profile.identity.name +
                      "', mode extended: existence needs detection_probability and survival in "
                      "(0, 1], birth and delete_below in (0, 1), expected_plots and "
                      "clutter_density above 0");
  }
  return ExtendedMode(spec);
}

ExtendedMode::Watch& ExtendedMode::watch_of(std::uint32_t sensor) {
  auto it = watches_.find(sensor);
  if (it == watches_.end()) it = watches_.emplace(sensor, Watch{ExtendedTracker(spec_), {}}).first;
  return it->second;
}

void ExtendedMode::report(Watch& watch, TrackFrame& frame, ScanReport& report) const {
  for (const ExtendedTrack& t : watch.tracker.tracks()) {
    TrackReport track;
    const auto number = watch.numbers.find(t.id);
    const bool confirmed = t.status == ExtendedTrackStatus::kConfirmed;
    track.id = number != watch.numbers.end() ? number->second
                                             : kProvisionalNumber + static_cast<std::int64_t>(t.id);
    track.status = !confirmed      ? TrackStatus::kTentative
                   : t.misses == 0 ? TrackStatus::kConfirmed
                                   : TrackStatus::kCoasting;
    track.kind = ObjectKind::kExtended;
    track.dims = 2;
    track.position = {t.position().x(), t.position().y(), 0.0};
    track.velocity = {t.velocity().x(), t.velocity().y(), 0.0};
    track.extent = t.extent();
    if (track.status == TrackStatus::kTentative) ++report.tentative;
    if (track.status == TrackStatus::kConfirmed) ++report.confirmed;
    if (track.status == TrackStatus::kCoasting) ++report.coasting;
    frame.tracks.push_back(std::move(track));
  }
}

void ExtendedMode::process(const PlotScan& look, Preprocessing& pre, TrackFrame& frame,
                           ScanReport& report) {
  begin_frame(look, frame);
  Watch& watch = watch_of(look.sensor);
  const ExtendedScanReport scan = watch.tracker.process(look.time, pre.plots());
  report.plots_invalid += scan.rejected_plots;
  report.numeric_failures += scan.numeric_failures;
  // Numbers in the order the tracker lists its tracks (by its own id): deterministic.
  for (const ExtendedTrack& t : watch.tracker.tracks()) {
    if (t.status != ExtendedTrackStatus::kConfirmed || watch.numbers.contains(t.id)) continue;
    const std::int64_t number = next_number_++;
    watch.numbers.emplace(t.id, number);
    frame.events.push_back(
        {TrackEventType::kConfirmed, number, std::to_string(t.hits) + " scans with plots", {}});
    ++report.initiated;
  }
  for (const std::uint64_t id : watch.tracker.deleted()) {
    const auto it = watch.numbers.find(id);
    if (it == watch.numbers.end()) continue;  // tentative: never reported as a track
    TrackReport gone;
    gone.id = it->second;
    gone.status = TrackStatus::kDeleted;
    gone.kind = ObjectKind::kExtended;
    frame.tracks.push_back(gone);
    frame.events.push_back({TrackEventType::kDeleted, it->second, "missed", {}});
    ++report.deleted;
    watch.numbers.erase(it);
  }
  this->report(watch, frame, report);
}

void ExtendedMode::report_only(const PlotScan& batch, TrackFrame& frame, ScanReport& report) {
  begin_frame(batch, frame);
  report.plots = static_cast<int>(batch.plots.size());
  const auto it = watches_.find(batch.sensor);
  if (it != watches_.end()) this->report(it->second, frame, report);
}

}  // namespace skytrack::extended
