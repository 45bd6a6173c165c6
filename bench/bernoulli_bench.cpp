// One 100-scan run of paper 001's scenario (20 clutter plots per scan) per iteration, filter
// construction included: the target is <= 10 ms on one core for the MMBPF with
// 300/700/700 particles (the paper's Matlab: 137 ms). The plots are simulated beforehand.
#include <benchmark/benchmark.h>

#include "skytrack/bernoulli/imm_bernoulli_filter.hpp"
#include "skytrack/bernoulli/mm_bernoulli_filter.hpp"
#include "skytrack/bernoulli/paper001_scenario.hpp"

namespace {

using namespace skytrack::bernoulli;

const std::vector<Paper001Scan>& scenario() {
  static const std::vector<Paper001Scan> scans = simulate_paper001(Paper001Options{});
  return scans;
}

template <class Filter>
void run(benchmark::State& state, Filter& filter) {
  double q = 0.0;
  for (const Paper001Scan& scan : scenario()) {
    q += filter.step(scan.time, Eigen::Vector2d::Zero(), std::span(scan.plots)).existence;
  }
  benchmark::DoNotOptimize(q);
  state.counters["mean_q"] = q / static_cast<double>(scenario().size());
}

void BM_MmbpfRun(benchmark::State& state) {
  BernoulliSpec spec;
  spec.models[0].particles = static_cast<int>(state.range(0));
  spec.models[1].particles = static_cast<int>(state.range(1));
  spec.models[2].particles = static_cast<int>(state.range(1));
  std::uint64_t seed = 1;
  for (auto _ : state) {
    spec.seed = seed++;
    MmBernoulliFilter filter(spec);
    run(state, filter);
  }
}
BENCHMARK(BM_MmbpfRun)->Args({300, 700})->Args({1000, 1000})->Unit(benchmark::kMillisecond);

void BM_ImmbpfRun(benchmark::State& state) {
  BernoulliSpec spec;
  std::uint64_t seed = 1;
  for (auto _ : state) {
    spec.seed = seed++;
    ImmBernoulliFilter filter(spec, static_cast<int>(state.range(0)));
    run(state, filter);
  }
}
BENCHMARK(BM_ImmbpfRun)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace
