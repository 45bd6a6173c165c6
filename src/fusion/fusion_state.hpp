#pragma once
// The private state of TrackFusion (not installed): sensors and their queued frames, local
// track records, system tracks, the cycle clock.
#include <cstdint>
#include <deque>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "cycle_associator.hpp"
#include "fusion_types.hpp"
#include "skytrack/fusion/track_fusion.hpp"

namespace skytrack::fusion {

namespace detail {

struct LocalInput {
  std::int64_t id = 0;
  StateEstimate state;
};

struct SensorFrame {
  double time = 0.0;
  std::vector<LocalInput> tracks;
};

struct SensorState {
  std::deque<SensorFrame> frames;  // time order; the oldest may serve the next cycle
  double last_time = -std::numeric_limits<double>::infinity();
  bool live = true;
};

struct SystemTrack {
  StateEstimate state;
  double state_time = 0.0;
  double last_fed = 0.0;  // [s] the last cycle it had sources
  TrackStatus status = TrackStatus::kConfirmed;
  std::vector<TrackSource> sources;       // this cycle's
  std::vector<TrackSource> last_sources;  // the last cycle's
  bool fresh = false;                     // started this cycle
};

using TrackKey = std::pair<std::uint32_t, std::int64_t>;  // (sensor, local track number)

}  // namespace detail

struct TrackFusion::State {
  explicit State(FusionSpec s);

  FusionSpec spec;
  FusionCounters counters;
  detail::CycleAssociator associator;
  std::uint64_t window_cycles = 1;

  std::map<std::uint32_t, detail::SensorState> sensors;
  std::map<detail::TrackKey, detail::LocalRecord> records;
  std::map<std::int64_t, detail::SystemTrack> systems;
  std::int64_t next_id = 1;

  bool started = false;
  double grid_origin = 0.0;      // [s] time of cycle index 0
  std::uint64_t next_cycle = 0;  // index of the next cycle to fuse
  bool fused_any = false;
  double last_fused = 0.0;  // [s] time of the last fused cycle
  double data_time = -std::numeric_limits<double>::infinity();

  // Workspaces reused every cycle.
  std::vector<detail::PresentTrack> present;
  std::vector<std::int64_t> system_of;
  std::vector<StateEstimate> fuse_inputs;
  std::vector<int> associator_order;
  std::vector<std::int64_t> fed_ids;
  std::vector<std::pair<std::int64_t, std::int64_t>> merges;  // (newer, older) system numbers

  double cycle_time(std::uint64_t index) const {
    return grid_origin + static_cast<double>(index) * spec.cycle;
  }
  /// Fuses the cycle `next_cycle` and advances the clock.
  TrackFrame fuse_cycle();
  /// Fuses every cycle that is due: all live sensors past it, or with `flushing` every
  /// cycle up to the latest data time.
  std::vector<TrackFrame> run_due_cycles(bool flushing);
  void keep_older_numbers(std::uint64_t k);
};

}  // namespace skytrack::fusion
