#include "skytrack/group/group_estimator.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace skytrack::group {

Expected<GroupEstimator> GroupEstimator::create(const config::TrackingProfile& profile) {
  try {
    check_group_spec(profile.group);
  } catch (const std::invalid_argument& e) {
    return make_error("profile '" + profile.identity.name + "', mode group: " + e.what());
  }
  return GroupEstimator(profile.group);
}

GroupEstimator::Watch& GroupEstimator::watch_of(std::uint32_t sensor) {
  auto it = watches_.find(sensor);
  if (it == watches_.end()) {
    // Each sensor's filter draws from its own stream, so adding a sensor changes no other's.
    GroupSpec spec = spec_;
    spec.seed += sensor;
    it = watches_.emplace(sensor, Watch{GroupTracker(spec), {}}).first;
  }
  return it->second;
}

void GroupEstimator::report(Watch& watch, const std::vector<GroupEstimate>& estimates,
                            TrackFrame& frame, ScanReport& report, bool decided) {
  seen_.clear();
  for (const GroupEstimate& e : estimates) {
    auto [it, born] = watch.numbers.try_emplace(e.label, 0);
    if (born) {
      it->second = next_number_++;
      frame.events.push_back({TrackEventType::kConfirmed,
                              it->second,
                              "group of " + std::to_string(std::lround(e.members)) + " members",
                              {}});
      ++report.initiated;
    }
    seen_.push_back(e.label);
    TrackReport track;
    track.id = it->second;
    track.status = e.missed_scans == 0 ? TrackStatus::kConfirmed : TrackStatus::kCoasting;
    track.kind = ObjectKind::kGroup;
    track.dims = 2;
    track.position = {e.position.x(), e.position.y(), 0.0};
    track.velocity = {e.velocity.x(), e.velocity.y(), 0.0};
    track.extent = e.extent;
    track.members = static_cast<int>(std::lround(std::max(e.members, 1.0)));
    track.quality = std::min(e.weight, 1.0);
    ++(track.status == TrackStatus::kConfirmed ? report.confirmed : report.coasting);
    frame.tracks.push_back(std::move(track));
  }
  if (!decided) return;
  for (auto it = watch.numbers.begin(); it != watch.numbers.end();) {
    if (std::find(seen_.begin(), seen_.end(), it->first) != seen_.end()) {
      ++it;
      continue;
    }
    TrackReport gone;
    gone.id = it->second;
    gone.status = TrackStatus::kDeleted;
    gone.kind = ObjectKind::kGroup;
    frame.tracks.push_back(gone);
    frame.events.push_back({TrackEventType::kDeleted, it->second, "label died", {}});
    ++report.deleted;
    it = watch.numbers.erase(it);
  }
}

void GroupEstimator::process(const PlotScan& look, Preprocessing& pre, TrackFrame& frame,
                             ScanReport& report) {
  begin_frame(look, frame);
  Watch& watch = watch_of(look.sensor);
  // Nothing to protect: a group's plots are dense, clutter sparse (paper 000 §3.1).
  const clutter::ClutterRejectionResult& rejection = pre.reject_clutter({});
  clutter::partitions_from_cells(rejection, partitions_);
  readmit_plots(pre.positions(), rejection, spec_.readmit_distance, partitions_);
  make_cells(pre.positions(), partitions_, spec_.measurement_box_padding, cells_);
  int kept = 0;
  for (const clutter::PlotPartition& partition : partitions_) {
    kept += static_cast<int>(partition.plots.size());
  }
  report.plots_rejected_clutter = static_cast<int>(pre.plots().size()) - kept;
  this->report(watch, watch.tracker.process_cells(look.time, cells_), frame, report, true);
}

void GroupEstimator::report_only(const PlotScan& batch, TrackFrame& frame, ScanReport& report) {
  begin_frame(batch, frame);
  report.plots = static_cast<int>(batch.plots.size());
  const auto it = watches_.find(batch.sensor);
  if (it == watches_.end()) return;
  this->report(it->second, it->second.tracker.estimates(), frame, report, false);
}

}  // namespace skytrack::group
