// Paper 004 §4 as a Monte Carlo experiment (experiment.hpp).
#include "experiment.hpp"

#include <cmath>
#include <random>
#include <stdexcept>

#include "skytrack/config/scenario_loader.hpp"
#include "skytrack/fusion/track_fusion.hpp"
#include "skytrack/sim/simulator.hpp"

namespace skytrack::fusion_mc {
namespace {

constexpr double kVariance[2] = {1.0, 0.8};  // [m^2] per axis, sensors 1 and 2 (paper §4)
constexpr double kVelocitySigma = 1.0;       // [m/s] not in the paper; only the output uses it
constexpr std::uint32_t kSensor[2] = {1, 2};

/// Local number of target `truth_id` on sensor index `s`: 101, 102 and 201, 202.
std::int64_t local_number(int s, std::int64_t truth_id) {
  return (s + 1) * 100 + truth_id;
}

TrackFrame local_frame(int s, const TruthFrame& truth, std::mt19937_64& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  const double sigma = std::sqrt(kVariance[s]);
  TrackFrame f;
  f.sensor = kSensor[s];
  f.time = truth.time;
  for (const TruthObject& o : truth.objects) {
    TrackReport t;
    t.id = local_number(s, o.id);
    t.status = TrackStatus::kConfirmed;
    t.dims = 2;
    t.position = {o.position.x() + sigma * normal(rng), o.position.y() + sigma * normal(rng), 0};
    t.velocity = {o.velocity.x() + kVelocitySigma * normal(rng),
                  o.velocity.y() + kVelocitySigma * normal(rng), 0};
    const double v2 = kVelocitySigma * kVelocitySigma;
    t.covariance = {kVariance[s], 0, 0, 0, 0, v2, 0, 0, 0, 0, kVariance[s], 0, 0, 0, 0, v2};
    f.tracks.push_back(std::move(t));
  }
  return f;
}

/// Right when targets 1 and 2 each have one fed system track holding exactly their two
/// local tracks.
bool correct(const TrackFrame& fused) {
  int right = 0;
  for (const TrackReport& t : fused.tracks) {
    if (t.status != TrackStatus::kConfirmed || t.sources.size() != 2) continue;
    const std::int64_t a = t.sources[0].track, b = t.sources[1].track;
    if (b - a == 100 && (a == 101 || a == 102)) ++right;
  }
  return right == 2;
}

void tally(const TrackFrame& fused, ScanTally& out) {
  out.time = fused.time;
  if (correct(fused)) ++out.correct;
  for (const TrackReport& t : fused.tracks) {
    if (t.status == TrackStatus::kConfirmed) ++out.system_tracks;
  }
}

}  // namespace

std::vector<TruthFrame> load_truth(const std::string& scenario_path) {
  auto scenario = config::load_scenario(scenario_path);
  if (!scenario) throw std::runtime_error(scenario.error().message);
  auto sim = sim::Simulator::create(*scenario, 1);
  if (!sim) throw std::runtime_error(sim.error().message);
  std::vector<TruthFrame> truth;
  while (auto batch = sim->next()) truth.push_back(std::move(batch->truth));
  return truth;
}

fusion::FusionSpec paper_spec(fusion::Blend blend, double label_sigmas) {
  const fusion::FusionSpec shipped;
  const double pair_sigma = std::sqrt(kVariance[0] + kVariance[1]);
  fusion::FusionSpec s = shipped;
  s.blend = blend;
  s.metric = fusion::Metric::kEuclidean;
  s.cutoff = shipped.cutoff * pair_sigma;
  s.label_penalty = label_sigmas * pair_sigma;
  s.gate = shipped.gate * pair_sigma;
  s.window = 10.0;  // paper §4
  s.cycle = 1.0;
  return s;
}

std::vector<std::vector<ScanTally>> run_monte_carlo(const std::vector<TruthFrame>& truth,
                                                    const std::vector<fusion::FusionSpec>& specs,
                                                    int runs, std::uint64_t first_seed) {
  std::vector<std::vector<ScanTally>> out(specs.size(), std::vector<ScanTally>(truth.size()));
  for (int run = 0; run < runs; ++run) {
    std::mt19937_64 rng(first_seed + static_cast<std::uint64_t>(run));
    std::vector<TrackFrame> input;
    for (const TruthFrame& t : truth) {
      for (int s = 0; s < 2; ++s) input.push_back(local_frame(s, t, rng));
    }
    for (std::size_t k = 0; k < specs.size(); ++k) {
      fusion::TrackFusion fusion(specs[k]);
      std::vector<TrackFrame> fused;
      for (const TrackFrame& f : input) {
        for (TrackFrame& g : fusion.add(f)) fused.push_back(std::move(g));
      }
      for (TrackFrame& g : fusion.flush()) fused.push_back(std::move(g));
      for (std::size_t i = 0; i < fused.size() && i < truth.size(); ++i) tally(fused[i], out[k][i]);
    }
  }
  return out;
}

}  // namespace skytrack::fusion_mc
