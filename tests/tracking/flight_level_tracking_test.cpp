// Secondary-radar plots with flight levels in the point tracker.
#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "tracker_test_support.hpp"

namespace skytrack {
namespace {

using testing::target;
using testing::test_profile;
using testing::track_scenario;

/// An en-route secondary radar: 4 s revolution, slant range and azimuth, Mode C altitude.
sim::Scenario secondary_radar() {
  sim::Scenario s;
  s.name = "ssr";
  s.dimensions = 3;
  s.duration = 240.0;
  s.sensor.scan_period = 4.0;
  s.sensor.antenna = sim::SensorSpec::Antenna::kRotating;
  s.sensor.detection_probability = 0.97;
  s.sensor.max_range = 100e3;
  s.sensor.elevation = false;
  s.sensor.flight_level_step = 1.0;
  s.sensor.sigma.range = 30.0;
  s.sensor.sigma.azimuth = 0.002;
  return s;
}

TEST(FlightLevelTracking, AircraftOvertakingOnOneAirwayAtTwoLevelsKeepTheirNumbersAndHeights) {
  // GIVEN two aircraft on one airway 40 km out, FL 300 and FL 310 (305 m apart), the faster
  // one overtaking 100 m to the side at t ~ 100 s: 80 m cross-range noise per plot, so in
  // the horizontal alone they are one blob for about half a minute
  sim::Scenario scenario = secondary_radar();
  scenario.targets = {target(1, {-24000.0, 40000.0, 9144.0}, {230.0, 0.0, 0.0}),
                      target(2, {-21000.0, 40100.0, 9449.0}, {200.0, 0.0, 0.0})};
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    SCOPED_TRACE(seed);
    // WHEN the default profile tracks them (dimension auto: 3-D from the flight levels)
    const auto run = track_scenario(scenario, seed, test_profile(), 500.0);
    // THEN each keeps its number, and its track its own level
    EXPECT_EQ(run.summary.id_changes, 0);
    for (const auto& truth : run.summary.continuity) {
      EXPECT_GE(truth.frames_tracked, truth.frames_present - 5) << "truth " << truth.truth_id;
      EXPECT_EQ(truth.distinct_tracks, 1) << "truth " << truth.truth_id;
    }
    for (const TrackFrame& frame : run.frames) {
      for (const TrackReport& track : frame.tracks) {
        if (!is_reported_as_firm(track.status)) continue;
        ASSERT_EQ(track.dims, 3);
        // The truth is the frame's z; at 45 km the altitude is 0.16 km above it (the curve),
        // so the reported levels are FL 305 and 315, and the tracks sit at the frame's z.
        EXPECT_TRUE(std::abs(track.position[2] - 9144.0) < 100.0 ||
                    std::abs(track.position[2] - 9449.0) < 100.0)
            << "t = " << frame.time << ": z = " << track.position[2];
      }
    }
  }
}

TEST(FlightLevelTracking, AReplyWithoutAltitudeAmongAltitudeRepliesKeepsOneTrack) {
  // GIVEN a 3-D tracker (one aircraft reports Mode C) and a second aircraft whose
  // transponder reports no altitude: its track's height is never measured
  sim::Scenario scenario = secondary_radar();
  sim::TargetSpec silent = target(2, {-21000.0, 30100.0, 9449.0}, {200.0, 0.0, 0.0});
  silent.reports_altitude = false;
  scenario.targets = {target(1, {-24000.0, 40000.0, 9144.0}, {230.0, 0.0, 0.0}), silent};
  const auto run = track_scenario(scenario, 1, test_profile(), 500.0);
  // WHEN it is tracked; THEN its track keeps one number over the whole run (its unknown
  // height's spread, kilometres, does not delete it) and no branch replaces it
  std::set<std::int64_t> numbers;
  int frames = 0, events = 0;
  for (const TrackFrame& frame : run.frames) {
    for (const TrackReport& track : frame.tracks) {
      if (is_reported_as_firm(track.status) && std::abs(track.position.y() - 30100.0) < 2000.0) {
        numbers.insert(track.id);
        ++frames;
      }
    }
    for (const TrackEvent& e : frame.events) events += type_name(e).rfind("branch", 0) == 0 ? 1 : 0;
  }
  EXPECT_EQ(numbers.size(), 1u);
  EXPECT_GE(frames, 55);  // of 60 revolutions
  EXPECT_EQ(events, 0);
}

}  // namespace
}  // namespace skytrack
