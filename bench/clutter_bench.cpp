// ClutterRejector::apply (paper 000 §3.1, eq. 6-11) versus scan size, h = 500 m, dims = 2.
// BM_ClutterRejectorApply: uniform clutter plus 500 targets over 200 km x 200 km (the clutter
// density grows with the plot count). BM_ClutterRejectorConstantDensity: area and targets grow
// with the plot count at the 10 000-plot clutter density. The k-d tree radius search keeps
// the cost ~ plots x neighbours, so at constant density the time per plot stays flat.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "skytrack/clutter/clutter_rejector.hpp"

namespace {

constexpr double kSide = 200e3;  // [m]
constexpr int kTargets = 500;    // per 200 km x 200 km: formations of 10 aircraft, one plot each

// `clutter` uniform plots over [0, side]^2, then `targets` plots in formations of 10
// (sigma 200 m per axis around a uniform centre).
std::vector<Eigen::Vector3d> make_scan(int clutter, double side, int targets) {
  std::mt19937_64 rng(static_cast<std::uint64_t>(clutter));
  std::uniform_real_distribution<double> u(0.0, side);
  std::normal_distribution<double> spread(0.0, 200.0);
  std::vector<Eigen::Vector3d> plots;
  for (int i = 0; i < clutter; ++i) {
    const double x = u(rng);
    plots.emplace_back(x, u(rng), 0.0);
  }
  for (int g = 0; g < targets / 10; ++g) {
    const double cx = u(rng);
    const double cy = u(rng);
    for (int t = 0; t < 10; ++t) {
      const double x = cx + spread(rng);
      plots.emplace_back(x, cy + spread(rng), 0.0);
    }
  }
  return plots;
}

void run(benchmark::State& state, const std::vector<Eigen::Vector3d>& plots) {
  skytrack::config::ClutterRejectionSpec spec;
  spec.enabled = true;
  spec.kernel_bandwidth = 500.0;
  spec.mean_shift.bandwidth = 500.0;
  skytrack::clutter::ClutterRejector rejector(spec);
  const std::vector<std::uint8_t> none;
  rejector.apply(plots, 2, none);  // warm-up: buffers reach their size
  for (auto _ : state) {
    benchmark::DoNotOptimize(rejector.apply(plots, 2, none).cells);
  }
  const skytrack::clutter::ClutterRejectionResult& r = rejector.result();
  const auto n = static_cast<double>(plots.size());
  const double kept = n - r.rejected;
  state.counters["plots"] = n;
  state.counters["kept"] = kept;
  state.counters["cells"] = r.cells;
  state.counters["steps_per_kept"] = r.mean_shift_steps / std::max(1.0, kept);
  state.counters["ns_per_plot"] = benchmark::Counter(
      n * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.SetComplexityN(static_cast<std::int64_t>(plots.size()));
}

void BM_ClutterRejectorApply(benchmark::State& state) {
  run(state, make_scan(static_cast<int>(state.range(0)), kSide, kTargets));
}
BENCHMARK(BM_ClutterRejectorApply)
    ->Arg(1000)
    ->Arg(5000)
    ->Arg(10000)
    ->Unit(benchmark::kMicrosecond)
    ->Complexity(benchmark::oN);

void BM_ClutterRejectorConstantDensity(benchmark::State& state) {
  const int clutter = static_cast<int>(state.range(0));
  const double scale = clutter / 10000.0;  // area relative to 200 km x 200 km
  run(state, make_scan(clutter, kSide * std::sqrt(scale),
                       static_cast<int>(std::lround(kTargets * scale))));
}
BENCHMARK(BM_ClutterRejectorConstantDensity)
    ->Arg(1000)
    ->Arg(5000)
    ->Arg(10000)
    ->Arg(50000)
    ->Unit(benchmark::kMicrosecond)
    ->Complexity(benchmark::oN);

}  // namespace
