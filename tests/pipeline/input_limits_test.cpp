// Plots and batches beyond the profile's input limits (input_limits: max_range, max_time_jump)
// are refused and counted, and never change the tracks of the good ones.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "../tracking/tracker_test_support.hpp"

namespace skytrack {
namespace {

constexpr double kFiftyYears = 50.0 * 365.25 * 86400.0;

using testing::cartesian;

/// Two targets seen by sensor 1 every 4 s, as Cartesian plots.
PlotScan clean_batch(std::uint64_t k, std::uint32_t sensor = 1) {
  PlotScan scan;
  scan.sensor = sensor;
  scan.scan = k;
  scan.time = 4.0 * static_cast<double>(k);
  scan.sigma.x = 10.0;
  scan.sigma.y = 10.0;
  const double t = scan.time;
  scan.plots = {cartesian(0, 20e3 + 150.0 * t, 5e3), cartesian(1, -10e3, 30e3 - 100.0 * t)};
  return scan;
}

/// Sensor 2's empty batch k on sensor 1's clock, covering a sector away from the targets.
PlotScan other(std::uint64_t k) {
  PlotScan scan = clean_batch(k, 2);
  scan.plots.clear();
  scan.coverage = AzimuthSector{2.5, 3.0};
  return scan;
}

std::vector<TrackFrame> frames_of(Pipeline& pipeline, const std::vector<PlotScan>& batches) {
  std::vector<TrackFrame> frames;
  for (const PlotScan& b : batches) {
    const ScanResult& r = pipeline.process(b);
    if (r.accepted) frames.push_back(r.frame);
  }
  return frames;
}

TEST(InputLimits, PlotsBeyondThePhysicalLimitsAreDroppedAndCountedByReason) {
  const config::TrackingProfile profile = testing::test_profile();
  // GIVEN plots each beyond one limit, next to a good one
  Plot far;  // beyond 2 000 km
  far.range = 2.5e6;
  far.azimuth = 0.3;
  Plot huge = far;  // finite but absurd (the clutter map's cast overflowed on it)
  huge.range = 5e22;
  Plot spun = far;
  spun.range = 40e3;
  spun.azimuth = 7.0;
  Plot steep = spun;
  steep.azimuth = 0.3;
  steep.elevation = 2.0;
  Plot distant = cartesian(9, 3e6, 1e3);
  Plot late = cartesian(10, 1e3, 1e3);
  late.time = 1000.0 + kFiftyYears;
  Plot vague = cartesian(11, 1e3, 1e3);
  vague.sigma.x = 1e30;
  Plot sharp = cartesian(13, 1e3, 1e3);  // its variance would square to zero
  sharp.sigma.y = 1e-300;
  Plot pinpoint = spun;
  pinpoint.azimuth = 0.3;
  pinpoint.sigma.azimuth = 1e-200;
  const Plot good = cartesian(12, 1e3, 1e3);
  // THEN each is refused with its reason, the good one passes
  const auto why = [&](const Plot& p) {
    return invalid_plot_reason(p, profile.input_limits, 1000.0);
  };
  EXPECT_EQ(why(far), "range beyond max_range");
  EXPECT_EQ(why(huge), "range beyond max_range");
  EXPECT_EQ(why(spun), "azimuth outside -2pi to 2pi");
  EXPECT_EQ(why(steep), "elevation outside -pi/2 to pi/2");
  EXPECT_EQ(why(distant), "range beyond max_range");
  EXPECT_EQ(why(late), "plot time beyond max_time_jump of its batch's");
  EXPECT_EQ(why(vague), "sigma beyond max_range");
  EXPECT_EQ(why(sharp), "sigma below 1 mm (or 1 mm/s)");
  EXPECT_EQ(why(pinpoint), "angle sigma below 1 microradian");
  EXPECT_FALSE(why(good));
  // AND a radar that reports azimuth in [-pi, pi) or [0, 2pi) is served either way
  Plot west = spun;
  west.azimuth = -std::numbers::pi / 2.0;
  EXPECT_FALSE(why(west));
  west.azimuth = 1.5 * std::numbers::pi;
  EXPECT_FALSE(why(west));

  // AND in a stream, the tracks are those without them, the bad plots counted
  std::vector<PlotScan> clean, dirty;
  for (std::uint64_t k = 0; k < 12; ++k) {
    clean.push_back(clean_batch(k));
    dirty.push_back(clean.back());
    for (const Plot& bad : {far, huge, spun, steep, distant}) dirty.back().plots.push_back(bad);
  }
  auto reference = Pipeline::create(profile);
  auto tested = Pipeline::create(profile);
  ASSERT_TRUE(reference && tested);
  const auto expected = frames_of(*reference, clean);
  const auto got = frames_of(*tested, dirty);
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t i = 0; i < got.size(); ++i) EXPECT_EQ(got[i].tracks, expected[i].tracks);
  EXPECT_EQ(tested->counters().plots_invalid, 5u * 12u);
}

TEST(InputLimits, OneBatchYearsAheadIsRefusedAndTheSensorGoesOn) {
  // GIVEN a stream with confirmed tracks, and the same stream with one batch dated fifty
  // years ahead inserted (a corrupted or hostile time)
  const config::TrackingProfile profile = testing::test_profile();
  std::vector<PlotScan> clean, dirty;
  for (std::uint64_t k = 0; k < 20; ++k) {
    clean.push_back(clean_batch(2 * k));
    dirty.push_back(clean.back());
    if (k == 8) {
      PlotScan corrupt = clean_batch(2 * k + 1);
      corrupt.time += kFiftyYears;
      dirty.push_back(corrupt);
    }
  }
  auto reference = Pipeline::create(profile);
  auto tested = Pipeline::create(profile);
  ASSERT_TRUE(reference && tested);
  const auto expected = frames_of(*reference, clean);
  // WHEN the dirty stream is tracked
  const auto got = frames_of(*tested, dirty);
  // THEN only the corrupted batch is refused, as a time jump, and every later batch of the
  // sensor is tracked exactly as without it (before the fix, all were skipped as "time goes
  // backwards")
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t i = 0; i < got.size(); ++i) EXPECT_EQ(got[i].tracks, expected[i].tracks);
  EXPECT_EQ(tested->counters().scans_rejected, 1u);
  EXPECT_EQ(tested->counters().clock_restarts, 0u);
  EXPECT_FALSE(expected.back().tracks.empty());
}

