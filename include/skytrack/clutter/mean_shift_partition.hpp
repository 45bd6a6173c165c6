#pragma once
// Mean-shift partitions of one scan's plots and their measurement boxes, paper 000 §3.1
// steps 2-3: the kept plots (after the kernel-density clutter rejection of step 1, eq. 6-8)
// are grouped by mean-shift (eq. 9-10, converged points merged) and each partition is
// wrapped in its interval hull, the measurement box (eq. 11). The rejection and the
// mean-shift iteration themselves are ClutterRejector's (clutter_rejector.hpp); this file
// turns its per-plot cell labels into lists of plot indices with their boxes, which is
// what group tracking and the pipeline's preprocessing stage consume.
#include <span>
#include <vector>

#include <Eigen/Core>

#include "skytrack/clutter/clutter_rejector.hpp"
#include "skytrack/clutter/clutter_rejection_spec.hpp"

namespace skytrack::clutter {

/// One mean-shift cell: the input indices of its plots (ascending) and its interval hull.
struct PlotPartition {
  std::vector<int> plots;
  MeasurementBox box;  // eq. 11, [m]; z interval [0, 0] in 2-D
};

/// Interval hull (eq. 11) of positions[indices]: componentwise min and max of the first
/// `dims` coordinates (the others [0, 0]). An empty index list gives an all-zero box;
/// indices out of range and non-finite positions are skipped.
MeasurementBox interval_hull(std::span<const Eigen::Vector3d> positions,
                             std::span<const int> indices, int dims) noexcept;

/// Groups a ClutterRejectionResult's per-plot cells into partitions (cell order: by first
/// plot index, as ClutterRejector labels them). `out` is cleared and its capacity reused.
void partitions_from_cells(const ClutterRejectionResult& result,
                           std::vector<PlotPartition>& out) noexcept;

/// Per-scan clutter rejection + mean-shift partitioning + measurement boxes.
/// Construction checks the spec (may throw std::invalid_argument: startup only).
class MeanShiftPartitioner {
 public:
  explicit MeanShiftPartitioner(const config::ClutterRejectionSpec& spec);

  /// positions: the scan's plot positions in the tracking frame [m]; dims 2 or 3. The
  /// returned partitions stay valid until the next call. Plots rejected as clutter or with a
  /// non-finite coordinate are in no partition. noexcept; deterministic.
  const std::vector<PlotPartition>& partition(std::span<const Eigen::Vector3d> positions,
                                              int dims) noexcept;

  const std::vector<PlotPartition>& partitions() const noexcept { return partitions_; }
  /// Densities, threshold and per-plot keep flags of the last call.
  const ClutterRejectionResult& rejection() const noexcept { return rejector_.result(); }

 private:
  ClutterRejector rejector_;
  std::vector<PlotPartition> partitions_;
};

}  // namespace skytrack::clutter
