// The fusion role's cycle (paper 004 association + CI fusion): N sensors each reporting the
// same T targets with their own errors, once per second. One iteration = one cycle: the N
// local frames added (input checks, alignment, gated MOSPA scoring with the 10 s history,
// assignment, fusion, the output frame). Target (issue 29): <= 10 ms for 10 x 200 on one core.
#include <malloc.h>

#include <cstdint>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "skytrack/fusion/track_fusion.hpp"

namespace {

using skytrack::TrackFrame;
using skytrack::TrackReport;
using skytrack::TrackStatus;

/// T targets over 200 x 200 km at 100-300 m/s; sensor s sees them with sigma 30 + 10 s m.
class Picture {
 public:
  Picture(int sensors, int targets) : sensors_(sensors), rng_(7) {
    std::uniform_real_distribution<double> pos(-1e5, 1e5), vel(-300.0, 300.0);
    for (int t = 0; t < targets; ++t)
      targets_.push_back({pos(rng_), pos(rng_), vel(rng_), vel(rng_)});
  }

  TrackFrame frame(int s, double time) {
    std::normal_distribution<double> normal(0.0, 1.0);
    const double sigma = 30.0 + 10.0 * s;
    TrackFrame f;
    f.sensor = static_cast<std::uint32_t>(s + 1);
    f.time = time;
    f.tracks.reserve(targets_.size());
    for (std::size_t i = 0; i < targets_.size(); ++i) {
      const Target& t = targets_[i];
      TrackReport r;
      r.id = static_cast<std::int64_t>(i) + 1000 * (s + 1);
      r.status = TrackStatus::kConfirmed;
      r.position = {t.x + t.vx * time + sigma * normal(rng_),
                    t.y + t.vy * time + sigma * normal(rng_), 0};
      r.velocity = {t.vx + 5 * normal(rng_), t.vy + 5 * normal(rng_), 0};
      const double p2 = sigma * sigma;
      r.covariance = {p2, 0, 0, 0, 0, 25, 0, 0, 0, 0, p2, 0, 0, 0, 0, 25};
      f.tracks.push_back(std::move(r));
    }
    return f;
  }
  int sensors() const { return sensors_; }

 private:
  struct Target {
    double x, y, vx, vy;
  };
  int sensors_;
  std::mt19937_64 rng_;
  std::vector<Target> targets_;
};

void BM_FusionCycle(benchmark::State& state) {
  Picture picture(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  // Frames are made ahead (they are the input, not the fusion's work), 64 cycles reused.
  constexpr int kCycles = 64;
  std::vector<std::vector<TrackFrame>> frames(kCycles);
  for (int c = 0; c < kCycles; ++c) {
    for (int s = 0; s < picture.sensors(); ++s) frames[c].push_back(picture.frame(s, c));
  }
  skytrack::fusion::TrackFusion fusion{skytrack::fusion::FusionSpec{}};
  double time = 0.0;
  const auto cycle = [&](int c) {
    std::size_t out = 0;
    for (TrackFrame& f : frames[static_cast<std::size_t>(c % kCycles)]) {
      f.time = time;  // positions repeat every 64 s; the history copes, the cost is the same
      out += fusion.add(f).size();
    }
    time += 1.0;
    return out;
  };
  for (int c = 0; c < 20; ++c) cycle(c);  // the window's history filled
  const std::uint64_t pairs_before = fusion.counters().pairs_scored;
  const std::uint64_t cycles_before = fusion.counters().cycles;
  int c = 20;
  for (auto _ : state) benchmark::DoNotOptimize(cycle(c++));
  const auto cycles = static_cast<double>(fusion.counters().cycles - cycles_before);
  state.counters["pairs_per_cycle"] =
      static_cast<double>(fusion.counters().pairs_scored - pairs_before) / cycles;
  state.counters["system_tracks"] = static_cast<double>(fusion.counters().system_tracks);
}
BENCHMARK(BM_FusionCycle)->Args({2, 200})->Args({10, 200})->Unit(benchmark::kMillisecond);

/// Heap in use after 1000 cycles against after 100: no growth.
void BM_FusionHeapOver1000Cycles(benchmark::State& state) {
  for (auto _ : state) {
    Picture picture(10, 200);
    skytrack::fusion::TrackFusion fusion{skytrack::fusion::FusionSpec{}};
    std::vector<TrackFrame> frames;
    for (int s = 0; s < 10; ++s) frames.push_back(picture.frame(s, 0.0));
    double at_100 = 0.0;
    for (int c = 0; c < 1000; ++c) {
      for (TrackFrame& f : frames) {
        f.time = c;
        benchmark::DoNotOptimize(fusion.add(f).size());
      }
      if (c == 99) at_100 = static_cast<double>(mallinfo2().uordblks);
    }
    state.counters["heap_growth_kB"] = (static_cast<double>(mallinfo2().uordblks) - at_100) / 1024;
  }
}
BENCHMARK(BM_FusionHeapOver1000Cycles)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace
