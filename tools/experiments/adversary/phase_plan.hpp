#pragma once
// The run's timeline in stream time: a quiet warm-up (the good sensor's tracks confirm), one
// phase per adversarial load, each active for its first (phase - settle) seconds and quiet
// for the rest (the daemon catches up, its status reports the phase), and a quiet recovery.
#include <string>
#include <vector>

#include "options.hpp"

namespace skytrack::adversary {

enum class PhaseKind {
  kQuiet,        // the good sensor alone
  kCloud,        // a cloud of `size` co-located plots every period
  kBurst,        // `size` batches back to back, every period (at most --bursts)
  kHugeUnder,    // one batch of `size` plots, the daemon's max_plots_per_scan minus one
  kHugeOver,     // one batch of `size` plots, one over it
  kMalformed,    // a malformed sample after each good batch, each kind in turn
  kClockHijack,  // three batches dated 50 years ahead that follow each other
};

struct Phase {
  std::string name;  // short, for the summary table
  PhaseKind kind = PhaseKind::kQuiet;
  int size = 0;
  double begin = 0.0;       // [s] stream time
  double active_end = 0.0;  // [s] the adversary sends before this
  double end = 0.0;         // [s]
  std::string what;         // one line: what the adversary sends
};

/// The phases from `start` (the good stream's first batch time) on; `max_plots` is the daemon's
/// max_plots_per_scan.
std::vector<Phase> plan_phases(const Options& options, int max_plots, double start);

/// Stream seconds the plan needs from its start.
double planned_duration(const Options& options);

}  // namespace skytrack::adversary
