#pragma once
// What the pipeline says of one batch beyond its frame: counters and stage timings, logged by
// the daemon and summed by the tools. The common part is every mode's; each estimator mode
// fills its own part (the others stay zero).
#include <chrono>

namespace skytrack {

/// The point tracker's part: JPDA clusters and branch tracking (paper 003).
struct PointScanReport {
  int clusters = 0, largest_cluster = 0, approximated_clusters = 0;
  // Live sons and grandsons after the batch, and this batch's decisions.
  int branches = 0;
  int branches_created = 0, branches_promoted = 0, branches_pruned = 0;
};

struct ScanReport {
  int plots = 0;
  int plots_invalid = 0;           // could not be turned into a measurement
  int plots_rejected_clutter = 0;  // removed by clutter rejection
  int plots_in_clouds = 0;         // left out of initiation: too many plots round them
  int tentative = 0, confirmed = 0, coasting = 0;
  int initiated = 0, deleted = 0;
  int initiations_refused = 0;  // chains that started no track: initiation.max_tentative held
  int chains_held = 0;  // completed chains too weak to outlive a miss, held for their next plot
  // Track updates in which a mode kept its prediction (an innovation covariance that would
  // not factorise), and associations that failed (JpdaStatus other than ok).
  int numeric_failures = 0;
  // Stage timings: preprocessing and gating (predictions), association with the update,
  // track management.
  std::chrono::microseconds predict{}, associate{}, manage{};

  PointScanReport point;

  /// Adds a later look of the same batch: counts add up, the track counts are the later
  /// look's.
  void add_later_look(const ScanReport& look);
};

}  // namespace skytrack
