#pragma once
// Spatial index over a set of plot positions for radius queries: a k-d tree (Friedman,
// Bentley & Finkel 1977, "An algorithm for finding best matches in logarithmic expected
// time", ACM TOMS 3(3)) from nanoflann 1.4.3, hidden behind this interface so nanoflann
// stays a private dependency of skytrack_core.
//
// Use: the extended tracker's distance partitioner asks for every plot within its partition
// distance of each plot. A query visits O(log n + k) tree nodes for k plots near the ball,
// so its cost grows with the number of nearby plots, not with the number of plots in the
// scan. (The look's gating uses a grid, GridIndex, whose queries have one scale per look.)
//
// Memory. build() copies the positions into a buffer and reuses the tree's index
// permutation, so after warm-up on the largest scan they do not allocate. nanoflann 1.4.3
// keeps its tree nodes in an internal pool that buildIndex() frees and refills in 8 KiB
// blocks (no reuse hook in that release): a few mallocs per build, the heap does not grow.
// within() allocates only if `out` has to grow.
#include <memory>
#include <span>
#include <vector>

#include <Eigen/Core>

namespace skytrack {

class PlotIndex {
 public:
  PlotIndex();
  ~PlotIndex();
  PlotIndex(PlotIndex&& other) noexcept;
  PlotIndex& operator=(PlotIndex&& other) noexcept;
  PlotIndex(const PlotIndex&) = delete;
  PlotIndex& operator=(const PlotIndex&) = delete;

  /// Index the plots of one scan [m]. dims = 2 uses (x, y) and ignores z; dims = 3 uses
  /// (x, y, z); any other value is treated as 3. The positions are copied.
  void build(std::span<const Eigen::Vector3d> positions, int dims) noexcept;

  /// Indices of the plots at Euclidean distance <= radius [m] from centre (first `dims`
  /// coordinates), sorted ascending. `out` is cleared first. A negative or non-finite
  /// radius, or a non-finite centre, gives no plots.
  void within(const Eigen::Vector3d& centre, double radius, std::vector<int>& out) const noexcept;

  int size() const noexcept;  // plots in the last build
  int dims() const noexcept;  // 2 or 3

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace skytrack
