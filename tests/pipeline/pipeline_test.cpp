#include <cmath>
#include <limits>
#include <utility>

#include <gtest/gtest.h>

#include "../tracking/tracker_test_support.hpp"

namespace skytrack {
namespace {

// The daemon's per-batch call cannot throw (std::bad_alloc terminates, by design).
static_assert(noexcept(std::declval<Pipeline&>().process(std::declval<const PlotScan&>())));

PlotScan batch(std::uint64_t number, double time, std::vector<Plot> plots) {
  PlotScan scan;
  scan.sensor = 1;
  scan.scan = number;
  scan.time = time;
  scan.sigma.x = 10.0;
  scan.sigma.y = 10.0;
  scan.plots = std::move(plots);
  return scan;
}

using testing::cartesian;

TEST(Pipeline, RejectsOutOfOrderAndDuplicateBatchesAndCountsThem) {
  auto pipeline = Pipeline::create(testing::test_profile());
  ASSERT_TRUE(pipeline);
  EXPECT_TRUE(pipeline->process(batch(5, 5.0, {})).accepted);
  const ScanResult& duplicate = pipeline->process(batch(5, 5.0, {}));
  EXPECT_FALSE(duplicate.accepted);
  EXPECT_EQ(duplicate.reason, batch_reason::kDuplicateScan);
  EXPECT_NE(duplicate.rejection.find("sensor 1 scan 5: duplicate scan"), std::string::npos);
  EXPECT_FALSE(pipeline->process(batch(4, 6.0, {})).accepted);
  EXPECT_FALSE(pipeline->process(batch(6, 4.0, {})).accepted);  // time goes backwards
  EXPECT_FALSE(pipeline->process(batch(7, std::nan(""), {})).accepted);
  EXPECT_TRUE(pipeline->process(batch(8, 8.0, {})).accepted);
  EXPECT_EQ(pipeline->counters().scans_rejected, 4u);
  EXPECT_EQ(pipeline->counters().scans_processed, 2u);
}

TEST(Pipeline, BadPlotsAndBatchesLeaveTheTracksUntouched) {
  // GIVEN a clean stream of one target, and the same stream with bad input mixed in
  std::vector<PlotScan> clean;
  for (int k = 0; k < 20; ++k) {
    clean.push_back(batch(static_cast<std::uint64_t>(k), k, {cartesian(0, 100.0 * k, 500.0)}));
  }
  auto reference = Pipeline::create(testing::test_profile());
  auto tested = Pipeline::create(testing::test_profile());
  ASSERT_TRUE(reference && tested);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const PlotScan& scan : clean) {
    const TrackFrame expected = reference->process(scan).frame;
    // WHEN each good batch also carries NaN and negative-range plots, and is followed by a
    // duplicate and an out-of-order copy
    PlotScan dirty = scan;
    dirty.plots.push_back(cartesian(1, nan, 0.0));
    Plot negative;
    negative.id = 2;
    negative.range = -5.0;
    negative.azimuth = 0.1;
    dirty.plots.push_back(negative);
    const ScanResult& result = tested->process(dirty);
    ASSERT_TRUE(result.accepted);
    // THEN the tracks are exactly those of the clean stream
    EXPECT_EQ(result.frame.tracks, expected.tracks);
    EXPECT_EQ(result.report.plots_invalid, 2);
    EXPECT_FALSE(tested->process(dirty).accepted);
    PlotScan older = scan;
    older.scan = scan.scan == 0 ? 0 : scan.scan - 1;
    EXPECT_FALSE(tested->process(older).accepted);
  }
  EXPECT_EQ(tested->counters().plots_invalid, 40u);
  EXPECT_FALSE(reference->process(clean.back()).accepted);  // sanity: same rules
}

TEST(Pipeline, ChoosesTheTrackerDimensionFromThePlots) {
  const config::TrackingProfile automatic = testing::test_profile();
  PlotScan flat = batch(0, 0.0, {cartesian(0, 1.0, 2.0)});
  EXPECT_EQ(tracker_dimension(automatic, flat), 2);
  flat.plots[0].z = 100.0;
  EXPECT_EQ(tracker_dimension(automatic, flat), 3);
  config::TrackingProfile fixed = automatic;
  fixed.dimension = 2;
  EXPECT_EQ(tracker_dimension(fixed, flat), 2);
}

TEST(Pipeline, FlightLevelsOnPolarPlotsGiveAThreeDimensionalTracker) {
  // GIVEN secondary-radar plots: slant range, azimuth and a flight level, no elevation
  const config::TrackingProfile automatic = testing::test_profile();
  Plot reply;
  reply.range = 40e3;
  reply.azimuth = 0.5;
  PlotScan scan = batch(0, 0.0, {reply});
  EXPECT_EQ(tracker_dimension(automatic, scan), 2);
  scan.plots[0].flight_level = 350.0;
  // THEN dimension auto tracks height
  EXPECT_EQ(tracker_dimension(automatic, scan), 3);
  // AND a Cartesian plot's flight level is not a height measurement
  PlotScan cartesian_scan = batch(0, 0.0, {cartesian(0, 1.0, 2.0)});
  cartesian_scan.plots[0].flight_level = 350.0;
  EXPECT_EQ(tracker_dimension(automatic, cartesian_scan), 2);
}

TEST(Pipeline, ThreeDimensionalProfileRefusesPlotsWithoutHeight) {
  // GIVEN a profile that asks for 3-D and a secondary radar's plots without flight levels
  config::TrackingProfile profile = testing::test_profile();
  profile.identity.name = "forced";
  profile.dimension = 3;
  auto pipeline = Pipeline::create(profile);
  ASSERT_TRUE(pipeline);
  Plot reply;
  reply.range = 40e3;
  reply.azimuth = 0.5;
  // WHEN the first batch comes (an empty one before it says nothing and passes)
  EXPECT_TRUE(pipeline->process(batch(0, 0.0, {})).accepted);
  const ScanResult& refused = pipeline->process(batch(1, 4.0, {reply}));
  // THEN it is refused, and the message says why and what to do
  EXPECT_FALSE(refused.accepted);
  EXPECT_TRUE(refused.refused);
  EXPECT_NE(refused.rejection.find("'forced' asks for 3-D tracking (dimension: 3)"),
            std::string::npos);
  EXPECT_NE(refused.rejection.find("carry no height"), std::string::npos);
  EXPECT_NE(refused.rejection.find("dimension: auto or 2"), std::string::npos);
  EXPECT_EQ(pipeline->counters().scans_rejected, 1u);
  // AND a batch whose plots carry flight levels is served, in 3-D
  reply.flight_level = 300.0;
  EXPECT_TRUE(pipeline->process(batch(2, 8.0, {reply})).accepted);
  // AND a profile with dimension auto takes the same height-less plots in 2-D
  auto automatic = Pipeline::create(testing::test_profile());
  reply.flight_level.reset();
  EXPECT_TRUE(automatic->process(batch(1, 4.0, {reply})).accepted);
}

TEST(Pipeline, AnEmptyFirstBatchLeavesTheDimensionToTheFirstPlots) {
  // GIVEN dimension auto, an empty first batch, then flight-level plots of one aircraft
  auto pipeline = Pipeline::create(testing::test_profile());
  ASSERT_TRUE(pipeline);
  EXPECT_TRUE(pipeline->process(batch(0, 0.0, {})).accepted);
  int dims = 0;
  for (int k = 1; k <= 6; ++k) {
    Plot reply;
    reply.range = 40e3 + 800.0 * k;
    reply.azimuth = 0.5;
    reply.flight_level = 300.0;
    const ScanResult& r = pipeline->process(batch(k, 4.0 * k, {reply}));
    ASSERT_TRUE(r.accepted);
    for (const TrackReport& t : r.frame.tracks) dims = t.dims;
  }
  // THEN its track is 3-D
  EXPECT_EQ(dims, 3);
}

}  // namespace
}  // namespace skytrack
