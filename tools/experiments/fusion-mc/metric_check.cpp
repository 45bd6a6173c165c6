// Why the shipped base distance is normalised: targets whose track errors differ (range,
// radar), fused with one setting. 40 targets 3 km apart flying east at 200 m/s; target i's
// track error sigma grows from 20 m to 300 m (sensor 1) and 1.2 times that (sensor 2),
// drawn per scan; 30 scans of 1 s. Normalised defaults against Euclidean metres set for one
// sigma (the shipped sigmas times that pair's sigma).
#include <cmath>
#include <random>
#include <vector>

#include <fmt/format.h>

#include "experiment.hpp"
#include "skytrack/fusion/track_fusion.hpp"

namespace skytrack::fusion_mc {
namespace {

constexpr int kTargets = 40;
constexpr int kScans = 30;
constexpr double kSpacing = 3000.0;  // [m]

double sigma_of(int target, int sensor) {
  return (20.0 + 280.0 * target / (kTargets - 1)) * (sensor == 0 ? 1.0 : 1.2);
}

TrackFrame frame(int sensor, int scan, std::mt19937_64& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  TrackFrame f;
  f.sensor = static_cast<std::uint32_t>(sensor + 1);
  f.time = scan;
  for (int i = 0; i < kTargets; ++i) {
    const double s = sigma_of(i, sensor);
    TrackReport t;
    t.id = (sensor + 1) * 1000 + i;
    t.status = TrackStatus::kConfirmed;
    t.position = {200.0 * scan + s * normal(rng), kSpacing * i + s * normal(rng), 0.0};
    t.velocity = {200.0 + 5.0 * normal(rng), 5.0 * normal(rng), 0.0};
    t.covariance = {s * s, 0, 0, 0, 0, 25, 0, 0, 0, 0, s * s, 0, 0, 0, 0, 25};
    f.tracks.push_back(std::move(t));
  }
  return f;
}

fusion::FusionSpec metres_for(double sigma) {
  const fusion::FusionSpec shipped;
  fusion::FusionSpec s = shipped;
  const double pair = std::sqrt(sigma * sigma + 1.44 * sigma * sigma);
  s.metric = fusion::Metric::kEuclidean;
  s.cutoff = shipped.cutoff * pair;
  s.label_penalty = shipped.label_penalty * pair;
  s.gate = shipped.gate * pair;
  return s;
}

}  // namespace

void run_metric_check(int runs, std::uint64_t first_seed) {
  struct Setting {
    const char* name;
    fusion::FusionSpec spec;
  };
  const std::vector<Setting> settings{{"normalised (shipped: c 10, alpha 2, gamma 4 sigmas)", {}},
                                      {"metres for sigma 20 m (the nearest)", metres_for(20.0)},
                                      {"metres for sigma 160 m (the median)", metres_for(160.0)},
                                      {"metres for sigma 300 m (the farthest)", metres_for(300.0)}};
  fmt::print(
      "### Base distance: {} targets, track sigma 20-300 m (sensor 2: x 1.2), {} runs, seeds "
      "{}..{}\n\n| setting | right pairs, sigma < 100 m | right pairs, sigma >= 100 m | system "
      "tracks (ideal {}) | pairs scored per cycle |\n|---|---:|---:|---:|---:|\n",
      kTargets, runs, first_seed, first_seed + static_cast<std::uint64_t>(runs) - 1, kTargets);
  for (const Setting& setting : settings) {
    long right_near = 0, right_far = 0, near = 0, far = 0, systems = 0, frames = 0;
    double pairs = 0.0;
    for (int run = 0; run < runs; ++run) {
      std::mt19937_64 rng(first_seed + static_cast<std::uint64_t>(run));
      fusion::TrackFusion fusion(setting.spec);
      std::vector<TrackFrame> out;
      for (int k = 0; k < kScans; ++k) {
        for (int s = 0; s < 2; ++s) {
          for (TrackFrame& g : fusion.add(frame(s, k, rng))) out.push_back(std::move(g));
        }
      }
      for (TrackFrame& g : fusion.flush()) out.push_back(std::move(g));
      pairs += static_cast<double>(fusion.counters().pairs_scored);
      for (const TrackFrame& f : out) {
        ++frames;
        std::vector<bool> right(kTargets, false);
        for (const TrackReport& t : f.tracks) {
          if (t.status != TrackStatus::kConfirmed) continue;
          ++systems;
          if (t.sources.size() == 2 && t.sources[1].track - t.sources[0].track == 1000) {
            right[static_cast<std::size_t>(t.sources[0].track - 1000)] = true;
          }
        }
        for (int i = 0; i < kTargets; ++i) {
          const bool is_near = sigma_of(i, 0) < 100.0;
          (is_near ? near : far) += 1;
          if (right[static_cast<std::size_t>(i)]) (is_near ? right_near : right_far) += 1;
        }
      }
    }
    fmt::print("| {} | {:.1f} % | {:.1f} % | {:.1f} | {:.1f} |\n", setting.name,
               100.0 * right_near / near, 100.0 * right_far / far,
               static_cast<double>(systems) / frames, pairs / frames);
  }
  fmt::print("\n");
}

}  // namespace skytrack::fusion_mc
