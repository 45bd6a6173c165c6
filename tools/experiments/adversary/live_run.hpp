#pragma once
// The live run: the good sensor's batches written at their pace (stream time / rate), the
// adversary acting after each, the daemon's memory sampled while waiting; then the last
// TrackBatches drained. Everything observed is recorded with its time for the report.
// Bounded: it stops early when the daemon is gone, its VmRSS passes --max-rss-mb, or the run
// passes --max-seconds.
#include <optional>
#include <string>
#include <vector>

#include "adversary_actions.hpp"
#include "dds_link.hpp"
#include "good_stream.hpp"
#include "measurements.hpp"
#include "phase_plan.hpp"

namespace skytrack::adversary {

struct PhaseRecord {
  Clock::time_point begin, end;   // wall clock: its first good batch written, the next phase's
  std::vector<std::size_t> good;  // indices of its good batches written
  PhaseTally tally;
  double rss_max_mib = 0.0;
  std::optional<MemorySample> last_memory;
};

struct RunRecord {
  std::vector<std::optional<Clock::time_point>> written;  // per good batch: when written
  std::size_t writes = 0;                                 // good batches written
  std::vector<PhaseRecord> phases;                        // those begun
  std::vector<ReceivedFrame> frames;                      // the good sensor's TrackBatches
  std::vector<ReceivedStatus> statuses;
  std::string stopped;  // why the run ended early; empty: it ran through
  double wall_seconds = 0.0;
};

RunRecord run_live(const Options& options, const GoodStream& good, const std::vector<Phase>& phases,
                   DdsLink& link, Adversary& adversary);

}  // namespace skytrack::adversary
