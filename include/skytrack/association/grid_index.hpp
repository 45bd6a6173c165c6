#pragma once
// Uniform grid over plot positions for radius queries of a known scale: the cells are
// squares in (x, y) of the side the caller expects its queries to reach, so a query looks
// at the few cells around its centre and tests only the plots in them. The initiator's
// searches have such a scale (a speed disc, a chain's gate), and so do a look's gates and
// plot-cloud tests (a few plot sigmas); they make many queries per batch. A grid is built
// in one counting pass and answers them with a few distance tests, where a k-d tree
// (PlotIndex) walks its levels. A query wider than a cell reads a few more rows. Height,
// when used, is tested per plot, not binned. Answers are exactly PlotIndex's (same
// arithmetic, sorted ascending).
//
// Memory: the buffers grow to the largest build and are reused; within() allocates only
// if `out` has to grow.
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

namespace skytrack {

class GridIndex {
 public:
  /// Index `positions` [m] in cells of side `cell` [m] (made coarser when the plots' extent
  /// would need more than a few cells per plot). dims = 2 uses (x, y) and ignores z; any
  /// other value uses (x, y, z). The positions are copied.
  void build(std::span<const Eigen::Vector3d> positions, int dims, double cell) noexcept;

  /// Indices of the plots at Euclidean distance <= radius [m] from centre (first `dims`
  /// coordinates), sorted ascending. `out` is cleared first. A negative or non-finite
  /// radius, or a non-finite centre, gives no plots.
  void within(const Eigen::Vector3d& centre, double radius, std::vector<int>& out) const noexcept;

  /// Whether more than `count` plots lie within `radius` of `centre` (as within(); stops
  /// counting there).
  bool more_than(const Eigen::Vector3d& centre, double radius, int count) const noexcept;

 private:
  struct Entry {
    Eigen::Vector3d position;
    int index = 0;
  };
  struct Rows {  // the cells a query looks at: columns [x0, x1] of rows [y0, y1]
    long x0 = 0, x1 = -1, y0 = 0, y1 = -1;
  };
  long cell_of(double value, double low) const noexcept;
  Rows rows_around(const Eigen::Vector3d& centre, double radius) const noexcept;
  double distance2(const Eigen::Vector3d& centre, const Entry& e) const noexcept;
  /// Calls visit(index) for each plot within `radius` of `centre`, in cell order, until it
  /// returns true; returns whether it did.
  template <class Visit>
  bool visit_within(const Eigen::Vector3d& centre, double radius,
                    const Visit& visit) const noexcept;

  std::vector<Entry> points_;         // in cell order
  std::vector<std::uint32_t> start_;  // points_[start_[c], start_[c + 1]) lie in cell c
  std::vector<std::uint32_t> cell_;   // build workspaces: each input plot's cell,
  std::vector<std::uint32_t> fill_;   // and each cell's next free slot
  double x0_ = 0.0, y0_ = 0.0, side_ = 1.0;
  long nx_ = 0, ny_ = 0;
  int dims_ = 3;
};

}  // namespace skytrack
