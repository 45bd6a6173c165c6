#pragma once
// A clutter map: the false-plot density around each plot of one batch, counted in cells of
// measurement space (range x azimuth for polar plots, x x y for Cartesian ones). A batch-wide
// density treats a clutter area (sea, towns, a look-down patch) like the empty sky around it,
// so false plots inside it look like targets: they confirm false tracks and pull real tracks
// off course. Counting the plots in the 3 x 3 block of cells around a plot gives the density
// where it is.
#include <cstdint>
#include <span>
#include <vector>

#include "skytrack/measurement/plot_measurement.hpp"

namespace skytrack::clutter {

struct ClutterMapCells {
  double range = 5000.0;      // [m] polar plots
  double azimuth = 0.05;      // [rad] polar plots
  double cartesian = 5000.0;  // [m] x and y of Cartesian plots
};

/// Per plot j: the density in j's measurement space of the plots with `counted` set, of j's
/// measurement kind and size, in the 3 x 3 cells around j (j itself not counted): their count
/// over the block's area times the width they span in the remaining components (elevation,
/// range-rate, height). `density[j]` is raised to it, never lowered, so a sparse block keeps
/// the batch-wide value. Cost: two passes over the plots through an open-addressing table.
void raise_to_local_density(std::span<const PlotMeasurement> plots,
                            std::span<const std::uint8_t> counted, const ClutterMapCells& cells,
                            std::vector<double>& density);

}  // namespace skytrack::clutter
