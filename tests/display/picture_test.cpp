// The display's picture: what it keeps per sensor and the JSON the page draws from.
#include "skytrack/display/picture.hpp"

#include <chrono>
#include <thread>

#include <gtest/gtest.h>
#include <simdjson.h>

namespace skytrack::display {
namespace {

using namespace std::chrono_literals;

PlotScan cartesian_scan(std::uint32_t sensor, std::uint64_t scan, double x) {
  PlotScan s;
  s.sensor = sensor;
  s.scan = scan;
  s.time = static_cast<double>(scan);
  Plot p;
  p.form = PlotForm::kCartesian;
  p.x = x;
  p.y = -2.0 * x;
  s.plots.push_back(p);
  return s;
}

TrackFrame frame_with_track(std::uint32_t sensor, std::uint64_t scan, std::int64_t id) {
  TrackFrame f;
  f.sensor = sensor;
  f.scan = scan;
  f.time = static_cast<double>(scan);
  TrackReport t;
  t.id = id;
  t.status = TrackStatus::kConfirmed;
  t.position = {1000.0, 2000.0, 0.0};
  t.velocity = {100.0, 0.0, 0.0};
  t.covariance.assign(16, 0.0);
  t.covariance[0] = 25.0;   // Pxx
  t.covariance[10] = 36.0;  // Pyy: row 2, column 2 of [x vx y vy]
  t.modes = {{"cv", 0.9}, {"ct", 0.1}};
  f.tracks.push_back(t);
  f.associations.push_back({id, 7, 0.8, std::nullopt});
  f.events.push_back({TrackEventType::kBranchCreated, id, "son 2 from plot 7", ""});
  return f;
}

simdjson::dom::element parse(simdjson::dom::parser& parser, const std::string& json) {
  return parser.parse(json);
}

TEST(Picture, KeepsTheLastScansOfPlotsPerSensorNewestFirst) {
  Picture picture(2);  // GIVEN two scans of plots kept
  for (std::uint64_t scan = 1; scan <= 3; ++scan) picture.add_plots(cartesian_scan(1, scan, scan));
  picture.add_plots(cartesian_scan(2, 9, 50.0));  // WHEN three scans of sensor 1, one of 2
  simdjson::dom::parser parser;
  const auto doc = parse(parser, picture.frame_json()->json);
  const simdjson::dom::array sensors = doc["sensors"].get_array().value();
  ASSERT_EQ(sensors.size(), 2u);  // THEN both sensors, sensor 1 with scans 3 then 2
  const simdjson::dom::array plots = sensors.at(0)["plots"].get_array().value();
  ASSERT_EQ(plots.size(), 2u);
  EXPECT_EQ(plots.at(0)["scan"].get_uint64().value(), 3u);
  EXPECT_EQ(plots.at(1)["scan"].get_uint64().value(), 2u);
  EXPECT_EQ(plots.at(0)["xy"].at(1).get_int64().value(), -6);
}

TEST(Picture, FrameCarriesTracksWithPositionCovarianceAndBranchEvents) {
  Picture picture;
  picture.add_tracks(frame_with_track(1, 5, 12));
  simdjson::dom::parser parser;
  const auto doc = parse(parser, picture.frame_json()->json);
  const auto track = doc["sensors"].at(0)["tracks"].at(0);
  EXPECT_EQ(track["i"].get_int64().value(), 12);
  EXPECT_EQ(std::string(track["s"].get_string().value()), "c");
  EXPECT_DOUBLE_EQ(track["y"].get_double().value(), 2000.0);
  EXPECT_DOUBLE_EQ(track["c"].at(0).get_double().value(), 25.0);
  EXPECT_DOUBLE_EQ(track["c"].at(2).get_double().value(), 36.0);
  const auto event = doc["sensors"].at(0)["events"].at(0);
  EXPECT_EQ(std::string(event.at(0).get_string().value()), "branch_created");
}

TEST(Picture, TrackDetailsHoldModesAssociationsAndEvents) {
  Picture picture;
  picture.add_tracks(frame_with_track(3, 5, 12));
  const auto json = picture.track_json(3, 12);
  ASSERT_TRUE(json);
  EXPECT_NE(json->find("\"cv\""), std::string::npos);
  EXPECT_NE(json->find("\"plot\":7"), std::string::npos);
  EXPECT_NE(json->find("son 2 from plot 7"), std::string::npos);
  EXPECT_FALSE(picture.track_json(3, 13));
  EXPECT_FALSE(picture.track_json(4, 12));
}

TEST(Picture, StatusIsKeptPerInstance) {
  Picture picture;
  TrackerStatusReport a;
  a.instance = "a";
  a.latency_p99 = 0.002;
  a.plots_rejected = {{"non_finite_range", 3}};
  picture.add_status(a);
  picture.add_status(a);
  a.instance = "b";
  picture.add_status(a);
  simdjson::dom::parser parser;
  const auto doc = parse(parser, picture.frame_json()->json);
  ASSERT_EQ(doc["status"].get_array().value().size(), 2u);
  EXPECT_EQ(doc["status"].at(0)["plots_rejected"]["non_finite_range"].get_uint64().value(), 3u);
}

TEST(Picture, AWaiterWakesOnChangeAndTheJsonIsBuiltOncePerVersion) {
  Picture picture;
  const std::uint64_t seen = picture.version();
  std::thread writer([&] {
    std::this_thread::sleep_for(20ms);
    picture.add_plots(cartesian_scan(1, 1, 1.0));
  });
  EXPECT_NE(picture.wait_for_change(seen, 5s), seen);
  writer.join();
  const auto first = picture.frame_json();
  EXPECT_EQ(first.get(), picture.frame_json().get());  // same version: the cached document
  picture.clear();
  EXPECT_NE(first.get(), picture.frame_json().get());
}

TEST(Picture, StopWakesEveryWaiter) {
  Picture picture;
  const std::uint64_t seen = picture.version();
  std::thread stopper([&] {
    std::this_thread::sleep_for(20ms);
    picture.stop();
  });
  const auto start = std::chrono::steady_clock::now();
  picture.wait_for_change(seen, 10s);
  EXPECT_LT(std::chrono::steady_clock::now() - start, 5s);
  EXPECT_TRUE(picture.stopped());
  stopper.join();
}

}  // namespace
}  // namespace skytrack::display
