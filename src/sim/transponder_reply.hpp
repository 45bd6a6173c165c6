#pragma once
// What a secondary radar adds to a plot (CONTRACTS.md §1 transponder fields).
#include <Eigen/Core>

#include "skytrack/core/plot.hpp"
#include "skytrack/sim/scenario.hpp"

namespace skytrack::sim {

/// Writes the target's identities on its plot and, when the sensor reports flight levels and
/// the target its altitude, the altitude of `position` (geometry/altitude.hpp) as a flight
/// level rounded to the sensor's step. Clutter (target null) gets the flight level alone.
void stamp_reply(Plot& plot, const Eigen::Vector3d& position, const SensorSpec& sensor,
                 const TargetSpec* target);

}  // namespace skytrack::sim
