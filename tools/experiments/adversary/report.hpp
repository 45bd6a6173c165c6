#pragma once
// The printed result: one block per phase (what sensor 2 sent, sensor 1's latency, the
// daemon's status counts and memory, sensor 1's frames unchanged), a summary table, and the
// comparison of sensor 1's tracks with the offline run, with its first differences.
#include <optional>
#include <vector>

#include "adversary_geometry.hpp"
#include "good_stream.hpp"
#include "live_run.hpp"
#include "options.hpp"
#include "phase_plan.hpp"

namespace skytrack::adversary {

struct ReportInputs {
  const Options& options;
  const GoodStream& good;
  const std::vector<Phase>& phases;
  const RunRecord& run;
  const std::vector<std::optional<TrackFrame>>& offline;  // per good batch
  const AdversaryGeometry& geometry;
};

/// Prints the report to stdout; returns the number of sensor-1 frames that changed.
std::size_t print_report(const ReportInputs& in);

}  // namespace skytrack::adversary
