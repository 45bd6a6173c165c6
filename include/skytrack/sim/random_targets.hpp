#pragma once
// Draws a scenario's random target population (Scenario::random_targets).
#include <cstdint>
#include <vector>

#include "skytrack/core/expected.hpp"
#include "skytrack/sim/scenario.hpp"

namespace skytrack::sim {

/// The targets of `spec` over a run of `duration` seconds, from their own random stream
/// seeded by `seed` (the measurement noise of the run draws from another).
std::vector<TargetSpec> draw_random_targets(const RandomTargetsSpec& spec, int dimensions,
                                            double duration, std::uint64_t seed);

/// Appends the drawn population to the scenario's listed targets; an error when an id clashes.
Expected<void> add_random_targets(Scenario& scenario, std::uint64_t seed);

}  // namespace skytrack::sim
