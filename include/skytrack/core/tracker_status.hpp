#pragma once
// Periodic health of one tracker instance. Mirrors the DDS type skytrack::dds::TrackerStatus
// (idl/skytrack.idl) field for field, so the pipeline can fill it without including DDS.
#include <cstdint>
#include <string>
#include <vector>

namespace skytrack {

/// How many plots or scans were rejected for one reason (e.g. "non_finite_range").
struct RejectionCount {
  std::string reason;
  std::uint64_t count = 0;

  bool operator==(const RejectionCount&) const = default;
};

struct TrackerStatusReport {
  std::string instance;  // tracker instance name; the DDS key
  std::string profile_name;
  std::string profile_version;
  double uptime = 0.0;  // [s]
  std::uint64_t scans_processed = 0;
  std::uint64_t plots_processed = 0;
  std::vector<RejectionCount> plots_rejected;
  std::vector<RejectionCount> scans_rejected;
  std::uint64_t scans_dropped = 0;  // dropped by the overload policy
  std::uint32_t queue_depth = 0;    // scans waiting to be processed
  double latency_p50 = 0.0;         // [s] per-scan processing latency
  double latency_p99 = 0.0;         // [s]
  double latency_max = 0.0;         // [s]
  std::uint32_t tracks_tentative = 0;
  std::uint32_t tracks_confirmed = 0;
  std::uint32_t tracks_coasting = 0;
  std::uint64_t numeric_failures = 0;  // ScanReport::numeric_failures, summed

  bool operator==(const TrackerStatusReport&) const = default;
};

}  // namespace skytrack
