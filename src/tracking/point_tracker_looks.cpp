// The point tracker's side of looks (core/look.hpp): where each track and candidate chain
// may still take a plot, which the pipeline keeps whole when it cuts a rotating antenna's
// plots into looks; and the numbers confirmed tracks are given.
#include <algorithm>
#include <cmath>
#include <string>

#include "point_tracker_support.hpp"
#include "skytrack/tracking/point_tracker.hpp"

namespace skytrack {

using tracking_detail::position_of;
using tracking_detail::position_spread;
using tracking_detail::velocity_of;

SearchRegion PointTracker::region_bound(int t, const PlotScan& header, double time,
                                        double threshold, double accel) const {
  // The combined estimate at its own time, kept until the track changes, extrapolated with a
  // bound on its growth rather than an IMM prediction (a feed of a few plots per batch asks
  // for regions thousands of times a revolution): position and velocity spread, and what a
  // turn or an acceleration of `accel` does meanwhile.
  const PointTrack& track = tracks_[static_cast<std::size_t>(t)];
  const int dims = layout_.dims;
  if (region_seeds_.size() < tracks_.size()) region_seeds_.resize(tracks_.size());
  RegionSeed& seed = region_seeds_[static_cast<std::size_t>(t)];
  if (seed.id != track.id || seed.time != track.estimate.time) {
    const Gaussian g = filter_.combine(track.estimate);
    Gaussian velocity = g;
    for (int a = 0; a < dims; ++a) {
      for (int b = 0; b < dims; ++b) {
        velocity.covariance(2 * a, 2 * b) = g.covariance(2 * a + 1, 2 * b + 1);
      }
    }
    seed = {track.id,
            track.estimate.time,
            position_of(g.mean, dims),
            velocity_of(g.mean, dims),
            position_spread(g, dims),
            position_spread(velocity, dims)};
  }
  const double dt = std::abs(time - seed.time);
  const Eigen::Vector3d centre = seed.position + seed.velocity * (time - seed.time);
  const double track_sigma = seed.spread + seed.velocity_spread * dt;
  const double plot_sigma = plot_spread_at(centre, header);
  const double manoeuvre = 0.5 * std::max(accel, max_turn_rate_ * seed.velocity.norm()) * dt * dt;
  return {centre,
          std::sqrt(threshold * (track_sigma * track_sigma + plot_sigma * plot_sigma)) + manoeuvre};
}

void PointTracker::search_regions(const PlotScan& header, double time,
                                  std::vector<SearchRegion>& out) const {
  out.clear();
  for (std::size_t t = 0; t < tracks_.size(); ++t) {
    if (tracks_[t].life.status == TrackStatus::kDeleted) continue;
    out.push_back(region_bound(static_cast<int>(t), header, time,
                               gate_threshold_[kMaxMeasurementDim], region_accel_));
  }
  initiator_.search_regions(time, out);
}

void PointTracker::number_confirmed(TrackFrame& frame) {
  std::vector<int> due;
  for (std::size_t t = 0; t < tracks_.size(); ++t) {
    const PointTrack& track = tracks_[t];
    if (track.id >= kProvisionalNumber && track.branch == BranchType::kFather &&
        is_reported_as_firm(track.life.status)) {
      due.push_back(static_cast<int>(t));
    }
  }
  if (due.empty()) return;
  const auto last_seen = [&](int t) {
    const PointTrack& track = tracks_[static_cast<std::size_t>(t)];
    return track.last_detected ? track.last_detected->time : track.estimate.time;
  };
  std::stable_sort(due.begin(), due.end(),
                   [&](int a, int b) { return last_seen(a) < last_seen(b); });
  for (const int t : due) {
    PointTrack& track = tracks_[static_cast<std::size_t>(t)];
    const std::int64_t provisional = track.id;
    track.id = next_number_++;
    if (branching()) {
      tree_.rename(provisional, track.id);
      slots_.erase(provisional);
      slots_[track.id] = t;
    }
    for (Association& a : frame.associations) {
      if (a.track == provisional) a.track = track.id;
    }
    const std::string old_name = "track " + std::to_string(provisional);
    const std::string new_name = "track " + std::to_string(track.id);
    for (TrackEvent& e : frame.events) {
      // This look's events name it by its number too ("son ... of track N").
      for (std::size_t at = e.detail.find(old_name); at != std::string::npos;
           at = e.detail.find(old_name, at + new_name.size())) {
        e.detail.replace(at, old_name.size(), new_name);
      }
      if (e.track != provisional) continue;
      e.track = track.id;
      if (e.type == TrackEventType::kConfirmed)
        e.detail = "tentative " + std::to_string(provisional);
    }
  }
}

}  // namespace skytrack
