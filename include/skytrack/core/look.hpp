#pragma once
// A look: the plots a tracker weighs together. Usually one batch as it arrived; for a
// rotating antenna the pipeline regroups the plots by the azimuth swept (pipeline/
// look_assembler.hpp), and plots held over from earlier batches keep the header (platform
// state, sigmas, scan number) of the batch they came in.
#include <cstdint>
#include <span>

#include <Eigen/Core>

#include "skytrack/core/plot.hpp"

namespace skytrack {

/// What a regrouped look adds to its PlotScan (whose header is the current batch's).
struct LookSources {
  std::span<const PlotScan> batches;  // headers (plots empty) of earlier batches
  std::span<const int> batch_of;      // per plot of the look: index into batches, -1: its own
  std::span<const double> sweep;      // per plot: the antenna's sweep when it was seen [rad]
  double sweep_to = 0.0;              // the sweep at the look's end [rad]
  bool whole = false;                 // a batch that swept a revolution by itself
};

/// Where a track or a candidate chain looks for its next plot: a sphere in the tracking
/// frame, at the time asked for.
struct SearchRegion {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // [m]
  double radius = 0.0;                               // [m]
};

}  // namespace skytrack
