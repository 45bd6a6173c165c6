// Paper 000 §3.1 steps 2-3: mean-shift cells (eq. 9-10, run by ClutterRejector) as lists of
// plot indices, each with its interval hull (eq. 11).
#include "skytrack/clutter/mean_shift_partition.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace skytrack::clutter {

MeasurementBox interval_hull(std::span<const Eigen::Vector3d> positions,
                             std::span<const int> indices, int dims) noexcept {
  const int d = dims >= 3 ? 3 : 2;
  const double inf = std::numeric_limits<double>::infinity();
  MeasurementBox box{Eigen::Vector3d::Constant(inf), Eigen::Vector3d::Constant(-inf)};
  bool any = false;
  for (const int i : indices) {
    if (i < 0 || static_cast<std::size_t>(i) >= positions.size()) {
      continue;
    }
    const Eigen::Vector3d& p = positions[static_cast<std::size_t>(i)];
    if (!p.head(d).allFinite()) {
      continue;
    }
    any = true;
    box.lower.head(d) = box.lower.head(d).cwiseMin(p.head(d));
    box.upper.head(d) = box.upper.head(d).cwiseMax(p.head(d));
  }
  if (!any) {
    return MeasurementBox{};
  }
  if (d == 2) {
    box.lower.z() = 0.0;
    box.upper.z() = 0.0;
  }
  return box;
}

void partitions_from_cells(const ClutterRejectionResult& result,
                           std::vector<PlotPartition>& out) noexcept {
  const auto cells = static_cast<std::size_t>(std::max(result.cells, 0));
  // Reuse the inner vectors' capacity: shrink or grow the outer one, clear the rest.
  if (out.size() > cells) {
    out.resize(cells);
  }
  for (auto& p : out) {
    p.plots.clear();
  }
  out.resize(cells);
  for (std::size_t i = 0; i < result.cell.size(); ++i) {
    const int c = result.cell[i];
    if (c >= 0 && static_cast<std::size_t>(c) < cells) {
      out[static_cast<std::size_t>(c)].plots.push_back(static_cast<int>(i));
    }
  }
  for (std::size_t c = 0; c < cells; ++c) {
    out[c].box = c < result.boxes.size() ? result.boxes[c] : MeasurementBox{};
  }
}

MeanShiftPartitioner::MeanShiftPartitioner(const config::ClutterRejectionSpec& spec)
    : rejector_(spec) {}

const std::vector<PlotPartition>& MeanShiftPartitioner::partition(
    std::span<const Eigen::Vector3d> positions, int dims) noexcept {
  const ClutterRejectionResult& r = rejector_.apply(positions, dims >= 3 ? 3 : 2, {});
  partitions_from_cells(r, partitions_);
  return partitions_;
}

}  // namespace skytrack::clutter
