#pragma once
// Distance partitioning of one scan's plots: two plots share a partition when a chain of
// plots, each within `distance` of the next, joins them (single linkage, the distance
// partitioning of Granstroem, Lundquist & Orguner 2012, IEEE Trans. AES 48(4), section IV-A,
// with one threshold). Neighbours come from a k-d tree (PlotIndex) and the components from
// a union-find, so a scan of n plots costs O(n log n + pairs), not O(n^2).
// The pipeline's preprocessing may hand extended mode its own partitions (mean shift) in
// the same form: a list of plot-index groups.
#include <span>
#include <vector>

#include <Eigen/Core>

#include "skytrack/association/plot_index.hpp"

namespace skytrack::extended {

class DistancePartitioner {
 public:
  /// `groups` is overwritten: every plot in exactly one group, plot indices ascending in a
  /// group, groups ordered by their first plot (deterministic). Non-finite positions are
  /// left out of every group. Buffers are reused across scans.
  void partition(std::span<const Eigen::Vector2d> positions, double distance,
                 std::vector<std::vector<int>>& groups);

 private:
  int find(int i) noexcept;

  PlotIndex index_;
  std::vector<Eigen::Vector3d> points_;
  std::vector<int> parent_;
  std::vector<int> neighbours_;
  std::vector<int> group_of_root_;
};

}  // namespace skytrack::extended