TEST(InputLimits, ASensorWhoseClockRestartsIsFollowedWithNewTracks) {
  // GIVEN tracks on a sensor, which then restarts: numbers and times from zero
  auto pipeline = Pipeline::create(testing::test_profile());
  ASSERT_TRUE(pipeline);
  for (std::uint64_t k = 100; k < 112; ++k) ASSERT_TRUE(pipeline->process(clean_batch(k)).accepted);
  ASSERT_FALSE(pipeline->process(clean_batch(111)).frame.tracks.empty());
  // WHEN its batches go on from its new clock
  EXPECT_EQ(pipeline->process(clean_batch(0)).reason, batch_reason::kOutOfOrderScan);
  EXPECT_FALSE(pipeline->process(clean_batch(1)).accepted);
  const ScanResult& third = pipeline->process(clean_batch(2));
  // THEN the third restarts the clock, and the old tracks (whose times no longer compare) go
  EXPECT_TRUE(third.accepted);
  EXPECT_TRUE(third.clock_restarted);
  EXPECT_TRUE(third.tracks_restarted);
  EXPECT_TRUE(third.frame.tracks.empty());
  EXPECT_EQ(pipeline->counters().clock_restarts, 1u);
  // AND the targets are tracked again on the new clock
  std::size_t confirmed = 0;
  for (std::uint64_t k = 3; k < 12; ++k) {
    const ScanResult& r = pipeline->process(clean_batch(k));
    ASSERT_TRUE(r.accepted);
    confirmed = static_cast<std::size_t>(r.report.confirmed);
  }
  EXPECT_EQ(confirmed, 2u);
}

TEST(InputLimits, AnotherSensorsCorruptTimeLeavesASensorsTracksUnchanged) {
  // GIVEN sensor 1's stream with sensor 2's batches (a sector away from the targets) on the
  // same clock, and the same with sensor 2's very first batch dated fifty years ahead
  const config::TrackingProfile profile = testing::test_profile();
  auto reference = Pipeline::create(profile);
  auto tested = Pipeline::create(profile);
  ASSERT_TRUE(reference && tested);
  PlotScan corrupt = other(0);
  corrupt.time += kFiftyYears;
  ASSERT_TRUE(tested->process(corrupt).accepted);  // a first batch: nothing to compare with
  for (std::uint64_t k = 0; k < 15; ++k) {
    const TrackFrame expected = reference->process(clean_batch(k)).frame;
    // THEN sensor 1's tracks are the same, before and after sensor 2's clock restarts on
    // sensor 1's (its new clock agrees with sensor 1's: the tracks go on)
    EXPECT_EQ(tested->process(clean_batch(k)).frame.tracks, expected.tracks) << "scan " << k;
    reference->process(other(k + 1));
    tested->process(other(k + 1));
  }
  EXPECT_EQ(tested->counters().clock_restarts, 1u);
  EXPECT_FALSE(reference->process(clean_batch(15)).frame.tracks.empty());
}

TEST(InputLimits, AnotherSensorsHijackedClockNeitherWipesNorMovesTheTracks) {
  // GIVEN sensor 1's stream with sensor 2's empty batches (a sector away) on the same clock,
  // and the same with three of sensor 2's batches dated fifty years ahead, each following
  // the one before: enough to restart sensor 2's own clock
  const config::TrackingProfile profile = testing::test_profile();
  auto reference = Pipeline::create(profile);
  auto tested = Pipeline::create(profile);
  ASSERT_TRUE(reference && tested);
  std::size_t held = 0;
  for (std::uint64_t k = 0; k < 24; ++k) {
    const TrackFrame expected = reference->process(clean_batch(k)).frame;
    // THEN sensor 1's tracks are the same throughout (before the fix they all restarted
    // when sensor 2's clock did, and sensor 1's batches then went to tracks 50 years ahead)
    EXPECT_EQ(tested->process(clean_batch(k)).frame.tracks, expected.tracks) << "scan " << k;
    reference->process(other(k));
    if (k >= 8 && k < 11) {
      PlotScan hijack = other(100 + k);
      hijack.time += kFiftyYears;
      const ScanResult& r = tested->process(hijack);
      EXPECT_FALSE(r.accepted);
      if (r.reason == batch_reason::kClockDisagrees) ++held;
    } else {
      // AND sensor 2's real batches, refused after the hijack by its own clock, restart it
      // on sensor 1's time three batches later and are tracked again
      tested->process(other(k < 11 ? k : 200 + k));
    }
  }
  EXPECT_EQ(held, 1u);  // the third, which restarted sensor 2's clock onto the hijacked time
  EXPECT_EQ(tested->counters().clock_restarts, 2u);
  EXPECT_FALSE(reference->process(clean_batch(24)).frame.tracks.empty());
}

}  // namespace
}  // namespace skytrack
