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

double GridIndex::distance2(const Eigen::Vector3d& centre, const Entry& e) const noexcept {
  // The k-d tree's metric: squared differences summed in axis order.
  const double dx = centre.x() - e.position.x(), dy = centre.y() - e.position.y();
  double d2 = dx * dx;
  d2 += dy * dy;
  if (dims_ == 3) {
    const double dz = centre.z() - e.position.z();
    d2 += dz * dz;
  }
  return d2;
}

GridIndex::Rows GridIndex::rows_around(const Eigen::Vector3d& centre,
                                       double radius) const noexcept {
  if (points_.empty() || !(radius >= 0.0) || !std::isfinite(radius) || !centre.allFinite()) {
    return {};
  }
  // Clamped to [-1, n] before the floor, so a far query cannot overflow a long and the floor
  // is a truncation (std::floor is a library call on baseline x86-64).
  const auto clamped = [&](double value, double low, long n) {
    const double t = std::clamp((value - low) / side_, -1.0, static_cast<double>(n));
    const long i = static_cast<long>(t);
    return static_cast<double>(i) > t ? i - 1 : i;
  };
  return {std::max(0L, clamped(centre.x() - radius, x0_, nx_)),
          std::min(nx_ - 1, clamped(centre.x() + radius, x0_, nx_)),
          std::max(0L, clamped(centre.y() - radius, y0_, ny_)),
          std::min(ny_ - 1, clamped(centre.y() + radius, y0_, ny_))};
}

template <class Visit>
bool GridIndex::visit_within(const Eigen::Vector3d& centre, double radius,
                             const Visit& visit) const noexcept {
  const Rows r = rows_around(centre, radius);
  const double bound = radius * radius;
  for (long iy = r.y0; iy <= r.y1; ++iy) {
    const std::size_t row = static_cast<std::size_t>(iy * nx_);
    const std::uint32_t end = start_[row + static_cast<std::size_t>(r.x1) + 1];
    for (std::uint32_t k = start_[row + static_cast<std::size_t>(r.x0)]; k < end; ++k) {
      if (distance2(centre, points_[k]) <= bound && visit(points_[k].index)) return true;
    }
  }
  return false;
}

void GridIndex::within(const Eigen::Vector3d& centre, double radius,
                       std::vector<int>& out) const noexcept {
  out.clear();
  visit_within(centre, radius, [&](int index) {
    out.push_back(index);
    return false;
  });
  std::sort(out.begin(), out.end());
}

bool GridIndex::more_than(const Eigen::Vector3d& centre, double radius, int count) const noexcept {
  int found = 0;
  return visit_within(centre, radius, [&](int) { return ++found > count; });
}

}  // namespace skytrack
