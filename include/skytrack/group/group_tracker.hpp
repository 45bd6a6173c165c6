#pragma once
// Group mode of paper 000 end to end for one sensor's scans: plots -> kernel-density clutter
// rejection and mean-shift partitions with measurement boxes (§3.1) -> labeled box-particle
// PHD filter (§3.2). 2-D: plots are used by their (x, y) in the tracking frame.
#include <span>
#include <vector>

#include <Eigen/Core>

#include "skytrack/clutter/mean_shift_partition.hpp"
#include "skytrack/group/group_spec.hpp"
#include "skytrack/group/labeled_box_phd.hpp"
#include "skytrack/measurement/plot_measurement.hpp"

namespace skytrack::group {

/// Throws std::invalid_argument naming the first bad field (startup only).
void check_group_spec(const GroupSpec& spec);

/// The filter's view of the partitions: the padded interval hull (eq. 11 plus
/// `padding` [m] on each side), and the mean and covariance of the plots. `out` is reused.
void make_cells(std::span<const Eigen::Vector3d> positions,
                std::span<const clutter::PlotPartition> partitions, double padding,
                std::vector<GroupCell>& out) noexcept;

/// Adds each plot with keep == 0 (finite position) to the partition whose interval hull is
/// nearest, when that hull is within `distance` [m] (x, y); boxes grow to take it in.
void readmit_plots(std::span<const Eigen::Vector3d> positions,
                   const clutter::ClutterRejectionResult& rejection, double distance,
                   std::vector<clutter::PlotPartition>& partitions) noexcept;

class GroupTracker {
 public:
  /// Checks the spec (throws std::invalid_argument); allocates the workspaces.
  explicit GroupTracker(const GroupSpec& spec);

  /// One scan: each plot's approximate_position (x, y), then preprocessing and filter.
  const std::vector<GroupEstimate>& process(double time,
                                            std::span<const PlotMeasurement> plots) noexcept;
  /// One scan from plot positions in the tracking frame [m] (z ignored).
  const std::vector<GroupEstimate>& process(double time,
                                            std::span<const Eigen::Vector3d> positions) noexcept;
  /// One scan from ready cells (partitions already made and boxed): the filter only.
  const std::vector<GroupEstimate>& process_cells(double time,
                                                  std::span<const GroupCell> cells) noexcept;

  const std::vector<GroupEstimate>& estimates() const noexcept { return filter_.estimates(); }
  const LabeledBoxPhd& filter() const noexcept { return filter_; }
  /// The last scan's partitions (plot indices into that scan) and cells, in the same order.
  const std::vector<clutter::PlotPartition>& partitions() const noexcept { return partitions_; }
  const std::vector<GroupCell>& cells() const noexcept { return cells_; }
  const clutter::ClutterRejectionResult& rejection() const noexcept {
    return partitioner_.rejection();
  }

 private:
  GroupSpec spec_;
  clutter::MeanShiftPartitioner partitioner_;
  LabeledBoxPhd filter_;
  std::vector<Eigen::Vector3d> positions_;
  std::vector<GroupCell> cells_;
  std::vector<clutter::PlotPartition> partitions_;
};

}  // namespace skytrack::group
