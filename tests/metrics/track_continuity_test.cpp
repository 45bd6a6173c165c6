#include "skytrack/metrics/track_continuity.hpp"

#include <gtest/gtest.h>

namespace skytrack::metrics {
namespace {

TEST(TrackContinuity, CountsIdChangesAndFragmentationsOnScriptedSequence) {
  // GIVEN truth 1 matched to: 10 10 - 10 20 (absent) 20 30 -, truth 2 never tracked
  TrackContinuity continuity;
  const std::optional<std::int64_t> none;
  for (const auto& track : {std::optional<std::int64_t>{10}, {10}, none, {10}, {20}}) {
    continuity.observe(1, track);
    continuity.observe(2, none);
  }
  continuity.observe(2, none);  // truth 1 absent from this frame: neither gap nor change
  for (const auto& track : {std::optional<std::int64_t>{20}, {30}, none}) {
    continuity.observe(1, track);
  }
  // THEN truth 1: 10->20, 20->30 = 2 id changes; one re-acquisition after the gap
  EXPECT_EQ(continuity.id_changes(), 2);
  EXPECT_EQ(continuity.fragmentations(), 1);
  const auto per_truth = continuity.per_truth();
  ASSERT_EQ(per_truth.size(), 2u);
  EXPECT_EQ(per_truth[0].truth_id, 1);
  EXPECT_EQ(per_truth[0].frames_present, 8);
  EXPECT_EQ(per_truth[0].frames_tracked, 6);
  EXPECT_EQ(per_truth[0].distinct_tracks, 3);
  EXPECT_EQ(per_truth[0].last_track, 30);
  EXPECT_FALSE(per_truth[0].tracked_now);
  EXPECT_EQ(per_truth[1].frames_present, 6);
  EXPECT_EQ(per_truth[1].frames_tracked, 0);
  EXPECT_EQ(per_truth[1].id_changes + per_truth[1].fragmentations, 0);
}

TEST(TrackContinuity, IdChangeAcrossAGapCountsOnceWithTheFragmentation) {
  // GIVEN 5, untracked, 6: one id change (gaps ignored) and one fragmentation
  TrackContinuity continuity;
  continuity.observe(3, 5);
  continuity.observe(3, std::nullopt);
  continuity.observe(3, std::nullopt);
  continuity.observe(3, 6);
  EXPECT_EQ(continuity.id_changes(), 1);
  EXPECT_EQ(continuity.fragmentations(), 1);
}

TEST(TrackContinuity, LateFirstAcquisitionIsNotAFragmentation) {
  TrackContinuity continuity;
  continuity.observe(4, std::nullopt);
  continuity.observe(4, 8);
  EXPECT_EQ(continuity.fragmentations(), 0);
  EXPECT_EQ(continuity.id_changes(), 0);
}

}  // namespace
}  // namespace skytrack::metrics
