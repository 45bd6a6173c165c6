#include <gtest/gtest.h>

#include "skytrack/tracking/track_life.hpp"

namespace skytrack {
namespace {

config::TrackLifeSpec spec() {
  config::TrackLifeSpec s;
  s.confirm_m = 3;
  s.confirm_n = 4;
  s.delete_tentative_misses = 2;
  s.delete_confirmed_misses = 3;
  s.delete_position_sigma = 1000.0;
  return s;
}

TEST(TrackLife, ConfirmsOnMOfNCountedFromTheFirstPlot) {
  // GIVEN a track initiated from 2 plots in 2 scans
  TrackLife life = initiated_life(2, 2);
  // WHEN it misses once and then hits: 3 hits in the last 4 scans
  EXPECT_FALSE(advance_life(life, false, 10.0, spec()).confirmed);
  EXPECT_EQ(life.status, TrackStatus::kTentative);
  const LifeChange change = advance_life(life, true, 10.0, spec());
  // THEN it is confirmed
  EXPECT_TRUE(change.confirmed);
  EXPECT_EQ(life.status, TrackStatus::kConfirmed);
}

TEST(TrackLife, TentativeTrackDiesAfterItsMissLimit) {
  TrackLife life = initiated_life(2, 2);
  advance_life(life, false, 10.0, spec());
  const LifeChange change = advance_life(life, false, 10.0, spec());
  EXPECT_TRUE(change.deleted);
  EXPECT_EQ(life.status, TrackStatus::kDeleted);
}

TEST(TrackLife, ConfirmedTrackCoastsThenDiesAfterKMisses) {
  TrackLife life = initiated_life(3, 3);
  advance_life(life, true, 10.0, spec());
  ASSERT_EQ(life.status, TrackStatus::kConfirmed);
  EXPECT_TRUE(advance_life(life, false, 10.0, spec()).started_coasting);
  EXPECT_EQ(life.status, TrackStatus::kCoasting);
  EXPECT_FALSE(advance_life(life, false, 10.0, spec()).started_coasting);  // only once
  EXPECT_TRUE(advance_life(life, false, 10.0, spec()).deleted);            // third miss
}

TEST(TrackLife, CoastingTrackRecoversOnAHit) {
  TrackLife life = initiated_life(3, 3);
  advance_life(life, true, 10.0, spec());
  advance_life(life, false, 10.0, spec());
  advance_life(life, true, 10.0, spec());
  EXPECT_EQ(life.status, TrackStatus::kConfirmed);
  EXPECT_EQ(life.consecutive_misses, 0);
}

TEST(TrackLife, UncertaintyBeyondTheLimitDeletes) {
  TrackLife life = initiated_life(3, 3);
  advance_life(life, true, 10.0, spec());
  EXPECT_TRUE(advance_life(life, true, 5000.0, spec()).deleted);
}

}  // namespace
}  // namespace skytrack
