// Track continuity: id changes and fragmentations per truth (see track_continuity.hpp).
#include "skytrack/metrics/track_continuity.hpp"

#include <algorithm>

namespace skytrack::metrics {

void TrackContinuity::observe(std::int64_t truth_id, std::optional<std::int64_t> track_id) {
  State& state = states_[truth_id];
  TruthContinuity& r = state.record;
  r.truth_id = truth_id;
  ++r.frames_present;
  if (!track_id) {
    r.tracked_now = false;
    return;
  }
  ++r.frames_tracked;
  if (r.last_track && *r.last_track != *track_id) {
    ++r.id_changes;
    ++id_changes_;
  }
  if (r.last_track && !r.tracked_now) {  // it had been tracked, then lost
    ++r.fragmentations;
    ++fragmentations_;
  }
  if (std::find(state.seen_tracks.begin(), state.seen_tracks.end(), *track_id) ==
      state.seen_tracks.end()) {
    state.seen_tracks.push_back(*track_id);
    ++r.distinct_tracks;
    r.tracks.push_back(*track_id);
  }
  r.last_track = track_id;
  r.tracked_now = true;
}

std::vector<TruthContinuity> TrackContinuity::per_truth() const {
  std::vector<TruthContinuity> out;
  out.reserve(states_.size());
  for (const auto& [id, state] : states_) out.push_back(state.record);
  return out;
}

}  // namespace skytrack::metrics
