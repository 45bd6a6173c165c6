#include "good_stream.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "skytrack/config/scenario_loader.hpp"
#include "skytrack/io/jsonl_reader.hpp"
#include "skytrack/sim/simulator.hpp"

namespace skytrack::adversary {
namespace {

Expected<std::vector<PlotScan>> simulate(const Options& options, const std::string& path,
                                         std::string& description) {
  auto scenario = config::load_scenario(path);
  if (!scenario) return unexpected(scenario.error());
  if (scenario->sensor.antenna == sim::SensorSpec::Antenna::kRotating) {
    scenario->sensor.sectors = options.sectors;
  }
  const std::uint64_t seed = options.seed.value_or(scenario->seed);
  description =
      fmt::format("scenario '{}' (seed {}, {} batch{} per revolution)", scenario->name, seed,
                  scenario->sensor.sectors, scenario->sensor.sectors > 1 ? "es" : "");
  auto simulator = sim::Simulator::create(std::move(*scenario), seed);
  if (!simulator) return make_error(path + ": " + simulator.error().message);
  std::vector<PlotScan> scans;
  while (auto batch = simulator->next()) scans.push_back(std::move(batch->plots));
  return scans;
}

Expected<std::vector<PlotScan>> read_plots(const std::string& path, std::string& description) {
  auto reader = io::PlotStreamReader::open(path);
  if (!reader) return unexpected(reader.error());
  std::vector<PlotScan> scans;
  while (auto scan = reader->next()) scans.push_back(std::move(*scan));
  if (reader->read_error()) return make_error(path + ": " + *reader->read_error());
  description =
      fmt::format("plot stream {} ({} lines rejected)", path, reader->counts().rejected_lines);
  return scans;
}

/// Appends passes of `pass` after `out` until it reaches `end`, each pass one period later
/// and numbered after the last (as `skytrack replay --loop` continues a stream).
void repeat_until(const std::vector<PlotScan>& pass, double end, std::vector<PlotScan>& out) {
  const double first = pass.front().time;
  const double last = pass.back().time;
  const double period =
      pass.size() > 1 ? (last - first) / static_cast<double>(pass.size() - 1) : 1.0;
  const double span = last - first + period;
  std::uint64_t max_scan = 0;
  for (const PlotScan& s : pass) max_scan = std::max(max_scan, s.scan);
  double time_offset = 0.0;
  std::uint64_t scan_offset = 0;
  for (;;) {
    for (const PlotScan& s : pass) {
      if (s.time + time_offset >= end) return;
      PlotScan copy = s;
      copy.time += time_offset;
      for (Plot& p : copy.plots) {
        if (p.time) *p.time += time_offset;
      }
      copy.scan += scan_offset;
      out.push_back(std::move(copy));
    }
    time_offset += span;
    scan_offset += max_scan + 1;
  }
}

}  // namespace

Expected<GoodStream> load_good_stream(const Options& options, const std::string& default_scenario,
                                      double duration) {
  GoodStream good;
  std::string source;
  auto pass = options.plots.empty()
                  ? simulate(options,
                             options.scenario.empty() ? default_scenario : options.scenario, source)
                  : read_plots(options.plots, source);
  if (!pass) return unexpected(pass.error());
  if (pass->empty()) return make_error("the good sensor's stream holds no batches");
  good.sensor = pass->front().sensor;
  for (const PlotScan& s : *pass) {
    if (s.sensor != good.sensor) {
      return make_error(fmt::format("the good stream mixes sensors {} and {}: give one sensor",
                                    good.sensor, s.sensor));
    }
  }
  if (good.sensor == options.adversary_sensor) {
    return make_error(
        fmt::format("the good sensor is {}, the adversary's id: pick another with "
                    "--adversary-sensor",
                    good.sensor));
  }
  std::stable_sort(pass->begin(), pass->end(),
                   [](const PlotScan& a, const PlotScan& b) { return a.time < b.time; });
  good.start = pass->front().time;
  repeat_until(*pass, good.start + duration, good.scans);
  const std::size_t passes = (good.scans.size() + pass->size() - 1) / pass->size();
  good.description = fmt::format("{}: sensor {}, {} batches over {:.0f} s{}", source, good.sensor,
                                 good.scans.size(), duration,
                                 passes > 1 ? fmt::format(" ({} passes)", passes) : "");
  return good;
}

}  // namespace skytrack::adversary
