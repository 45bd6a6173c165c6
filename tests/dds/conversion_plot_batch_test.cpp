// PlotScan -> PlotBatch -> PlotScan round trips and errors for malformed PlotBatch samples.
#include "skytrack/dds/conversion.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "conversion_test_support.hpp"

namespace skytrack::dds {
namespace {

using test::cartesian_plot;
using test::full_sigma;
using test::polar_plot;
using test::scan_with;
using ::testing::HasSubstr;

PlotScan round_trip(const PlotScan& scan) {
  auto sample = to_dds(scan);
  EXPECT_TRUE(sample) << sample.error().message;
  auto back = from_dds(sample->get());
  EXPECT_TRUE(back) << back.error().message;
  return back ? *back : PlotScan{};
}

TEST(PlotBatchConversion, PolarPlotsRoundTripWithAndWithoutOptionalValues) {
  // GIVEN one bare polar plot and one with every optional value and a per-plot sigma
  Plot partial = polar_plot(2, false);
  partial.elevation = 0.05;  // AND one with only some optionals
  partial.sigma.azimuth = 0.001;
  const PlotScan scan = scan_with({polar_plot(0, false), polar_plot(1, true), partial});
  EXPECT_EQ(round_trip(scan), scan);  // THEN the round trip is exact
}

TEST(PlotBatchConversion, TransponderAttributesRoundTripWhereSomePlotsCarryThem) {
  // GIVEN secondary-radar plots: one with every attribute, one with a code only, one bare
  Plot full = polar_plot(0, false), code_only = polar_plot(1, false);
  full.mode3a = 02270;
  full.mode_s = 0xFFFFFF;
  full.flight_level = 221.0;
  code_only.mode3a = 0;
  const PlotScan scan = scan_with({full, code_only, polar_plot(2, false)});
  EXPECT_EQ(round_trip(scan), scan);  // THEN the round trip is exact
  // AND a batch without them sends empty sequences
  auto bare = to_dds(scan_with({polar_plot(0, false)}));
  ASSERT_TRUE(bare);
  EXPECT_EQ(bare->get().plot_mode3a._length, 0u);
  EXPECT_EQ(bare->get().plot_flight_level._length, 0u);
}

TEST(PlotBatchConversion, TransponderSequencesOfTheWrongLengthOrRangeAreErrors) {
  Plot plot = polar_plot(0, false);
  plot.mode3a = 01234;
  auto sample = to_dds(scan_with({plot, polar_plot(1, false)}));
  ASSERT_TRUE(sample);
  skytrack_dds_PlotBatch& b = sample->get();
  b.plot_mode3a._buffer[1] = 010000;  // 13 bits
  auto range = from_dds(b);
  ASSERT_FALSE(range);
  EXPECT_THAT(range.error().message, HasSubstr("plot_mode3a[1]: out of range"));
  b.plot_mode3a._buffer[1] = -1;
  b.plot_mode3a._length = 1;
  auto length = from_dds(b);
  ASSERT_FALSE(length);
  EXPECT_THAT(length.error().message, HasSubstr("transponder"));
}

TEST(PlotBatchConversion, CartesianPlotsRoundTripWithAndWithoutZ) {
  Plot with_sigma = cartesian_plot(3, 120.0);
  with_sigma.sigma.x = 2.5;
  with_sigma.sigma.y = 2.5;
  with_sigma.snr_db = 9.0;
  const PlotScan scan =
      scan_with({cartesian_plot(0, std::nullopt), cartesian_plot(1, 80.0), with_sigma});
  EXPECT_EQ(round_trip(scan), scan);
}

TEST(PlotBatchConversion, ScanSigmaPartiallyPresentRoundTrips) {
  PlotScan scan = scan_with({polar_plot(0, false), cartesian_plot(1, std::nullopt)});
  scan.sigma = {};
  scan.sigma.elevation = 0.004;
  scan.sigma.z = 30.0;
  EXPECT_EQ(round_trip(scan), scan);
  scan.sigma = full_sigma();
  EXPECT_EQ(round_trip(scan), scan);
  scan.sigma = {};
  EXPECT_EQ(round_trip(scan), scan);
}

TEST(PlotBatchConversion, EmptyPlotListRoundTrips) {
  const PlotScan scan = scan_with({});
  auto sample = to_dds(scan);
  ASSERT_TRUE(sample);
  EXPECT_EQ(sample->get().plot_ids._length, 0u);
  EXPECT_EQ(sample->get().plot_values._length, 0u);
  EXPECT_EQ(round_trip(scan), scan);
}

TEST(PlotBatchConversion, FlagsAndValuesFollowTheIdlLayout) {
  const PlotScan scan = scan_with({polar_plot(10, false), cartesian_plot(11, 80.0)});
  auto sample = to_dds(scan);
  ASSERT_TRUE(sample);
  const skytrack_dds_PlotBatch& b = sample->get();
  EXPECT_EQ(b.sigma_flags, 0b11u);  // range and azimuth
  EXPECT_EQ(b.plot_ids._buffer[1], 11);
  EXPECT_EQ(b.plot_flags._buffer[0], (1u << kPlotRange) | (1u << kPlotAzimuth));
  EXPECT_EQ(b.plot_flags._buffer[1],
            kPlotFlagCartesian | (1u << kPlotX) | (1u << kPlotY) | (1u << kPlotZ));
  EXPECT_EQ(b.plot_values._buffer[kPlotRange], 35130.5);
  EXPECT_EQ(b.plot_values._buffer[kPlotStride + kPlotZ], 80.0);
  EXPECT_EQ(b.plot_values._buffer[kPlotStride + kPlotRange], 0.0);  // absent -> 0
}

TEST(PlotBatchConversion, ReusedSampleAndScanKeepRoundTripping) {
  // GIVEN a sample and a scan reused for a large, a small and a large batch
  PlotBatchSample sample;
  PlotScan back;
  for (const std::size_t n : {300u, 2u, 500u}) {
    std::vector<Plot> plots;
    for (std::size_t i = 0; i < n; ++i) {
      const auto id = static_cast<std::int64_t>(i);
      plots.push_back(i % 2 ? polar_plot(id, i % 3 == 0) : cartesian_plot(id, 1.0 * i));
    }
    const PlotScan scan = scan_with(std::move(plots));
    ASSERT_TRUE(to_dds(scan, sample));
    ASSERT_TRUE(from_dds(sample.get(), back));
    EXPECT_EQ(back, scan);  // THEN every batch round-trips
  }
}

TEST(PlotBatchConversion, PlotMissingItsFormValuesGetsNaNForThePipelineToReject) {
  auto sample = to_dds(scan_with({polar_plot(0, false), cartesian_plot(1, std::nullopt)}));
  ASSERT_TRUE(sample);
  sample->get().plot_flags._buffer[0] = 0;                   // polar, no range/azimuth
  sample->get().plot_flags._buffer[1] = kPlotFlagCartesian;  // Cartesian, no x/y
  auto back = from_dds(sample->get());
  ASSERT_TRUE(back);
  EXPECT_TRUE(std::isnan(back->plots[0].range) && std::isnan(back->plots[0].azimuth));
  EXPECT_TRUE(std::isnan(back->plots[1].x) && std::isnan(back->plots[1].y));
}

TEST(PlotBatchConversion, WrongSequenceLengthsAreErrorsNamingTheField) {
  auto sample = to_dds(scan_with({polar_plot(0, true), polar_plot(1, false)}));
  ASSERT_TRUE(sample);
  skytrack_dds_PlotBatch& b = sample->get();
  b.plot_values._length -= 1;
  auto values = from_dds(b);
  ASSERT_FALSE(values);
  EXPECT_THAT(values.error().message, HasSubstr("plot_values"));
  b.plot_values._length += 1;
  b.plot_flags._length -= 1;
  auto flags = from_dds(b);
  ASSERT_FALSE(flags);
  EXPECT_THAT(flags.error().message, HasSubstr("plot_flags"));
  b.plot_flags._length += 1;
  EXPECT_TRUE(from_dds(b));
}

TEST(PlotBatchConversion, LengthWithoutBufferIsAnErrorNamingTheField) {
  skytrack_dds_PlotBatch b{};
  b.plot_ids._length = 2;
  auto back = from_dds(b);
  ASSERT_FALSE(back);
  EXPECT_THAT(back.error().message, HasSubstr("plot_ids"));
}

}  // namespace
}  // namespace skytrack::dds
