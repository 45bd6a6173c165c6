// Group tracking (paper 000, LBP-PHD: §3.1 preprocessing + §3.2 filter) on one core.
// BM_GroupExperiment1Run: one whole 50-scan run of the paper's experiment 1 (six groups,
//   clutter 10 per scan), the scenario made before timing; the target is 50 ms.
// BM_GroupScan/groups/clutter: steady-state cost of one scan with `groups` groups of 15 plots
//   (uniform +-10 m) in `clutter` uniform clutter plots, CV motion, groups 300 m apart.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "scenario.hpp"
#include "skytrack/group/group_tracker.hpp"

namespace {

using skytrack::group::GroupSpec;
using skytrack::group::GroupTracker;

void BM_GroupExperiment1Run(benchmark::State& state) {
  const group_mc::Scenario sc = group_mc::make_experiment1(1);
  GroupSpec spec;
  std::size_t plots = 0;
  for (const auto& s : sc.scans) {
    plots += s.plots.size();
  }
  for (auto _ : state) {
    GroupTracker tracker(spec);
    for (const auto& s : sc.scans) {
      benchmark::DoNotOptimize(tracker.process(s.time, std::span(s.plots)).data());
    }
  }
  state.counters["scans"] = static_cast<double>(sc.scans.size());
  state.counters["plots/scan"] = static_cast<double>(plots) / sc.scans.size();
  state.counters["time_per_scan"] = benchmark::Counter(
      static_cast<double>(sc.scans.size()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_GroupExperiment1Run)->Unit(benchmark::kMillisecond);

constexpr int kScans = 200;
constexpr int kWarmUp = 10;

std::vector<std::vector<Eigen::Vector3d>> make_scans(int groups, int clutter) {
  std::mt19937_64 rng(static_cast<std::uint64_t>(groups * 1000 + clutter));
  const int side = static_cast<int>(std::ceil(std::sqrt(groups)));
  const double half_area = 0.5 * std::max(side * 300.0, 2000.0) + 2000.0;
  std::uniform_real_distribution<double> spread(-10.0, 10.0);
  std::uniform_real_distribution<double> area(-half_area, half_area);
  std::vector<std::vector<Eigen::Vector3d>> scans(kScans);
  for (int k = 0; k < kScans; ++k) {
    for (int g = 0; g < groups; ++g) {
      const double cx = (g % side - 0.5 * side) * 300.0 + 5.0 * k;
      const double cy = (g / side - 0.5 * side) * 300.0 - 3.0 * k;
      for (int i = 0; i < 15; ++i) {
        scans[static_cast<std::size_t>(k)].emplace_back(cx + spread(rng), cy + spread(rng), 0.0);
      }
    }
    for (int i = 0; i < clutter; ++i) {
      const double x = area(rng);
      scans[static_cast<std::size_t>(k)].emplace_back(x, area(rng), 0.0);
    }
  }
  return scans;
}

void BM_GroupScan(benchmark::State& state) {
  const int groups = static_cast<int>(state.range(0));
  const int clutter = static_cast<int>(state.range(1));
  const auto scans = make_scans(groups, clutter);
  GroupSpec spec;
  spec.motion = skytrack::group::GroupMotion::kConstantVelocity;
  // lambda of eq. 20 counts the clutter that reaches the filter: the preprocessing leaves a
  // few of the scan's clutter plots, not all of them.
  spec.clutter_rate = 10.0;
  const double half = 0.5 * std::max(std::ceil(std::sqrt(groups)) * 300.0, 2000.0) + 2000.0;
  spec.surveillance_area = 4.0 * half * half;
  auto tracker = std::make_unique<GroupTracker>(spec);
  int k = 0;
  double reported = 0.0, particles = 0.0, runs = 0.0;
  for (auto _ : state) {
    if (k == 0 || k == kScans) {
      state.PauseTiming();
      tracker = std::make_unique<GroupTracker>(spec);
      for (k = 0; k < kWarmUp; ++k) {
        tracker->process(k, std::span(scans[static_cast<std::size_t>(k)]));
      }
      state.ResumeTiming();
    }
    const auto& est = tracker->process(k, std::span(scans[static_cast<std::size_t>(k)]));
    reported += static_cast<double>(est.size());
    particles += static_cast<double>(tracker->filter().particles().size());
    runs += 1.0;
    ++k;
  }
  state.counters["plots"] = 15.0 * groups + clutter;
  state.counters["groups_reported"] = reported / runs;
  state.counters["boxes"] = particles / runs;
}
BENCHMARK(BM_GroupScan)
    ->ArgsProduct({{1, 4, 16, 64}, {10, 100, 1000}})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
