// Per-batch cost of the point tracker (Pipeline::process) against the number of targets and
// clutter plots, with the default profile (branch tracking on), the same without branches
// (plain IMM-JPDA) and with the dense-clutter initiation rules: a 3-D
// snapshot radar over 200 km, Pd 0.9, targets on straight
// and turning paths. Batches are simulated up front; 10 warm-up batches establish the tracks
// before timing starts, then each iteration processes the next batch.
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "skytrack/pipeline/pipeline.hpp"
#include "skytrack/sim/simulator.hpp"

namespace {

constexpr int kWarmup = 10;
constexpr int kTimed = 20;

std::vector<skytrack::PlotScan> make_batches(int targets, int clutter) {
  skytrack::sim::Scenario s;
  s.name = "bench";
  s.dimensions = 3;
  s.duration = (kWarmup + kTimed) * 4.0;
  s.platform.trajectory.position = {0.0, 0.0, 20.0};
  s.sensor.scan_period = 4.0;
  s.sensor.detection_probability = 0.9;
  s.sensor.sigma.range = 30.0;
  s.sensor.sigma.azimuth = 0.002;
  s.sensor.sigma.elevation = 0.003;
  s.sensor.max_range = 150000.0;
  s.clutter.mean = clutter;
  s.clutter.range = {5000.0, 150000.0};
  s.clutter.elevation = {0.0, 0.1};
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int i = 0; i < targets; ++i) {
    skytrack::sim::TargetSpec t;
    t.id = i;
    const double range = 20000.0 + 120000.0 * uniform(rng), bearing = 6.283 * uniform(rng);
    const double heading = 6.283 * uniform(rng), speed = 150.0 + 150.0 * uniform(rng);
    t.trajectory.position = {range * std::sin(bearing), range * std::cos(bearing),
                             1000.0 + 9000.0 * uniform(rng)};
    t.trajectory.velocity = {speed * std::sin(heading), speed * std::cos(heading), 0.0};
    if (i % 3 == 0) {
      skytrack::sim::SegmentSpec turn;
      turn.type = skytrack::sim::SegmentSpec::Type::kCoordinatedTurn;
      turn.duration = 60.0;
      turn.g_load = 2.0;
      turn.turn_left = i % 2 == 0;
      skytrack::sim::SegmentSpec straight;
      straight.duration = 40.0;
      t.trajectory.segments = {straight, turn};
    }
    s.targets.push_back(t);
  }
  auto simulator = skytrack::sim::Simulator::create(s, 11);
  std::vector<skytrack::PlotScan> batches;
  while (auto batch = simulator->next()) batches.push_back(std::move(batch->plots));
  return batches;
}

void run_batches(benchmark::State& state, bool dense_clutter_rules, bool branching = true,
                 bool gated_seeds = true) {
  const int targets = static_cast<int>(state.range(0)), clutter = static_cast<int>(state.range(1));
  const std::vector<skytrack::PlotScan> batches = make_batches(targets, clutter);
  skytrack::config::TrackingProfile profile;
  profile.identity = {"bench", "1", ""};
  if (dense_clutter_rules) {  // config/profiles/dense_clutter.yaml's initiation and map
    profile.point.initiation.m = 3;
    profile.point.initiation.n = 3;
    profile.association.clutter_map.enabled = true;
  }
  profile.point.branching.enabled = branching;
  if (!gated_seeds) profile.point.initiation.gated_seed_beta = 1.0;  // only plots in no gate seed
  auto pipeline = skytrack::Pipeline::create(profile);
  std::size_t next = 0;
  for (; next < kWarmup; ++next) pipeline->process(batches[next]);
  std::size_t tracks = 0, plots = 0;
  double largest_cluster = 0.0, approximated = 0.0, gate_ms = 0.0, associate_ms = 0.0,
         manage_ms = 0.0, confirmed = 0.0, branches = 0.0;
  for (auto _ : state) {
    if (next >= batches.size()) {
      state.SkipWithError("ran out of simulated batches");
      break;
    }
    const skytrack::ScanResult& result = pipeline->process(batches[next]);
    plots += batches[next].plots.size();
    tracks = result.frame.tracks.size();
    const skytrack::ScanReport& r = result.report;
    largest_cluster = std::max(largest_cluster, static_cast<double>(r.point.largest_cluster));
    approximated += r.point.approximated_clusters;
    gate_ms += r.predict.count() / 1000.0;
    associate_ms += r.associate.count() / 1000.0;
    manage_ms += r.manage.count() / 1000.0;
    confirmed = r.confirmed + r.coasting;
    branches += r.point.branches;
    ++next;
  }
  state.counters["plots"] =
      benchmark::Counter(static_cast<double>(plots), benchmark::Counter::kAvgIterations);
  state.counters["tracks"] = static_cast<double>(tracks);
  state.counters["firm"] = confirmed;
  state.counters["max_cluster"] = largest_cluster;
  state.counters["approx"] = approximated;
  const double n = static_cast<double>(state.iterations());
  state.counters["gate_ms"] = gate_ms / n;
  state.counters["assoc_ms"] = associate_ms / n;
  state.counters["manage_ms"] = manage_ms / n;
  state.counters["branches"] = branches / n;
}
void BM_DefaultProfile(benchmark::State& state) {
  run_batches(state, false);
}
void BM_NoBranching(benchmark::State& state) {
  run_batches(state, false, false);
}

void BM_DenseClutterRules(benchmark::State& state) {
  run_batches(state, true);
}
// The initiation rule before initiation.gated_seed_beta: plots inside any gate never seed.
void BM_DenseClutterRulesNoGatedSeeds(benchmark::State& state) {
  run_batches(state, true, true, false);
}
BENCHMARK(BM_DefaultProfile)
    ->ArgsProduct({{10, 100, 500, 1000}, {100, 1000, 5000}})
    ->Iterations(kTimed)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_NoBranching)
    ->ArgsProduct({{10, 100, 500, 1000}, {100, 1000, 5000}})
    ->Iterations(kTimed)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DenseClutterRules)
    ->ArgsProduct({{10, 100, 500, 1000}, {100, 1000, 5000}})
    ->Iterations(kTimed)
    ->Unit(benchmark::kMillisecond);

BENCHMARK(BM_DenseClutterRulesNoGatedSeeds)
    ->ArgsProduct({{500}, {1000, 5000}})
    ->Iterations(kTimed)
    ->Unit(benchmark::kMillisecond);

}  // namespace
