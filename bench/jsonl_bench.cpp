// Plot-stream parse and write throughput for scans of many plots (replay and offline runs
// are bounded by this when the tracker is fast).
#include <random>
#include <string>

#include <benchmark/benchmark.h>

#include "skytrack/io/jsonl_reader.hpp"
#include "skytrack/io/jsonl_writer.hpp"

namespace {

skytrack::PlotScan make_scan(int plots) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> range(1e3, 1e5), angle(-3.14, 3.14);
  skytrack::PlotScan scan;
  scan.sensor = 1;
  scan.scan = 7;
  scan.time = 123.456;
  scan.sigma.range = 30.0;
  scan.sigma.azimuth = 0.002;
  for (int i = 0; i < plots; ++i) {
    skytrack::Plot plot;
    plot.id = i;
    plot.range = range(rng);
    plot.azimuth = angle(rng);
    plot.elevation = angle(rng) / 30.0;
    plot.range_rate = angle(rng) * 100.0;
    plot.time = 120.0 + angle(rng);
    scan.plots.push_back(plot);
  }
  return scan;
}

void BM_ParsePlotScan(benchmark::State& state) {
  const std::string line = skytrack::io::to_json(make_scan(static_cast<int>(state.range(0))));
  for (auto _ : state) {
    auto parsed = skytrack::io::parse_plot_scan(line);
    benchmark::DoNotOptimize(parsed->scan.plots.size());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * line.size()));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_ParsePlotScan)->Arg(100)->Arg(1000)->Arg(5000);

void BM_WritePlotScan(benchmark::State& state) {
  const skytrack::PlotScan scan = make_scan(static_cast<int>(state.range(0)));
  std::size_t bytes = 0;
  for (auto _ : state) {
    const std::string line = skytrack::io::to_json(scan);
    bytes += line.size();
    benchmark::DoNotOptimize(line.data());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(bytes));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_WritePlotScan)->Arg(100)->Arg(1000)->Arg(5000);

}  // namespace
