// The shipped multi-object extended scenario (config/scenarios/extended_crossing.yaml: four
// objects, A and B crossing at the origin at t = 133 s, 20 clutter plots per scan) tracked
// through the Pipeline with the shipped profile config/profiles/extended.yaml and the
// random-matrix estimator, seed 1: from the fifth scan (t = 40 s) on each object is held by one
// confirmed (or coasting) number, the nearest firm track within kMatch of it, every scan,
// and no two objects share a number.
#include <cstdint>
#include <map>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "skytrack/config/profile_loader.hpp"
#include "skytrack/config/scenario_loader.hpp"
#include "skytrack/pipeline/pipeline.hpp"
#include "skytrack/sim/simulator.hpp"

namespace skytrack {
namespace {

constexpr std::uint64_t kSeed = 1;
constexpr double kMatch = 200.0;  // [m] a firm track this close holds the object (eval's cutoff)
// The fifth scan (t = 40 s): three scans with plots confirm a track, and on seed 1 objects A
// and C are first confirmed at t = 40 s (B and D at 20 s).
constexpr int kFirstScored = 4;
constexpr int kObjects = 4;

std::string source(const std::string& relative) {
  return std::string(SKYTRACK_SOURCE_DIR) + "/" + relative;
}

TEST(ExtendedCrossingScenario, EachObjectHasOneNumberWithTheRandomMatrix) {
  const auto scenario = config::load_scenario(source("config/scenarios/extended_crossing.yaml"));
  ASSERT_TRUE(scenario) << scenario.error().message;
  auto profile = config::load_profile(source("config/profiles/extended.yaml"));
  ASSERT_TRUE(profile) << profile.error().message;
  profile->extended.kind = extended::EstimatorKind::kRandomMatrix;
  auto simulator = sim::Simulator::create(*scenario, kSeed);
  ASSERT_TRUE(simulator) << simulator.error().message;
  auto pipeline = Pipeline::create(*profile);
  ASSERT_TRUE(pipeline) << pipeline.error().message;

  std::map<std::int64_t, std::set<std::int64_t>> numbers;  // truth id -> track numbers on it
  int scans = 0;
  for (int k = 0; auto batch = simulator->next(); ++k) {
    const ScanResult& result = pipeline->process(batch->plots);
    ASSERT_TRUE(result.accepted) << result.rejection;
    ++scans;
    ASSERT_EQ(batch->truth.objects.size(), static_cast<std::size_t>(kObjects));
    if (k < kFirstScored) continue;
    for (const TruthObject& object : batch->truth.objects) {
      const TrackReport* nearest = nullptr;
      double best = kMatch;
      for (const TrackReport& track : result.frame.tracks) {
        if (!is_reported_as_firm(track.status)) continue;
        const double d = (track.position - object.position).head<2>().norm();
        if (d < best) best = d, nearest = &track;
      }
      ASSERT_NE(nearest, nullptr) << "object " << object.id
                                  << " untracked at t = " << batch->truth.time;
      numbers[object.id].insert(nearest->id);
    }
  }
  EXPECT_EQ(scans, 31);  // t = 0, 10, ..., 300 s
  std::set<std::int64_t> all;
  for (const auto& [object, on_it] : numbers) {
    EXPECT_EQ(on_it.size(), 1u) << "object " << object;
    all.insert(on_it.begin(), on_it.end());
  }
  EXPECT_EQ(numbers.size(), static_cast<std::size_t>(kObjects));
  EXPECT_EQ(all.size(), static_cast<std::size_t>(kObjects));  // no two objects share one
}

}  // namespace
}  // namespace skytrack
