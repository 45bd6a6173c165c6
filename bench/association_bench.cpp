// Association family: spatial gating index, JPDA exact vs cluster size, Murty k-best, GNN.
// Clusters come from the same generator as the tests (tests/association/jpda_test_support.hpp):
// targets on a line `spacing` innovation-sigmas apart, PD 0.9, Poisson clutter, PG 0.99.
#include <cstdint>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "../tests/association/jpda_test_support.hpp"
#include "skytrack/association/gnn_associator.hpp"
#include "skytrack/association/jpda_solver.hpp"
#include "skytrack/association/plot_index.hpp"

namespace {

using skytrack::JpdaProblem;

constexpr int kTracks = 500;
constexpr double kArea = 200e3;       // square surveillance area side [m]
constexpr double kGateRadius = 2e3;   // coarse gating ball [m]
constexpr int kClustersPerSize = 16;  // distinct clusters cycled through per benchmark

std::vector<Eigen::Vector3d> uniform_points(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> xy(0.0, kArea), z(0.0, 12e3);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < n; ++i) points.emplace_back(xy(rng), xy(rng), z(rng));
  return points;
}

// One scan: build the index over the plots, then one radius query per track (2-D).
void BM_PlotIndexBuildAndQuery(benchmark::State& state) {
  const std::vector<Eigen::Vector3d> plots = uniform_points(static_cast<int>(state.range(0)), 1);
  const std::vector<Eigen::Vector3d> tracks = uniform_points(kTracks, 2);
  skytrack::PlotIndex index;
  std::vector<int> found;
  double hits = 0.0;
  for (auto _ : state) {
    index.build(plots, 2);
    for (const Eigen::Vector3d& centre : tracks) {
      index.within(centre, kGateRadius, found);
      hits += static_cast<double>(found.size());
    }
  }
  state.counters["hits_per_query"] = hits / (static_cast<double>(state.iterations()) * kTracks);
}
BENCHMARK(BM_PlotIndexBuildAndQuery)->Arg(1000)->Arg(5000)->Unit(benchmark::kMicrosecond);

// The same 500 queries without the build, and a linear scan for contrast.
void BM_PlotIndexQueriesOnly(benchmark::State& state) {
  const std::vector<Eigen::Vector3d> plots = uniform_points(static_cast<int>(state.range(0)), 1);
  const std::vector<Eigen::Vector3d> tracks = uniform_points(kTracks, 2);
  skytrack::PlotIndex index;
  index.build(plots, 2);
  std::vector<int> found;
  for (auto _ : state) {
    for (const Eigen::Vector3d& centre : tracks) index.within(centre, kGateRadius, found);
    benchmark::DoNotOptimize(found.data());
  }
}
BENCHMARK(BM_PlotIndexQueriesOnly)->Arg(1000)->Arg(5000)->Unit(benchmark::kMicrosecond);

void BM_LinearScanQueries(benchmark::State& state) {
  const std::vector<Eigen::Vector3d> plots = uniform_points(static_cast<int>(state.range(0)), 1);
  const std::vector<Eigen::Vector3d> tracks = uniform_points(kTracks, 2);
  std::vector<int> found;
  for (auto _ : state) {
    for (const Eigen::Vector3d& centre : tracks) {
      found.clear();
      for (std::size_t j = 0; j < plots.size(); ++j) {
        if ((plots[j] - centre).head<2>().squaredNorm() <= kGateRadius * kGateRadius) {
          found.push_back(static_cast<int>(j));
        }
      }
    }
    benchmark::DoNotOptimize(found.data());
  }
}
BENCHMARK(BM_LinearScanQueries)->Arg(1000)->Arg(5000)->Unit(benchmark::kMicrosecond);

std::vector<JpdaProblem> chain_clusters(int tracks, double spacing, double clutter) {
  std::mt19937_64 rng(static_cast<std::uint64_t>(1000 + tracks));
  std::vector<JpdaProblem> clusters;
  for (int i = 0; i < kClustersPerSize; ++i) {
    clusters.push_back(skytrack::test::chain_cluster(tracks, spacing, clutter, rng));
  }
  return clusters;
}

// Exact JPDA (dynamic programme) vs cluster size; range(1): 0 = sparse (4 sigma apart,
// 0.005 clutter / sigma^2), 1 = dense (1.5 sigma apart, 0.05 clutter / sigma^2).
void BM_JpdaExact(benchmark::State& state) {
  const bool dense = state.range(1) != 0;
  const auto clusters =
      chain_clusters(static_cast<int>(state.range(0)), dense ? 1.5 : 4.0, dense ? 0.05 : 0.005);
  skytrack::JpdaOptions options;
  options.max_exact_tracks = 64;
  options.max_exact_states = std::int64_t{1} << 24;
  skytrack::JpdaSolver solver(options);
  std::size_t i = 0;
  double states = 0.0, events = 0.0, plots = 0.0;
  for (auto _ : state) {
    const JpdaProblem& problem = clusters[i++ % clusters.size()];
    const skytrack::JpdaResult& result = solver.solve_exact(problem);
    benchmark::DoNotOptimize(result.beta.data());
    states += static_cast<double>(solver.exact_outcome().states);
    events += static_cast<double>(result.hypotheses);
    plots += static_cast<double>(problem.likelihood.cols());
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["plots"] = plots / n;
  state.counters["states"] = states / n;
  state.counters["events"] = events / n;
}
BENCHMARK(BM_JpdaExact)
    ->ArgsProduct({benchmark::CreateDenseRange(2, 14, 2), {0, 1}})
    ->ArgNames({"tracks", "dense"})
    ->Unit(benchmark::kMicrosecond);

// Murty k = 100 approximation on 10- and 20-track clusters (same two regimes).
void BM_JpdaMurtyK100(benchmark::State& state) {
  const bool dense = state.range(1) != 0;
  const auto clusters =
      chain_clusters(static_cast<int>(state.range(0)), dense ? 1.5 : 4.0, dense ? 0.05 : 0.005);
  skytrack::JpdaSolver solver;
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(solver.solve_k_best(clusters[i++ % clusters.size()], 100).beta.data());
  }
}
BENCHMARK(BM_JpdaMurtyK100)
    ->ArgsProduct({{10, 20}, {0, 1}})
    ->ArgNames({"tracks", "dense"})
    ->Unit(benchmark::kMicrosecond);

// GNN: one assignment per cluster (10, 20 tracks, dense regime) and per 500-track cluster.
void BM_Gnn(benchmark::State& state) {
  const auto clusters = chain_clusters(static_cast<int>(state.range(0)), 1.5, 0.05);
  skytrack::GnnAssociator gnn;
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(gnn.associate(clusters[i++ % clusters.size()]).beta.data());
  }
}
BENCHMARK(BM_Gnn)->Arg(10)->Arg(20)->Arg(100)->ArgName("tracks")->Unit(benchmark::kMicrosecond);

}  // namespace
