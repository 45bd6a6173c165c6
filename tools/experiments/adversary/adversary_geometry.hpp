#pragma once
// Where the adversary's sensor stands and the sector it floods. The site lies east of
// everything the good sensor reported (at least 100 km, and at least the height of its area),
// the sector is due north of the site, so seen from the site the good sensor's area lies
// 45 degrees or more off the sector: the adversary's batches carry that sector as their
// coverage, and a look at it never touches the good sensor's tracks.
#include <vector>

#include <Eigen/Core>

#include "skytrack/core/plot.hpp"

namespace skytrack::adversary {

struct AdversaryGeometry {
  PlatformState site;            // attitude zero: body azimuth = azimuth from north
  AzimuthSector sector;          // the batches' coverage
  double cloud_range = 0.0;      // [m] the cloud's centre, due north of the site
  double cloud_elevation = 0.0;  // [rad]
  double range_min = 0.0;        // [m] spread batches cover [range_min, range_max] of the sector
  double range_max = 0.0;
  bool elevation = false;   // the good sensor's plots carry elevation ...
  bool range_rate = false;  // ... and range-rate: so do the adversary's
  MeasurementSigma sigma;   // the good sensor's first scan sigma, for the adversary's

  /// True when `position` lies in the flooded sector widened by `margin` [rad] on each side.
  bool contains(const Eigen::Vector3d& position, double margin) const;
  /// The sector's centre azimuth [rad].
  double centre_azimuth() const;
};

/// The margin [rad] by which the comparison widens the sector: tracks this close to it are
/// the adversary's.
inline constexpr double kSectorMargin = 0.1;

/// Places the adversary away from the good sensor's plots (their ENU positions).
AdversaryGeometry place_adversary(const std::vector<PlotScan>& good);

}  // namespace skytrack::adversary
