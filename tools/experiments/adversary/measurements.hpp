#pragma once
// What is measured per phase: the good sensor's latency (its batch written -> the daemon's
// TrackBatch for it received), the daemon's memory from /proc/<pid>/status, and its
// TrackerStatus over the phase (counts at the phase's end minus those at its start).
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "dds_link.hpp"

namespace skytrack::adversary {

struct LatencySummary {
  std::size_t sent = 0;                    // good batches written
  std::size_t answered = 0;                // ... whose TrackBatch arrived
  double p50 = 0.0, p99 = 0.0, max = 0.0;  // [s] over the answered ones
};
/// Nearest-rank percentiles of `latencies` [s]; `sent` counts the unanswered too.
LatencySummary summarize_latency(std::vector<double> latencies, std::size_t sent);

struct MemorySample {
  double rss_mib = 0.0;  // VmRSS
  double hwm_mib = 0.0;  // VmHWM: the peak so far
};
/// The process's memory, or nullopt when it is gone (or `pid` is 0).
std::optional<MemorySample> read_memory(int pid);

struct StatusWindow {
  bool seen = false;  // a status arrived by the window's end
  std::map<std::string, std::uint64_t> scans_rejected, plots_rejected;  // by reason, in it
  std::uint64_t scans_processed = 0, plots_processed = 0, scans_dropped = 0;
  std::uint32_t queue_max = 0;  // deepest queue a status reported in it
  std::uint32_t confirmed = 0;  // confirmed tracks in the last status of the window
};
/// The daemon's status over [from, to): the last one received by `to` minus the last by `from`.
StatusWindow status_window(const std::vector<ReceivedStatus>& statuses, Clock::time_point from,
                           Clock::time_point to);

/// "{reason: n, ...}" or "none".
std::string format_counts(const std::map<std::string, std::uint64_t>& counts);

}  // namespace skytrack::adversary
