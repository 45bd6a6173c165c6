#pragma once
// The fusion role (paper 004): local trackers' track frames, keyed by sensor, associated
// track to track with the adaptive sliding-window mean OSPA and fused into one picture of
// system tracks with stable numbers. The offline tool (`skytrack fuse`) and skytrackd in the
// fusion role run this same object.
#include <cstdint>
#include <memory>
#include <vector>

#include "skytrack/core/track_report.hpp"
#include "skytrack/fusion/fusion_spec.hpp"

namespace skytrack::fusion {

struct FusionCounters {
  std::uint64_t frames = 0;           // local frames accepted
  std::uint64_t frames_late = 0;      // older than the last fused cycle or the sensor's last frame
                                      // (a new or returning sensor's is kept: it joins)
  std::uint64_t frames_invalid = 0;   // non-finite time: ignored
  std::uint64_t frames_dropped = 0;   // queued beyond max_queued_frames for a slow sensor
  std::uint64_t tracks_invalid = 0;   // local tracks with non-finite or non-PD state: ignored
  std::uint64_t cycles = 0;           // fused frames produced
  std::uint64_t cycles_skipped = 0;   // empty cycles jumped over after a gap in data time
  std::uint64_t sensors_dropped = 0;  // sensors silent for longer than sensor_timeout
  std::uint64_t system_tracks = 0;    // system tracks started
  std::uint64_t pairs_scored = 0;     // track pairs scored by MOSPA (after the spatial gate)
};

class TrackFusion {
 public:
  explicit TrackFusion(FusionSpec spec);
  ~TrackFusion();
  TrackFusion(TrackFusion&&) noexcept;
  TrackFusion& operator=(TrackFusion&&) noexcept;

  /// One local tracker's frame (its `sensor` is the key). Returns the fused frames it
  /// completes, in time order: the cycle at time B is fused once every live sensor has
  /// reported a frame at or after B; each local track is predicted to B from its sensor's
  /// latest frame at or before B. Never throws on bad input (counted and ignored).
  std::vector<TrackFrame> add(const TrackFrame& local);
  /// End of input: fuses the cycles still open.
  std::vector<TrackFrame> flush();

  const FusionSpec& spec() const;
  const FusionCounters& counters() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace skytrack::fusion
