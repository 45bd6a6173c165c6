// Extended mode's speed (issue 27): a 100-run Monte Carlo of paper 002's experiment per
// estimator (target: under 1 s each), and the ExtendedTracker's cost per scan on the
// multi-object scenario (four objects, two crossing, 20 clutter plots a scan).
#include <benchmark/benchmark.h>

#include "multi_scenario.hpp"
#include "paper_scenario.hpp"
#include "skytrack/extended/extended_tracker.hpp"

namespace xmc = skytrack::extended::experiment;
using skytrack::extended::ExtendedTracker;

namespace {

void BM_PaperMonteCarlo100(benchmark::State& state) {
  const xmc::PaperScenario scenario;
  const xmc::FilterSetup filter =
      xmc::paper_filters(scenario, scenario.sensor_bound)[static_cast<int>(state.range(0))];
  state.SetLabel(filter.name);
  for (auto _ : state) {
    const xmc::McResult r = xmc::run_paper_monte_carlo(scenario, filter, 100, 1);
    benchmark::DoNotOptimize(r.mean_gwd);
  }
}
BENCHMARK(BM_PaperMonteCarlo100)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

void BM_MultiObjectScan(benchmark::State& state) {
  const xmc::PaperScenario paper;
  xmc::FilterSetup filter =
      xmc::paper_filters(paper, paper.sensor_bound / 4.0)[static_cast<int>(state.range(0))];
  filter.spec.smf.bound_sigmas = 2.0;
  state.SetLabel(filter.name);
  const std::vector<xmc::MultiScan> scans = xmc::multi_object_scans(1);
  std::size_t plots = 0;
  for (const xmc::MultiScan& scan : scans) plots = std::max(plots, scan.plots.size());
  const std::vector<Eigen::Matrix2d> noises(plots, Eigen::Matrix2d(paper.sensor_bound / 4.0));
  for (auto _ : state) {
    ExtendedTracker tracker(filter.spec);
    for (const xmc::MultiScan& scan : scans) {
      tracker.process(scan.time, scan.plots, std::span(noises).first(scan.plots.size()));
    }
    benchmark::DoNotOptimize(tracker.tracks().data());
  }
  // Time per scan: the whole run's time divided by its scans.
  state.counters["scans"] = static_cast<double>(scans.size());
  state.counters["per_scan"] = benchmark::Counter(
      static_cast<double>(scans.size()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_MultiObjectScan)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);

}  // namespace
