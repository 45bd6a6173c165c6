#pragma once
// SVG picture of one experiment-1 run: truth centroid tracks against the LBP-PHD group
// estimates, one colour and marker label per group number.
#include <string>

#include "run_record.hpp"
#include "scenario.hpp"

namespace group_mc {

/// Writes the picture; returns false when the file cannot be written.
bool write_svg(const std::string& path, const Scenario& scenario, const RunRecord& run);

}  // namespace group_mc
