// A completed chain whose track would be deleted by its next look unless it took a plot waits
// for that plot as a chain (Initiator::hold): in dense clutter most chains are such, and each
// would otherwise cost a filter's prediction and gating for the one look it lives.
#include <map>

#include <gtest/gtest.h>

#include "tracker_test_support.hpp"

namespace skytrack {
namespace {

using testing::target;
using testing::test_profile;

struct WeakChainRun {
  int initiated = 0, held = 0;
  int tracks = 0, one_look = 0;  // tracks reported, and of them deleted by their first look
  metrics::EvaluationSummary summary;
};

WeakChainRun track_weak_chains(std::uint64_t seed) {
  // Three targets among 600 clutter plots per scan (0.05 per km^2) of a 2-s snapshot radar.
  sim::Scenario s = testing::radar_scenario(600.0, sim::SensorSpec::Antenna::kSnapshot);
  s.duration = 80.0;
  s.targets = {target(1, {-15000.0, 20000.0, 0.0}, {200.0, 0.0, 0.0}),
               target(2, {10000.0, -30000.0, 0.0}, {0.0, 250.0, 0.0}),
               target(3, {30000.0, 30000.0, 0.0}, {-150.0, -150.0, 0.0})};
  auto simulator = sim::Simulator::create(s, seed);
  EXPECT_TRUE(simulator);
  config::TrackingProfile profile = test_profile();
  profile.point.track_life.confirmation = config::ConfirmationMethod::kExistence;
  auto pipeline = Pipeline::create(profile);
  EXPECT_TRUE(pipeline);
  metrics::ScenarioEvaluation evaluation({200.0, 2.0});
  std::map<std::int64_t, int> frames_of;
  WeakChainRun out;
  while (auto batch = simulator->next()) {
    const ScanResult& result = pipeline->process(batch->plots);
    EXPECT_TRUE(result.accepted) << result.rejection;
    out.initiated += result.report.initiated;
    out.held += result.report.chains_held;
    for (const TrackReport& track : result.frame.tracks) ++frames_of[track.id];
    evaluation.add(batch->truth, &result.frame);
  }
  out.summary = evaluation.summary();
  for (const auto& [id, frames] : frames_of) {
    ++out.tracks;
    out.one_look += frames <= 2 ? 1 : 0;  // reported as started, then as deleted
  }
  return out;
}

TEST(WeakChains, WaitForTheirNextPlotAsChainsInsteadOfStartingTracksThatDieAtOnce) {
  for (const std::uint64_t seed : {1, 2}) {
    const WeakChainRun r = track_weak_chains(seed);
    // THEN most completed chains are clutter too weak to outlive a missed look, and wait
    // (measured: 393 and 359 held, 184 and 158 tracks started; 573 and 514 started when
    // every chain started a track)
    EXPECT_GT(r.held, r.initiated) << "seed " << seed;
    // AND under 40 % of the tracks started are deleted by their first look (measured: 19 %
    // and 14 %; 74 % and 73 % when every chain started a track)
    EXPECT_LT(5 * r.one_look, 2 * r.tracks) << "seed " << seed;
    // AND every target is tracked for most of the run with one number
    for (const auto& truth : r.summary.continuity) {
      EXPECT_GE(truth.frames_tracked, truth.frames_present - 10) << "truth " << truth.truth_id;
      EXPECT_EQ(truth.distinct_tracks, 1) << "truth " << truth.truth_id;
    }
  }
}

}  // namespace
}  // namespace skytrack
