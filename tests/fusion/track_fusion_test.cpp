// TrackFusion: cycles, association, numbering, sensors dropping out, bad input.
#include <cmath>
#include <limits>
#include <map>
#include <vector>

#include <gtest/gtest.h>

#include "fusion_test_support.hpp"
#include "skytrack/fusion/track_fusion.hpp"

namespace skytrack::fusion {
namespace {

using testing::frame;

/// Feeds two sensors seeing targets at (100 t, 0) and (100 t, 5000) for cycles [from, to);
/// `numbers` give each sensor's local numbers of the two targets.
struct TwoSensors {
  TrackFusion fusion{FusionSpec{}};
  std::vector<TrackFrame> out;

  void feed(double from, double to, std::int64_t a1 = 11, std::int64_t a2 = 12,
            std::int64_t b1 = 21, std::int64_t b2 = 22, bool sensor_b = true) {
    for (double t = from; t < to; t += 1.0) {
      for (auto& f : fusion.add(frame(1, t, {{a1, 100 * t + 10, 0}, {a2, 100 * t, 5000}}))) {
        out.push_back(f);
      }
      if (!sensor_b) continue;
      for (auto& f : fusion.add(frame(2, t, {{b1, 100 * t - 10, 20}, {b2, 100 * t, 5030}}))) {
        out.push_back(f);
      }
    }
  }
};

std::map<std::int64_t, const TrackReport*> by_id(const TrackFrame& f) {
  std::map<std::int64_t, const TrackReport*> m;
  for (const TrackReport& t : f.tracks) m[t.id] = &t;
  return m;
}

TEST(TrackFusion, TwoSensorsGiveOneSystemTrackPerTarget) {
  TwoSensors s;
  s.feed(0, 10);
  ASSERT_EQ(s.out.size(), 10u);  // each cycle fused when sensor 2 reported it
  const TrackFrame& last = s.out.back();
  EXPECT_EQ(last.time, 9.0);
  EXPECT_EQ(last.scan, 10u);
  ASSERT_EQ(last.tracks.size(), 2u);
  for (const TrackReport& t : last.tracks) {
    EXPECT_EQ(t.status, TrackStatus::kConfirmed);
    ASSERT_EQ(t.sources.size(), 2u);
    EXPECT_EQ(t.sources[0].sensor, 1u);
    EXPECT_EQ(t.sources[1].sensor, 2u);
    EXPECT_EQ(t.sources[1].track - t.sources[0].track, 10);  // 11 with 21, 12 with 22
  }
  EXPECT_EQ(s.fusion.counters().system_tracks, 2u);
  EXPECT_EQ(s.out.front().events.size(), 4u);  // initiated + confirmed, twice
}

TEST(TrackFusion, NumbersSurviveALocalRenumbering) {
  TwoSensors s;
  s.feed(0, 10);
  const auto before = by_id(s.out.back());
  // WHEN sensor 1 renumbers both its tracks (its partners on sensor 2 keep theirs)
  s.feed(10, 20, 111, 112);
  const auto after = by_id(s.out.back());
  ASSERT_EQ(after.size(), 2u);
  for (const auto& [id, t] : after) {
    EXPECT_TRUE(before.count(id)) << "system track " << id << " is new";
    EXPECT_EQ(t->sources.size(), 2u);
    EXPECT_GT(t->sources[0].track, 100);
  }
  EXPECT_EQ(s.fusion.counters().system_tracks, 2u);
}

TEST(TrackFusion, ASilentSensorIsDroppedAndItsTracksContinueFromTheOthers) {
  TwoSensors s;
  s.feed(0, 10);
  const auto before = by_id(s.out.back());
  s.feed(10, 30, 11, 12, 21, 22, /*sensor_b=*/false);
  EXPECT_EQ(s.fusion.counters().sensors_dropped, 1u);
  // cycles go on without sensor 2 once its timeout (5 s) has passed
  EXPECT_GE(s.out.back().time, 28.0);
  const auto after = by_id(s.out.back());
  ASSERT_EQ(after.size(), 2u);
  for (const auto& [id, t] : after) {
    EXPECT_TRUE(before.count(id));
    ASSERT_EQ(t->sources.size(), 1u);
    EXPECT_EQ(t->sources[0].sensor, 1u);
  }
}

TEST(TrackFusion, ATrackWithoutSourcesCoastsThenIsDeletedOnce) {
  TrackFusion fusion{FusionSpec{}};
  std::vector<TrackFrame> out;
  for (double t = 0; t < 3; t += 1.0) {
    for (auto& f : fusion.add(frame(1, t, {{7, 100 * t, 0}}))) out.push_back(f);
  }
  for (double t = 3; t < 12; t += 1.0) {
    for (auto& f : fusion.add(frame(1, t, {}))) out.push_back(f);
  }
  ASSERT_EQ(out.size(), 12u);
  EXPECT_EQ(out[3].tracks.at(0).status, TrackStatus::kCoasting);
  EXPECT_NEAR(out[3].tracks.at(0).position.x(), 300.0, 1e-9);  // predicted on
  EXPECT_TRUE(out[3].tracks.at(0).sources.empty());
  // coast_time 5 s: last fed at t = 2, deleted at t = 8 and never reported again
  EXPECT_EQ(out[7].tracks.at(0).status, TrackStatus::kCoasting);
  EXPECT_EQ(out[8].tracks.at(0).status, TrackStatus::kDeleted);
  ASSERT_EQ(out[8].events.size(), 1u);
  EXPECT_EQ(out[8].events[0].type, TrackEventType::kDeleted);
  EXPECT_TRUE(out[9].tracks.empty());
}

TEST(TrackFusion, LateAndNonFiniteInputIsCountedAndIgnored) {
  TwoSensors s;
  s.feed(0, 5);
  TrackFusion& f = s.fusion;
  EXPECT_TRUE(f.add(frame(1, 2.0, {{11, 0, 0}})).empty());  // older than the last cycle
  EXPECT_EQ(f.counters().frames_late, 1u);
  EXPECT_TRUE(f.add(frame(1, std::nan(""), {{11, 0, 0}})).empty());
  EXPECT_EQ(f.counters().frames_invalid, 1u);
  TrackFrame bad = frame(1, 5.0, {{11, 500, 0}, {12, 500, 5000}});
  bad.tracks[0].position.x() = std::numeric_limits<double>::infinity();
  bad.tracks[1].covariance[5] = std::nan("");
  f.add(bad);
  EXPECT_EQ(f.counters().tracks_invalid, 2u);
  const std::vector<TrackFrame> out = f.add(frame(2, 5.0, {{21, 490, 20}, {22, 500, 5030}}));
  ASSERT_EQ(out.size(), 1u);
  for (const TrackReport& t : out[0].tracks) {
    EXPECT_TRUE(t.position.allFinite());
    EXPECT_EQ(t.sources.size(), 1u);  // sensor 2 alone this cycle
  }
}

TEST(TrackFusion, IsDeterministic) {
  TwoSensors a, b;
  a.feed(0, 15);
  b.feed(0, 15);
  EXPECT_EQ(a.out, b.out);
}

TEST(TrackFusion, AlignsFramesOfDifferentTimesByPrediction) {
  TrackFusion fusion{FusionSpec{}};
  EXPECT_TRUE(fusion.add(frame(1, 0.0, {{1, 0, 0}})).empty());    // the first cycle waits
  EXPECT_EQ(fusion.add(frame(2, 0.4, {{5, 40, 0}})).size(), 1u);  // cycle 0: sensor 1 only
  EXPECT_TRUE(fusion.add(frame(1, 1.0, {{1, 100, 0}})).empty());  // sensor 2 not at 1 s yet
  const std::vector<TrackFrame> out = fusion.add(frame(2, 1.4, {{5, 140, 0}}));
  ASSERT_EQ(out.size(), 1u);
  // cycle at t = 1: sensor 2's frame at 0.4 predicted by 0.6 s to x = 100
  const TrackFrame& f = out.back();
  EXPECT_EQ(f.time, 1.0);
  ASSERT_EQ(f.tracks.size(), 1u);
  EXPECT_EQ(f.tracks[0].sources.size(), 2u);
  EXPECT_NEAR(f.tracks[0].position.x(), 100.0, 1e-6);
}

TEST(TrackFusion, FlushFusesTheOpenCycles) {
  TrackFusion fusion{FusionSpec{}};
  fusion.add(frame(1, 0.0, {{1, 0, 0}}));
  fusion.add(frame(2, 0.0, {{5, 0, 0}}));
  fusion.add(frame(1, 1.0, {{1, 100, 0}}));
  fusion.add(frame(1, 2.0, {{1, 200, 0}}));
  const std::vector<TrackFrame> rest = fusion.flush();
  ASSERT_EQ(rest.size(), 2u);
  EXPECT_EQ(rest.back().time, 2.0);
  EXPECT_EQ(fusion.counters().cycles, 3u);
}

TEST(TrackFusion, ThreeDimensionalTracksGiveThreeDimensionalSystemTracks) {
  TrackFusion fusion{FusionSpec{}};
  std::vector<TrackFrame> out;
  for (double t = 0; t < 3; t += 1.0) {
    for (std::uint32_t s = 1; s <= 2; ++s) {
      TrackFrame f = frame(s, t, {{s == 1 ? 1 : 5, 100 * t, 0}});
      TrackReport& r = f.tracks[0];
      r.dims = 3;
      r.position.z() = 3000.0 + 10.0 * s;
      r.covariance.assign(36, 0.0);
      for (int i = 0; i < 6; ++i) r.covariance[static_cast<std::size_t>(i * 7)] = 400.0;
      for (auto& g : fusion.add(f)) out.push_back(g);
    }
  }
  ASSERT_FALSE(out.empty());
  const TrackReport& t = out.back().tracks.at(0);
  EXPECT_EQ(t.dims, 3);
  EXPECT_EQ(t.covariance.size(), 36u);
  EXPECT_EQ(t.sources.size(), 2u);
  EXPECT_NEAR(t.position.z(), 3015.0, 1e-9);  // equal covariances: the mean
}

TEST(TrackFusion, ADroppedSensorComesBackIntoItsSystemTracks) {
  TwoSensors s;
  s.feed(0, 10);
  s.feed(10, 20, 11, 12, 21, 22, /*sensor_b=*/false);
  s.feed(20, 30);
  EXPECT_EQ(s.fusion.counters().sensors_dropped, 1u);
  EXPECT_EQ(s.fusion.counters().system_tracks, 2u);
  for (const TrackReport& t : s.out.back().tracks) EXPECT_EQ(t.sources.size(), 2u);
}

TEST(TrackFusion, ALocalTrackBackFromAShortGapRejoinsItsSystemTrack) {
  TrackFusion fusion{FusionSpec{}};
  std::vector<TrackFrame> out;
  const auto feed = [&](double t, bool present) {
    TrackFrame f = present ? frame(1, t, {{7, 100 * t, 0}}) : frame(1, t, {});
    for (auto& g : fusion.add(f)) out.push_back(g);
  };
  for (int k = 0; k < 20; ++k) feed(k, k < 5 || (k >= 8 && k < 12) || k >= 19);
  // back after 3 cycles (coasting 3 s < 5 s): the same number, confirmed again
  EXPECT_EQ(out[7].tracks.at(0).status, TrackStatus::kCoasting);
  ASSERT_EQ(out[8].tracks.size(), 1u);
  EXPECT_EQ(out[8].tracks[0].id, out[0].tracks[0].id);
  EXPECT_EQ(out[8].tracks[0].status, TrackStatus::kConfirmed);
  // back after 7 cycles, its system track deleted meanwhile: a new number, never a reused one
  ASSERT_EQ(out[19].tracks.size(), 1u);
  EXPECT_GT(out[19].tracks[0].id, out[0].tracks[0].id);
  EXPECT_EQ(fusion.counters().system_tracks, 2u);
}

TEST(TrackFusion, AGapInDataTimeIsJumpedOver) {
  TrackFusion fusion{FusionSpec{}};
  fusion.add(frame(1, 0.0, {{1, 0, 0}}));
  const std::vector<TrackFrame> out = fusion.add(frame(1, 1e7, {{1, 0, 0}}));
  EXPECT_LT(out.size(), 100u);
  EXPECT_GT(fusion.counters().cycles_skipped, 0u);
}

}  // namespace
}  // namespace skytrack::fusion
