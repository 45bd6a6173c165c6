#include "skytrack/pipeline/batch_clock.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace skytrack {
namespace {

constexpr double kMaxJump = 600.0;  // [s] the default input_limits.max_time_jump
constexpr double kFiftyYears = 50.0 * 365.25 * 86400.0;

TEST(BatchClock, NamesDuplicateOutOfOrderBackwardAndFarAheadBatches) {
  BatchClock clock;
  ASSERT_TRUE(clock.admit(5, 20.0, kMaxJump).refusal.empty());
  EXPECT_EQ(clock.admit(5, 20.0, kMaxJump).refusal, batch_reason::kDuplicateScan);
  EXPECT_EQ(clock.admit(3, 12.0, kMaxJump).refusal, batch_reason::kOutOfOrderScan);
  EXPECT_EQ(clock.admit(6, 19.0, kMaxJump).refusal, batch_reason::kTimeBackwards);
  EXPECT_EQ(clock.admit(6, 20.0 + kMaxJump + 1.0, kMaxJump).refusal, batch_reason::kTimeJump);
  EXPECT_EQ(clock.admit(6, NAN, kMaxJump).refusal, batch_reason::kNonFiniteTime);
  // None of them moved the clock: the next batch in order is taken.
  EXPECT_TRUE(clock.admit(6, 24.0, kMaxJump).refusal.empty());
  EXPECT_EQ(clock.latest()->scan, 6u);
  // A step of exactly the bound is allowed (a sensor silent for max_time_jump).
  EXPECT_TRUE(clock.admit(7, 24.0 + kMaxJump, kMaxJump).refusal.empty());
}

TEST(BatchClock, OneBatchFarAheadDoesNotLockTheSensorOut) {
  // GIVEN a sensor at 4 s revolutions
  BatchClock clock;
  ASSERT_TRUE(clock.admit(1, 100.0, kMaxJump).refusal.empty());
  // WHEN one batch is dated fifty years ahead (a corrupted time)
  EXPECT_EQ(clock.admit(2, 104.0 + kFiftyYears, kMaxJump).refusal, batch_reason::kTimeJump);
  // THEN every later batch of the sensor is taken, without a restart
  for (std::uint64_t k = 3; k < 10; ++k) {
    const BatchClock::Verdict v = clock.admit(k, 100.0 + 4.0 * static_cast<double>(k), kMaxJump);
    EXPECT_TRUE(v.refusal.empty()) << "scan " << k;
    EXPECT_FALSE(v.restarted);
  }
}

TEST(BatchClock, AFirstBatchFarAheadIsLeftBehindByTheRestartRule) {
  // GIVEN the very first batch dated fifty years ahead: it sets the clock
  BatchClock clock;
  ASSERT_TRUE(clock.admit(1, kFiftyYears, kMaxJump).refusal.empty());
  // WHEN the sensor goes on at its true time
  EXPECT_EQ(clock.admit(2, 8.0, kMaxJump).refusal, batch_reason::kTimeBackwards);
  EXPECT_EQ(clock.admit(3, 12.0, kMaxJump).refusal, batch_reason::kTimeBackwards);
  // THEN the third batch in a row that follows the others restarts the clock
  const BatchClock::Verdict third = clock.admit(4, 16.0, kMaxJump);
  EXPECT_TRUE(third.refusal.empty());
  EXPECT_TRUE(third.restarted);
  EXPECT_DOUBLE_EQ(clock.latest()->time, 16.0);
  EXPECT_TRUE(clock.admit(5, 20.0, kMaxJump).refusal.empty());
}

TEST(BatchClock, ASensorThatRebootsWithNewNumbersAndTimesIsFollowed) {
  BatchClock clock;
  for (std::uint64_t k = 100; k < 110; ++k) {
    ASSERT_TRUE(clock.admit(k, 4.0 * static_cast<double>(k), kMaxJump).refusal.empty());
  }
  // The radar restarts: numbers from 1, times from its power-on.
  EXPECT_EQ(clock.admit(1, 0.5, kMaxJump).refusal, batch_reason::kOutOfOrderScan);
  EXPECT_EQ(clock.admit(2, 4.5, kMaxJump).refusal, batch_reason::kOutOfOrderScan);
  EXPECT_TRUE(clock.admit(3, 8.5, kMaxJump).restarted);
}

TEST(BatchClock, StrayOldBatchesAmongLiveOnesNeverRestartTheClock) {
  // GIVEN a live sensor, and copies of its old batches delivered again among its live ones
  BatchClock clock;
  ASSERT_TRUE(clock.admit(50, 200.0, kMaxJump).refusal.empty());
  for (std::uint64_t k = 51; k < 60; ++k) {
    const double live = 4.0 * static_cast<double>(k);
    const BatchClock::Verdict v = clock.admit(k, live, kMaxJump);
    EXPECT_TRUE(v.refusal.empty());
    // two old batches in a row between live ones: never three, never a restart
    EXPECT_FALSE(clock.admit(k - 40, live - 160.0, kMaxJump).refusal.empty());
    EXPECT_FALSE(clock.admit(k - 39, live - 156.0, kMaxJump).refusal.empty());
  }
  EXPECT_EQ(clock.latest()->scan, 59u);
}

TEST(BatchClock, RefusedBatchesThatDoNotFollowEachOtherNeverRestart) {
  // Garbage times, each refused, do not add up to a restart.
  BatchClock clock;
  ASSERT_TRUE(clock.admit(10, 1000.0, kMaxJump).refusal.empty());
  const double garbage[] = {1e12, 3.0, 5e11, 2.0, 1e15, 0.0};
  std::uint64_t scan = 11;
  for (double t : garbage) EXPECT_FALSE(clock.admit(scan++, t, kMaxJump).restarted);
  EXPECT_DOUBLE_EQ(clock.latest()->time, 1000.0);
}

}  // namespace
}  // namespace skytrack
