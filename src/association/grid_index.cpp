#include "skytrack/association/grid_index.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace skytrack {
namespace {

// At most this many cells per plot: beyond, empty cells cost more than the plots they save.
constexpr double kCellsPerPlot = 4.0;

}  // namespace

long GridIndex::cell_of(double value, double low) const noexcept {
  return static_cast<long>(std::floor((value - low) / side_));
}

void GridIndex::build(std::span<const Eigen::Vector3d> positions, int dims, double cell) noexcept {
  dims_ = dims == 2 ? 2 : 3;
  points_.clear();
  start_.clear();
  nx_ = ny_ = 0;
  double x1 = -std::numeric_limits<double>::infinity(), y1 = x1;
  x0_ = y0_ = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& p : positions) {
    if (!p.allFinite()) continue;  // never within any radius
    x0_ = std::min(x0_, p.x());
    y0_ = std::min(y0_, p.y());
    x1 = std::max(x1, p.x());
    y1 = std::max(y1, p.y());
  }
  if (!(x1 >= x0_)) return;
  const double width = x1 - x0_, height = y1 - y0_;
  side_ = std::isfinite(cell) && cell > 0.0 ? cell : std::max({width, height, 1.0});
  const double most = kCellsPerPlot * static_cast<double>(positions.size()) + 1.0;
  if ((width / side_ + 1.0) * (height / side_ + 1.0) > most) {
    side_ = std::max(std::sqrt(width * height / most), std::max(width, height) / most);
  }
  nx_ = cell_of(x1, x0_) + 1;
  ny_ = cell_of(y1, y0_) + 1;
  start_.assign(static_cast<std::size_t>(nx_ * ny_) + 1, 0);
  cell_.assign(positions.size(), 0);
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Eigen::Vector3d& p = positions[i];
    if (!p.allFinite()) continue;
    cell_[i] = static_cast<std::uint32_t>(cell_of(p.y(), y0_) * nx_ + cell_of(p.x(), x0_));
    ++start_[cell_[i] + 1];
  }
  for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  points_.resize(start_.back());
  fill_.assign(start_.begin(), start_.end() - 1);
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (!positions[i].allFinite()) continue;
    points_[fill_[cell_[i]]++] = {positions[i], static_cast<int>(i)};
  }
}

void GridIndex::within(const Eigen::Vector3d& centre, double radius,
                       std::vector<int>& out) const noexcept {
  out.clear();
  if (points_.empty() || !(radius >= 0.0) || !std::isfinite(radius) || !centre.allFinite()) {
    return;
  }
  // Clamped to the grid in floating point first: a far query must not overflow a long.
  const auto clamped = [&](double value, double low, long n) {
    return static_cast<long>(
        std::clamp(std::floor((value - low) / side_), -1.0, static_cast<double>(n)));
  };
  const long ix0 = std::max(0L, clamped(centre.x() - radius, x0_, nx_));
  const long ix1 = std::min(nx_ - 1, clamped(centre.x() + radius, x0_, nx_));
  const long iy0 = std::max(0L, clamped(centre.y() - radius, y0_, ny_));
  const long iy1 = std::min(ny_ - 1, clamped(centre.y() + radius, y0_, ny_));
  const double bound = radius * radius;
  for (long iy = iy0; iy <= iy1; ++iy) {
    const std::size_t row = static_cast<std::size_t>(iy * nx_);
    for (std::uint32_t k = start_[row + static_cast<std::size_t>(ix0)];
         k < start_[row + static_cast<std::size_t>(ix1) + 1]; ++k) {
      const Entry& e = points_[k];
      // The k-d tree's metric: squared differences summed in axis order.
      double d2 = 0.0;
      for (int d = 0; d < dims_; ++d)
        d2 += (centre[d] - e.position[d]) * (centre[d] - e.position[d]);
      if (d2 <= bound) out.push_back(e.index);
    }
  }
  std::sort(out.begin(), out.end());
}

}  // namespace skytrack
