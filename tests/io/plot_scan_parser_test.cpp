#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "skytrack/io/jsonl_reader.hpp"
#include "skytrack/io/jsonl_writer.hpp"

namespace skytrack::io {
namespace {

using ::testing::HasSubstr;

constexpr const char* kContractExample =
    R"({"sensor": 1, "scan": 42, "time": 420.0,
 "platform": {"position": [0.0, 0.0, 8000.0], "velocity": [220.0, 0.0, 0.0],
              "attitude": [0.10, 0.0, 0.0]},
 "sigma": {"range": 15.0, "azimuth": 0.002, "elevation": 0.004, "range_rate": 1.0},
 "plots": [
   {"id": 0, "range": 35120.5, "azimuth": 1.2034, "elevation": -0.21,
    "range_rate": -180.2, "snr_db": 14.2},
   {"id": 1, "x": 1200.0, "y": -340.0, "sigma": {"x": 2.5, "y": 2.5}}
 ]})";

TEST(PlotScanParser, ReadsTheContractExample) {
  const auto parsed = parse_plot_scan(kContractExample);
  ASSERT_TRUE(parsed) << parsed.error().message;
  const PlotScan& scan = parsed->scan;
  EXPECT_EQ(scan.sensor, 1u);
  EXPECT_EQ(scan.scan, 42u);
  EXPECT_DOUBLE_EQ(scan.time, 420.0);
  EXPECT_DOUBLE_EQ(scan.platform.position.z(), 8000.0);
  EXPECT_DOUBLE_EQ(scan.platform.velocity.x(), 220.0);
  EXPECT_DOUBLE_EQ(scan.platform.attitude.x(), 0.10);
  EXPECT_EQ(scan.sigma.range, 15.0);
  EXPECT_FALSE(scan.sigma.x.has_value());
  ASSERT_EQ(scan.plots.size(), 2u);
  EXPECT_EQ(scan.plots[0].form, PlotForm::kPolar);
  EXPECT_DOUBLE_EQ(scan.plots[0].range, 35120.5);
  EXPECT_EQ(scan.plots[0].elevation, -0.21);
  EXPECT_EQ(scan.plots[0].range_rate, -180.2);
  EXPECT_EQ(scan.plots[0].snr_db, 14.2);
  EXPECT_FALSE(scan.plots[0].time.has_value());
  EXPECT_EQ(scan.plots[1].form, PlotForm::kCartesian);
  EXPECT_DOUBLE_EQ(scan.plots[1].y, -340.0);
  EXPECT_EQ(scan.plots[1].sigma.x, 2.5);
  EXPECT_TRUE(parsed->rejected_plots.empty());
}

TEST(PlotScanParser, IgnoresUnknownFields) {
  const auto parsed = parse_plot_scan(
      R"({"sensor":0,"scan":1,"time":1.5,"radar_mode":"tws","plots":[{"id":3,"x":1,"y":2,"doppler_bin":7}]})");
  ASSERT_TRUE(parsed) << parsed.error().message;
  EXPECT_EQ(parsed->scan.plots.size(), 1u);
}

TEST(PlotScanParser, DropsBadPlotsAndKeepsTheRest) {
  const auto parsed = parse_plot_scan(
      R"({"sensor":0,"scan":1,"time":1.0,"plots":[
          {"id":0,"range":100,"azimuth":0.5},
          {"id":1,"range":-5,"azimuth":0.5},
          {"id":2,"range":100,"azimuth":0.5,"x":3,"y":4},
          {"id":3,"snr_db":12},
          {"id":0,"x":1,"y":1},
          {"id":5,"range":"far","azimuth":0.1},
          {"id":6,"range":100}]})");
  ASSERT_TRUE(parsed) << parsed.error().message;
  ASSERT_EQ(parsed->scan.plots.size(), 1u);
  EXPECT_EQ(parsed->scan.plots[0].id, 0);
  ASSERT_EQ(parsed->rejected_plots.size(), 6u);
  EXPECT_THAT(parsed->rejected_plots[0], HasSubstr("plots[1].range: negative"));
  EXPECT_THAT(parsed->rejected_plots[1], HasSubstr("both polar and Cartesian"));
  EXPECT_THAT(parsed->rejected_plots[2], HasSubstr("neither"));
  EXPECT_THAT(parsed->rejected_plots[3], HasSubstr("duplicate id 0"));
  EXPECT_THAT(parsed->rejected_plots[4], HasSubstr("plots[5].range: expected a number"));
  EXPECT_THAT(parsed->rejected_plots[5], HasSubstr("plots[6].azimuth: missing"));
}

