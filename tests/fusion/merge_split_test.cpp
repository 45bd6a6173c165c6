// System tracks through merges and splits of their local tracks.
#include <algorithm>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "fusion_test_support.hpp"
#include "skytrack/fusion/track_fusion.hpp"

namespace skytrack::fusion {
namespace {

using testing::frame;

std::vector<TrackFrame> run(double y2_before, double y2_after) {
  TrackFusion fusion{FusionSpec{}};
  std::vector<TrackFrame> out;
  for (int k = 0; k < 30; ++k) {
    const double t = k, y2 = k < 10 ? y2_before : y2_after;
    for (auto& f : fusion.add(frame(1, t, {{1, 100 * t, 0}}))) out.push_back(f);
    for (auto& f : fusion.add(frame(2, t, {{5, 100 * t, y2}}))) out.push_back(f);
  }
  for (auto& f : fusion.flush()) out.push_back(f);
  return out;
}

TEST(TrackFusionMergeSplit, TwoSystemTracksOfOneTargetMergeAndOneIsDeletedAtOnce) {
  // GIVEN sensor 2's track 3 km off until t = 10 s, then on sensor 1's target (10 m off)
  const std::vector<TrackFrame> out = run(3000.0, 10.0);
  ASSERT_EQ(out.size(), 30u);
  EXPECT_EQ(out[5].tracks.size(), 2u);  // two targets as far as the fusion can tell
  // THEN one system track with both sources once the window no longer holds the far past,
  // under the older number
  ASSERT_EQ(out.back().tracks.size(), 1u);
  EXPECT_EQ(out.back().tracks[0].sources.size(), 2u);
  EXPECT_EQ(out.back().tracks[0].id, std::min(out[5].tracks[0].id, out[5].tracks[1].id));
  int deleted = 0;
  for (const TrackFrame& f : out) {
    for (const TrackEvent& e : f.events) {
      if (e.type != TrackEventType::kDeleted) continue;
      ++deleted;
      EXPECT_THAT(e.detail, ::testing::HasSubstr("merged into"));
    }
  }
  EXPECT_EQ(deleted, 1);
}

TEST(TrackFusionMergeSplit, ASplitStartsANewSystemTrackAndTheLowerSensorKeepsTheNumber) {
  // GIVEN both sensors on one target until t = 10 s, then sensor 2's track 5 km away
  const std::vector<TrackFrame> out = run(10.0, 5000.0);
  ASSERT_EQ(out[5].tracks.size(), 1u);
  const std::int64_t number = out[5].tracks[0].id;
  const TrackFrame& last = out.back();
  ASSERT_EQ(last.tracks.size(), 2u);
  for (const TrackReport& t : last.tracks) {
    ASSERT_EQ(t.sources.size(), 1u);
    if (t.sources[0].sensor == 1) {
      EXPECT_EQ(t.id, number);
    } else {
      EXPECT_NE(t.id, number);
    }
  }
}

}  // namespace
}  // namespace skytrack::fusion
