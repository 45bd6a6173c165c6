// SensorTimeline: a sensor whose clock disagrees with the tracks' time is held while another
// sensor goes on in it, rejoins when it agrees, and takes the tracks only once it is alone.
#include "skytrack/pipeline/sensor_timeline.hpp"

#include <gtest/gtest.h>

namespace skytrack {
namespace {

using enum SensorTimeline::Placement;
constexpr double kMaxJump = 600.0;
constexpr double kYears = 50.0 * 365.25 * 86400.0;

/// Places and, unless held, feeds.
SensorTimeline::Placement step(SensorTimeline& timeline, std::uint32_t id, double time,
                               bool restarted = false) {
  const auto placement = timeline.place(id, time, restarted, kMaxJump);
  if (placement != kHeld) timeline.fed(id, time);
  return placement;
}

TEST(SensorTimeline, SensorsOnOneTimeAreFedAsUsual) {
  SensorTimeline timeline;
  for (int k = 0; k < 10; ++k) {
    EXPECT_EQ(step(timeline, 1, 4.0 * k), kOnTime);
    EXPECT_EQ(step(timeline, 2, 4.0 * k + 1.0), kOnTime);
  }
  EXPECT_DOUBLE_EQ(*timeline.time(), 37.0);
}

TEST(SensorTimeline, AClockRestartYearsAheadIsHeldWhileAnotherSensorGoesOn) {
  // GIVEN two sensors on one time
  SensorTimeline timeline;
  step(timeline, 1, 0.0);
  step(timeline, 2, 1.0);
  // WHEN sensor 2's clock restarts fifty years ahead (its own clock accepted it), and its
  // batches go on from there while sensor 1 goes on
  EXPECT_EQ(step(timeline, 2, kYears, true), kHeld);
  for (int k = 1; k < 400; ++k) {
    EXPECT_EQ(step(timeline, 1, 4.0 * k), kOnTime);
    // THEN sensor 2 stays held, however long its own clock runs
    EXPECT_EQ(step(timeline, 2, kYears + 4.0 * k), kHeld) << k;
  }
  // ... and the tracks' time is sensor 1's
  EXPECT_DOUBLE_EQ(*timeline.time(), 4.0 * 399);
  // AND it rejoins (its looks restart) once its time agrees again
  EXPECT_EQ(step(timeline, 2, 4.0 * 399 + 1.0, true), kRejoins);
  EXPECT_EQ(step(timeline, 2, 4.0 * 400 + 1.0), kOnTime);
}

TEST(SensorTimeline, ANewSensorOnAnotherEpochIsHeldNotFollowed) {
  SensorTimeline timeline;
  step(timeline, 1, 100.0);
  EXPECT_EQ(step(timeline, 7, 100.0 + kYears), kHeld);
  EXPECT_EQ(step(timeline, 7, 100.0 - kYears), kHeld);
  EXPECT_EQ(step(timeline, 1, 104.0), kOnTime);
  EXPECT_DOUBLE_EQ(*timeline.time(), 104.0);
}

TEST(SensorTimeline, AHeldSensorTakesTheTracksOnceTheOthersAreSilentForMaxJump) {
  // GIVEN sensor 2 held on a new epoch after sensor 1 was last heard
  SensorTimeline timeline;
  step(timeline, 1, 0.0);
  step(timeline, 2, 1.0);
  ASSERT_EQ(step(timeline, 2, 1e6, true), kHeld);
  // WHEN sensor 1 is never heard again
  // THEN sensor 2 stays held for max_time_jump of its own time, and then the tracks restart
  // on its clock
  EXPECT_EQ(step(timeline, 2, 1e6 + kMaxJump), kHeld);
  EXPECT_EQ(step(timeline, 2, 1e6 + kMaxJump + 4.0), kNewTimeline);
  EXPECT_DOUBLE_EQ(*timeline.time(), 1e6 + kMaxJump + 4.0);
  // ... and sensor 1, back on its old time, is now the one held
  EXPECT_EQ(step(timeline, 1, 8.0, true), kHeld);
}

TEST(SensorTimeline, AnotherSensorHeardRestartsTheSilenceCount) {
  SensorTimeline timeline;
  step(timeline, 1, 0.0);
  ASSERT_EQ(step(timeline, 2, 1e6), kHeld);
  EXPECT_EQ(step(timeline, 2, 1e6 + 500.0), kHeld);
  step(timeline, 1, 4.0);  // sensor 1 is heard: sensor 2 is not alone
  EXPECT_EQ(step(timeline, 2, 1e6 + 700.0), kHeld);
  EXPECT_EQ(step(timeline, 2, 1e6 + 1300.0), kHeld);
  EXPECT_EQ(step(timeline, 2, 1e6 + 1301.0), kNewTimeline);
}

TEST(SensorTimeline, ALoneSensorsClockRestartRestartsTheTracks) {
  SensorTimeline timeline;
  step(timeline, 1, 400.0);
  EXPECT_EQ(step(timeline, 1, 8.0, true), kNewTimeline);
  EXPECT_EQ(step(timeline, 1, 12.0), kOnTime);
}

TEST(SensorTimeline, AClockRestartOntoAnotherSensorsTimeRejoins) {
  SensorTimeline timeline;
  step(timeline, 1, 0.0);
  step(timeline, 2, kYears);  // held: sensor 1 is on the tracks' time
  EXPECT_EQ(step(timeline, 2, 9.0, true), kRejoins);
  EXPECT_EQ(step(timeline, 1, 12.0), kOnTime);
}

TEST(SensorTimeline, WhenEverySensorRestartsTheTracksFollowTheLast) {
  // The common time source restarts: sensor 1 first (held: sensor 2 is still on the old
  // time), then sensor 2 (no sensor left on the old time: new timeline), then sensor 1 rejoins.
  SensorTimeline timeline;
  step(timeline, 1, 5000.0);
  step(timeline, 2, 5001.0);
  EXPECT_EQ(step(timeline, 1, 10.0, true), kHeld);
  EXPECT_EQ(step(timeline, 2, 11.0, true), kNewTimeline);
  EXPECT_EQ(step(timeline, 1, 14.0), kOnTime);
}

}  // namespace
}  // namespace skytrack
