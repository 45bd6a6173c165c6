#pragma once
// The daemon's counters, shared by the reception thread (drops, malformed samples), the
// tracker thread (processed and rejected scans, latency) and the status publisher. Every
// member function locks; snapshot() fills a TrackerStatusReport.
#include <chrono>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <string_view>

#include <dds/dds.h>

#include "skytrack/core/track_report.hpp"
#include "skytrack/core/tracker_status.hpp"
#include "skytrack/daemon/latency_stats.hpp"

namespace skytrack::daemon {

class StatusCollector {
 public:
  StatusCollector(std::string instance, std::size_t latency_window = 1024);

  void set_profile(const std::string& name, const std::string& version);
  void scan_rejected(std::string_view reason);
  void plots_rejected(std::string_view reason, std::uint64_t count);
  /// Returns the number of drops so far (for rate-limited logging).
  std::uint64_t scan_dropped();
  /// A scan went through the tracker: `plots` in it, `latency` [s] from reception to
  /// publication, the track picture it left and its numeric failures.
  void scan_processed(std::uint64_t plots, double latency, const TrackFrame& frame,
                      std::uint64_t numeric_failures = 0);

  TrackerStatusReport snapshot(std::uint32_t queue_depth) const;

 private:
  mutable std::mutex mutex_;
  const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  TrackerStatusReport report_;
  std::map<std::string, std::uint64_t, std::less<>> plots_rejected_;
  std::map<std::string, std::uint64_t, std::less<>> scans_rejected_;
  LatencyStats latency_;
};

/// Writes `report` as one TrackerStatus sample on `writer`; a failure is logged, not thrown.
void publish_status(dds_entity_t writer, const TrackerStatusReport& report);

}  // namespace skytrack::daemon
