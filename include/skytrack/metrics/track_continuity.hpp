#pragma once
// Track continuity per truth object, the usual track-maintenance measures (Blackman &
// Popoli 1999, Design and Analysis of Modern Tracking Systems, performance evaluation): over the
// frames in which a truth is present, which reported track (if any) was matched to it.
//   id change     - the matched track id differs from the previously matched id; frames
//                   without a match in between are ignored.
//   fragmentation - tracked -> untracked -> tracked again (one per re-acquisition).
// Frames in which the truth is absent from the truth set count neither way.
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace skytrack::metrics {

struct TruthContinuity {
  std::int64_t truth_id = 0;
  int frames_present = 0;  // frames in which the truth was present
  int frames_tracked = 0;  // ... and matched to a track
  int id_changes = 0;
  int fragmentations = 0;
  int distinct_tracks = 0;                 // number of different track ids matched over time
  std::vector<std::int64_t> tracks;        // those ids, in the order first matched
  std::optional<std::int64_t> last_track;  // last matched track id
  bool tracked_now = false;                // matched in its latest frame
};

class TrackContinuity {
 public:
  /// Records one frame of one truth: the track matched to it, or nullopt.
  void observe(std::int64_t truth_id, std::optional<std::int64_t> track_id);

  /// Per truth, ordered by truth id.
  std::vector<TruthContinuity> per_truth() const;
  int id_changes() const { return id_changes_; }
  int fragmentations() const { return fragmentations_; }

 private:
  struct State {
    TruthContinuity record;
    std::vector<std::int64_t> seen_tracks;  // small: usually one or two ids
  };
  std::map<std::int64_t, State> states_;
  int id_changes_ = 0;
  int fragmentations_ = 0;
};

}  // namespace skytrack::metrics
