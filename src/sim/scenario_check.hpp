#pragma once
// What a scenario needs before it can be simulated (the loader checks the file; this checks
// the plain data, which tests and tools may build by hand).
#include "skytrack/core/expected.hpp"
#include "skytrack/sim/scenario.hpp"

namespace skytrack::sim {

Expected<void> check_scenario(const Scenario& scenario);

}  // namespace skytrack::sim