TEST(PlotScanParser, ReadsTransponderAttributesAndDropsPlotsWithBadOnes) {
  // GIVEN secondary-radar plots with a Mode 3/A code, a Mode S address and a flight level
  const auto parsed = parse_plot_scan(
      R"({"sensor":0,"scan":1,"time":1.0,"plots":[
          {"id":0,"range":100,"azimuth":0.5,"mode3a":"2270","mode_s":"4ca2D7","flight_level":221},
          {"id":1,"range":100,"azimuth":0.6},
          {"id":2,"range":100,"azimuth":0.7,"mode3a":"2290"},
          {"id":3,"range":100,"azimuth":0.8,"mode_s":"4CA2D"},
          {"id":4,"range":100,"azimuth":0.9,"flight_level":4000},
          {"id":5,"range":100,"azimuth":1.0,"mode3a":2270}]})");
  ASSERT_TRUE(parsed) << parsed.error().message;
  // THEN the attributes are read as numbers, and absent where not given
  ASSERT_EQ(parsed->scan.plots.size(), 2u);
  const Plot& plot = parsed->scan.plots[0];
  EXPECT_EQ(plot.mode3a, 02270);
  EXPECT_EQ(plot.mode_s, 0x4CA2D7u);
  EXPECT_EQ(plot.flight_level, 221.0);
  EXPECT_FALSE(parsed->scan.plots[1].mode3a || parsed->scan.plots[1].mode_s ||
               parsed->scan.plots[1].flight_level);
  // AND a malformed attribute drops its plot with a reason naming the field
  ASSERT_EQ(parsed->rejected_plots.size(), 4u);
  EXPECT_THAT(parsed->rejected_plots[0], HasSubstr("plots[2].mode3a: expected 4 octal digits"));
  EXPECT_THAT(parsed->rejected_plots[1], HasSubstr("plots[3].mode_s: expected 6 hex digits"));
  EXPECT_THAT(parsed->rejected_plots[2], HasSubstr("plots[4].flight_level: outside"));
  EXPECT_THAT(parsed->rejected_plots[3], HasSubstr("plots[5].mode3a: expected a string"));
}

TEST(PlotScanParser, RejectsLinesWithBadStructure) {
  const struct {
    const char* line;
    const char* reason;
  } cases[] = {
      {R"({"sensor":0,"scan":1,"time":1.0)", "invalid JSON"},
      {R"([1,2,3])", "expected an object"},
      {R"({"scan":1,"time":1.0,"plots":[]})", "sensor: missing required field"},
      {R"({"sensor":-1,"scan":1,"time":1.0,"plots":[]})", "sensor: out of range"},
      {R"({"sensor":0,"scan":1.5,"time":1.0,"plots":[]})", "scan: expected an integer"},
      {R"({"sensor":0,"scan":1,"time":"now","plots":[]})", "time: expected a number"},
      {R"({"sensor":0,"scan":1,"time":1e400,"plots":[]})", "invalid JSON"},
      {R"({"sensor":0,"scan":1,"time":1.0})", "plots: missing required field"},
      {R"({"sensor":0,"scan":1,"time":1.0,"plots":{}})", "plots: expected an array"},
      {R"({"sensor":0,"scan":1,"time":1.0,"platform":{"attitude":[0,0]},"plots":[]})",
       "platform.attitude: expected 3 numbers"},
      {R"({"sensor":0,"scan":1,"time":1.0,"sigma":{"range":-1},"plots":[]})",
       "sigma.range: must be positive"},
  };
  for (const auto& c : cases) {
    const auto parsed = parse_plot_scan(c.line);
    ASSERT_FALSE(parsed) << c.line;
    EXPECT_THAT(parsed.error().message, HasSubstr(c.reason)) << c.line;
  }
}

TEST(PlotScanWriter, RoundTripsBitExactly) {
  PlotScan scan;
  scan.sensor = 3;
  scan.scan = 17;
  scan.time = 0.1 + 0.2;  // not representable in short decimal
  scan.platform.position = {1.0 / 3.0, -2.5, 8000.0};
  scan.platform.attitude = {0.1, -0.02, 0.003};
  scan.sigma.range = 15.0;
  scan.sigma.azimuth = 0.002;
  scan.coverage = AzimuthSector{3.0, -2.9};  // a sector across +-pi
  Plot polar;
  polar.id = 4;
  polar.range = 35120.123456789;
  polar.azimuth = -3.14159;
  polar.elevation = 0.01;
  polar.range_rate = -180.2;
  polar.time = 17.123456789012345;
  polar.snr_db = 13.0;
  polar.mode3a = 07777;
  polar.mode_s = 0x00ABCD;
  polar.flight_level = -12.5;
  polar.sigma.range = 20.0;
  Plot cartesian;
  cartesian.id = 9;
  cartesian.form = PlotForm::kCartesian;
  cartesian.x = 1e-7;
  cartesian.y = -1e7;
  cartesian.z = 12.5;
  cartesian.amplitude = 3.0;
  scan.plots = {polar, cartesian};

  const auto parsed = parse_plot_scan(to_json(scan));
  ASSERT_TRUE(parsed) << parsed.error().message;
  EXPECT_EQ(parsed->scan, scan);
}

}  // namespace
}  // namespace skytrack::io
