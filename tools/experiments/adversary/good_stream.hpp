#pragma once
// The good sensor's batches: a scenario simulated with the project's simulator (as `skytrack
// simulate` does, optionally reported in sectors) or a recorded plot stream, repeated as
// `skytrack replay --loop` repeats it (later times and scan numbers) until it lasts long
// enough for every phase. Held whole: the same batches go to the daemon and to the offline run.
#include <string>
#include <vector>

#include "options.hpp"
#include "skytrack/core/expected.hpp"
#include "skytrack/core/plot.hpp"

namespace skytrack::adversary {

struct GoodStream {
  std::vector<PlotScan> scans;  // one sensor, in time order
  std::uint32_t sensor = 0;
  std::string description;  // for the report: source, batches, span
  double start = 0.0;       // [s] the first batch's time
};

/// The good sensor's batches from `options` (scenario or plots), covering `duration` seconds
/// of stream time from the first batch. Fails on a stream with more than one sensor, with the
/// adversary's sensor id, or without batches.
Expected<GoodStream> load_good_stream(const Options& options, const std::string& default_scenario,
                                      double duration);

}  // namespace skytrack::adversary
