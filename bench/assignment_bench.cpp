// Assignment and GOSPA cost versus problem size (the solver is reused by the tracker's GNN).
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "skytrack/association/assignment.hpp"
#include "skytrack/metrics/ospa_gospa.hpp"

namespace {

void BM_AssignmentSquare(benchmark::State& state) {
  const auto n = static_cast<Eigen::Index>(state.range(0));
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> cost(0.0, 100.0);
  const Eigen::MatrixXd matrix = Eigen::MatrixXd::NullaryExpr(n, n, [&] { return cost(rng); });
  skytrack::AssignmentSolver solver;
  for (auto _ : state) benchmark::DoNotOptimize(solver.solve(matrix).total_cost);
  state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_AssignmentSquare)->RangeMultiplier(2)->Range(8, 512)->Complexity();

void BM_GospaPerScan(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> position(-1e4, 1e4);
  std::normal_distribution<double> error(0.0, 30.0);
  std::vector<Eigen::VectorXd> truths, tracks;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d p(position(rng), position(rng));
    truths.emplace_back(p);
    tracks.emplace_back(p + Eigen::Vector2d(error(rng), error(rng)));
  }
  skytrack::metrics::OspaGospa metric({100.0, 2.0});
  for (auto _ : state) benchmark::DoNotOptimize(metric.compute(truths, tracks).gospa);
}
BENCHMARK(BM_GospaPerScan)->Arg(10)->Arg(100)->Arg(500);

}  // namespace
