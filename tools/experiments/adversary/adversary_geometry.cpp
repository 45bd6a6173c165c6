#include "adversary_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "skytrack/geometry/angles.hpp"
#include "skytrack/geometry/frames.hpp"

namespace skytrack::adversary {
namespace {

constexpr double kHalfWidth = 0.1;       // [rad] of the flooded sector
constexpr double kMinOffset = 100000.0;  // [m] east of the good sensor's area
constexpr double kCloudRange = 60000.0;  // [m]
constexpr double kSpreadMin = 40000.0;   // [m]
constexpr double kSpreadMax = 80000.0;   // [m]

}  // namespace

double AdversaryGeometry::centre_azimuth() const {
  return wrap_angle(sector.from + 0.5 * wrap_angle_positive(sector.to - sector.from));
}

bool AdversaryGeometry::contains(const Eigen::Vector3d& position, double margin) const {
  const double azimuth = enu_to_polar(position, site).azimuth;
  const double half = 0.5 * wrap_angle_positive(sector.to - sector.from) + margin;
  return std::abs(wrap_angle(azimuth - centre_azimuth())) <= half;
}

AdversaryGeometry place_adversary(const std::vector<PlotScan>& good) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Eigen::Vector2d low(kInf, kInf), high(-kInf, -kInf);
  double height = 0.0;
  std::size_t platforms = 0;
  AdversaryGeometry g;
  for (const PlotScan& scan : good) {
    height += scan.platform.position.z();
    ++platforms;
    for (const Plot& plot : scan.plots) {
      const Eigen::Vector3d p = plot_position_enu(plot, scan.platform);
      if (!p.allFinite()) continue;
      low = low.cwiseMin(p.head<2>());
      high = high.cwiseMax(p.head<2>());
      g.elevation = g.elevation || plot.elevation.has_value();
      g.range_rate = g.range_rate || plot.range_rate.has_value();
    }
  }
  if (!std::isfinite(low.x())) low = high = Eigen::Vector2d::Zero();  // no plots at all
  const double offset = std::max(kMinOffset, high.y() - low.y());
  g.site.position = {high.x() + offset, 0.5 * (low.y() + high.y()),
                     platforms > 0 ? height / static_cast<double>(platforms) : 0.0};
  g.sector = {-kHalfWidth, kHalfWidth};
  g.cloud_range = kCloudRange;
  g.cloud_elevation = g.elevation ? 0.02 : 0.0;
  g.range_min = kSpreadMin;
  g.range_max = kSpreadMax;
  if (!good.empty()) g.sigma = good.front().sigma;
  return g;
}

}  // namespace skytrack::adversary
