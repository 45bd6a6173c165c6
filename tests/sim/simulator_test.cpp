#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "skytrack/geometry/angles.hpp"
#include "skytrack/geometry/frames.hpp"
#include "skytrack/sim/simulator.hpp"

namespace skytrack::sim {
namespace {

Scenario base_scenario() {
  Scenario scenario;
  scenario.name = "test";
  scenario.dimensions = 2;
  scenario.duration = 999.0;
  scenario.sensor.scan_period = 1.0;
  scenario.sensor.sigma.range = 10.0;
  scenario.sensor.sigma.azimuth = 0.001;
  scenario.sensor.max_range = 50000.0;
  scenario.clutter.range = {1000.0, 50000.0};
  return scenario;
}

TargetSpec point_target(std::int64_t id, Eigen::Vector3d position, Eigen::Vector3d velocity) {
  TargetSpec target;
  target.id = id;
  target.trajectory.position = position;
  target.trajectory.velocity = velocity;
  return target;
}

std::vector<SimulatedBatch> run(const Scenario& scenario, std::uint64_t seed) {
  auto simulator = Simulator::create(scenario, seed);
  EXPECT_TRUE(simulator) << (simulator ? "" : simulator.error().message);
  std::vector<SimulatedBatch> out;
  while (auto batch = simulator->next()) out.push_back(std::move(*batch));
  return out;
}

TEST(Simulator, ClutterCountIsPoissonWithTheConfiguredMean) {
  Scenario scenario = base_scenario();
  scenario.clutter.mean = 20.0;
  const auto batches = run(scenario, 3);
  ASSERT_EQ(batches.size(), 1000u);
  double sum = 0.0, sum_sq = 0.0;
  for (const auto& b : batches) {
    const double n = static_cast<double>(b.plots.plots.size());
    sum += n;
    sum_sq += n * n;
  }
  const double mean = sum / 1000.0, variance = sum_sq / 1000.0 - mean * mean;
  // Standard error of the mean: sqrt(20 / 1000) = 0.14; allow 4 of them.
  EXPECT_NEAR(mean, 20.0, 0.57);
  EXPECT_NEAR(variance, 20.0, 3.0);  // Poisson: variance = mean
}

TEST(Simulator, PolarClutterStaysInItsRegion) {
  Scenario scenario = base_scenario();
  scenario.clutter.mean = 50.0;
  scenario.clutter.azimuth = {0.5, 1.0};
  scenario.sensor.sigma.range = 1e-6;
  scenario.sensor.sigma.azimuth = 1e-9;
  scenario.duration = 20.0;
  for (const auto& b : run(scenario, 4)) {
    for (const Plot& p : b.plots.plots) {
      EXPECT_GE(p.range, 1000.0 - 1e-3);
      EXPECT_LE(p.range, 50000.0 + 1e-3);
      EXPECT_GE(p.azimuth, 0.5 - 1e-6);
      EXPECT_LE(p.azimuth, 1.0 + 1e-6);
    }
  }
}

TEST(Simulator, DetectionRateMatchesPd) {
  Scenario scenario = base_scenario();
  scenario.sensor.detection_probability = 0.7;
  for (int i = 0; i < 10; ++i) {
    scenario.targets.push_back(point_target(i, {1000.0 * (i + 2), 3000.0, 0.0}, {0.0, 10.0, 0.0}));
  }
  const auto batches = run(scenario, 5);
  std::size_t plots = 0;
  for (const auto& b : batches) plots += b.plots.plots.size();
  const double rate = static_cast<double>(plots) / (10.0 * batches.size());
  // 10000 Bernoulli(0.7) trials: standard error 0.0046.
  EXPECT_NEAR(rate, 0.7, 0.02);
}

TEST(Simulator, SameSeedGivesTheSameOutputAndAnotherSeedDoesNot) {
  Scenario scenario = base_scenario();
  scenario.duration = 50.0;
  scenario.clutter.mean = 5.0;
  scenario.sensor.detection_probability = 0.8;
  scenario.targets.push_back(point_target(1, {5000.0, 5000.0, 0.0}, {100.0, 0.0, 0.0}));
  const auto a = run(scenario, 42), b = run(scenario, 42), c = run(scenario, 43);
  ASSERT_EQ(a.size(), b.size());
  bool all_equal = true, any_differs = false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    all_equal = all_equal && a[i].plots == b[i].plots && a[i].truth == b[i].truth;
    any_differs = any_differs || !(a[i].plots == c[i].plots);
  }
  EXPECT_TRUE(all_equal);
  EXPECT_TRUE(any_differs);
}

TEST(Simulator, NoiseMatchesTheConfiguredSigma) {
  Scenario scenario = base_scenario();
  scenario.targets.push_back(point_target(1, {0.0, 20000.0, 0.0}, {0.0, 0.0, 0.0}));
  double sum_sq_range = 0.0, sum_sq_az = 0.0;
  const auto batches = run(scenario, 6);
  for (const auto& b : batches) {
    ASSERT_EQ(b.plots.plots.size(), 1u);
    sum_sq_range += std::pow(b.plots.plots[0].range - 20000.0, 2);
    sum_sq_az += std::pow(wrap_angle(b.plots.plots[0].azimuth), 2);
  }
  EXPECT_NEAR(std::sqrt(sum_sq_range / batches.size()), 10.0, 0.5);
  EXPECT_NEAR(std::sqrt(sum_sq_az / batches.size()), 0.001, 0.00005);
  EXPECT_EQ(batches[0].plots.sigma.range, 10.0);
}

TEST(Simulator, BoundedNoiseStaysInsideItsEllipse) {
  Scenario scenario = base_scenario();
  scenario.sensor.type = SensorSpec::Type::kCartesian;
  scenario.sensor.noise = SensorSpec::Noise::kBounded;
  scenario.sensor.sigma = {};
  scenario.sensor.sigma.x = 20.0;
  scenario.sensor.sigma.y = 10.0;
  scenario.targets.push_back(point_target(1, {100.0, 200.0, 0.0}, {0.0, 0.0, 0.0}));
  double max_radius = 0.0;
  const auto batches = run(scenario, 7);
  for (const auto& b : batches) {
    const Plot& p = b.plots.plots.at(0);
    const double r = std::hypot((p.x - 100.0) / 20.0, (p.y - 200.0) / 10.0);
    EXPECT_LE(r, 1.0 + 1e-12);
    max_radius = std::max(max_radius, r);
  }
  EXPECT_GT(max_radius, 0.97);  // and it fills the ellipse
  // Reported sigma: standard deviation of the uniform disk, a / 2.
  EXPECT_DOUBLE_EQ(*batches[0].plots.sigma.x, 10.0);
}

TEST(Simulator, RotatingAntennaTimesEachPlotByItsAzimuth) {
  // GIVEN a 4 s revolution in 4 sectors and targets spread in azimuth
  Scenario scenario = base_scenario();
  scenario.duration = 40.0;
  scenario.sensor.scan_period = 4.0;
  scenario.sensor.antenna = SensorSpec::Antenna::kRotating;
  scenario.sensor.sectors = 4;
  for (int i = 0; i < 12; ++i) {
    const double az = i * std::numbers::pi / 6 + 0.1;
    scenario.targets.push_back(
        point_target(i, {20000.0 * std::sin(az), 20000.0 * std::cos(az), 0.0}, {0.0, 0.0, 0.0}));
  }
  const auto batches = run(scenario, 8);
  // THEN 10 revolutions give 40 batches, stamped at sector ends
  ASSERT_EQ(batches.size(), 40u);
  EXPECT_DOUBLE_EQ(batches[0].plots.time, 1.0);
  EXPECT_DOUBLE_EQ(batches[39].plots.time, 40.0);
  std::size_t plots = 0;
  for (const auto& b : batches) {
    EXPECT_EQ(b.plots.plots.size(), 3u);  // three targets per 90-degree sector
    for (const Plot& p : b.plots.plots) {
      ASSERT_TRUE(p.time);
      EXPECT_LE(*p.time, b.plots.time);
      EXPECT_GT(*p.time, b.plots.time - 1.0);
      const double revolution_start = std::floor(b.plots.time / 4.0 - 1e-9) * 4.0;
      const double expected =
          revolution_start + wrap_angle_positive(p.azimuth) / (2 * std::numbers::pi) * 4.0;
      // Azimuth noise 0.001 rad moves the beam time by 0.64 ms per sigma: allow 5 sigma.
      EXPECT_NEAR(*p.time, expected, 3.2e-3);
      ++plots;
    }
  }
  EXPECT_EQ(plots, 120u);
}

TEST(Simulator, MovingPlatformMeasuresRelativeToItself) {
  // GIVEN an airborne platform heading east at 200 m/s and a target 10 km ahead, same speed
  Scenario scenario = base_scenario();
  scenario.dimensions = 3;
  scenario.duration = 10.0;
  scenario.sensor.sigma.range = 1e-6;
  scenario.sensor.sigma.azimuth = 1e-9;
  scenario.sensor.sigma.elevation = 1e-9;
  scenario.sensor.sigma.range_rate = 1e-9;
  scenario.sensor.range_rate = true;
  scenario.platform.trajectory.position = {0.0, 0.0, 8000.0};
  scenario.platform.trajectory.velocity = {200.0, 0.0, 0.0};
  scenario.platform.attitude_follows_velocity = true;
  scenario.targets.push_back(point_target(1, {10000.0, 0.0, 8000.0}, {150.0, 0.0, 0.0}));
  for (const auto& b : run(scenario, 9)) {
    const Plot& p = b.plots.plots.at(0);
    EXPECT_NEAR(p.azimuth, 0.0, 1e-6);  // on the nose
    EXPECT_NEAR(p.range, 10000.0 - 50.0 * b.plots.time, 1e-3);
    EXPECT_NEAR(*p.range_rate, -50.0, 1e-6);
    EXPECT_NEAR((plot_position_enu(p, b.plots.platform) - b.truth.objects[0].position).norm(), 0.0,
                1e-3);
  }
}

TEST(Simulator, RotatingAirbornePlotsAreRelativeToTheirBatchPlatformState) {
  // GIVEN an airborne radar turning at 3 deg/s with a 10 s revolution, and one target
  Scenario scenario = base_scenario();
  scenario.dimensions = 3;
  scenario.duration = 60.0;
  scenario.sensor.scan_period = 10.0;
  scenario.sensor.antenna = SensorSpec::Antenna::kRotating;
  scenario.sensor.sigma.range = 1e-6;
  scenario.sensor.sigma.azimuth = 1e-9;
  scenario.sensor.sigma.elevation = 1e-9;
  scenario.platform.trajectory.position = {0.0, 0.0, 9000.0};
  scenario.platform.trajectory.velocity = {180.0, 0.0, 0.0};
  SegmentSpec turn;
  turn.type = SegmentSpec::Type::kCoordinatedTurn;
  turn.duration = 100.0;
  turn.turn_rate = 0.05;
  scenario.platform.trajectory.segments = {turn};
  scenario.platform.attitude_follows_velocity = true;
  TargetSpec aircraft = point_target(1, {20000.0, 30000.0, 3000.0}, {-200.0, 50.0, 0.0});
  scenario.targets = {aircraft};
  const Trajectory truth(aircraft.trajectory, 0.0, 3);
  // THEN each plot, converted with the platform state its batch carries, lies where the
  // target was at the plot's own time (the platform moves 1.8 km and turns 29 deg per sweep)
  for (const auto& b : run(scenario, 15)) {
    ASSERT_EQ(b.plots.plots.size(), 1u);
    const Plot& p = b.plots.plots[0];
    const Eigen::Vector3d at_plot_time = truth.at(*p.time).position;
    EXPECT_NEAR((plot_position_enu(p, b.plots.platform) - at_plot_time).norm(), 0.0, 1e-3);
  }
}

TEST(Simulator, GroupMembersEachProduceAPlotAndTruthCarriesTheShape) {
  Scenario scenario = base_scenario();
  scenario.duration = 5.0;
  scenario.sensor.sigma.range = 1e-3;  // noise-free enough to see the member layout
  scenario.sensor.sigma.azimuth = 1e-8;
  TargetSpec group = point_target(1, {0.0, 20000.0, 0.0}, {50.0, 0.0, 0.0});
  group.kind = ObjectKind::kGroup;
  group.members = 15;
  group.shape = Eigen::Vector2d(400.0 * 400.0, 200.0 * 200.0).asDiagonal();
  scenario.targets.push_back(group);
  for (const auto& b : run(scenario, 10)) {
    EXPECT_EQ(b.plots.plots.size(), 15u);
    ASSERT_EQ(b.truth.objects.size(), 1u);
    EXPECT_EQ(b.truth.objects[0].members, 15);
    ASSERT_TRUE(b.truth.objects[0].extent);
    for (const Plot& p : b.plots.plots) {
      const Eigen::Vector3d d =
          plot_position_enu(p, b.plots.platform) - b.truth.objects[0].position;
      EXPECT_LE(std::hypot(d.x() / 400.0, d.y() / 200.0), 1.0 + 0.01);
    }
  }
}

TEST(Simulator, ExtendedObjectPlotCountIsPoisson) {
  Scenario scenario = base_scenario();
  scenario.sensor.type = SensorSpec::Type::kCartesian;
  scenario.sensor.sigma = {};
  scenario.sensor.sigma.x = 1.0;
  scenario.sensor.sigma.y = 1.0;
  TargetSpec object = point_target(1, {800.0, -200.0, 0.0}, {9.8, -9.8, 0.0});
  object.kind = ObjectKind::kExtended;
  object.plot_rate = 8.0;
  object.shape << 2500.0, 300.0, 300.0, 900.0;
  scenario.targets.push_back(object);
  double total = 0.0;
  const auto batches = run(scenario, 11);
  for (const auto& b : batches) total += static_cast<double>(b.plots.plots.size());
  EXPECT_NEAR(total / batches.size(), 8.0, 0.4);
}

TEST(Simulator, BirthsDeathsAndSplitsFollowTheScenario) {
  Scenario scenario = base_scenario();
  scenario.duration = 30.0;
  TargetSpec parent = point_target(1, {1000.0, 1000.0, 0.0}, {10.0, 0.0, 0.0});
  parent.death = 20.0;
  TargetSpec child;
  child.id = 2;
  child.parent = 1;
  child.birth = 10.0;
  child.offset = {0.0, 50.0, 0.0};
  child.trajectory.velocity = {0.0, 10.0, 0.0};
  scenario.targets = {child, parent};
  for (const auto& b : run(scenario, 12)) {
    const double t = b.truth.time;
    const std::size_t expected = (t < 10.0 || t >= 20.0) ? 1u : 2u;
    EXPECT_EQ(b.truth.objects.size(), expected) << "t=" << t;
    if (t == 10.0) {
      EXPECT_NEAR(b.truth.objects[1].position.x(), 1100.0, 1e-9);  // parent's x at birth
      EXPECT_NEAR(b.truth.objects[1].position.y(), 1050.0, 1e-9);
    }
  }
}

TEST(Simulator, DetectionWindowsScriptMissesAndFalseObjectsStayOutOfTheTruth) {
  // GIVEN a target missed in [3, 6) s and a decoy that is never in the truth
  Scenario scenario = base_scenario();
  scenario.duration = 9.0;
  TargetSpec target = point_target(1, {0.0, 5000.0, 0.0}, {10.0, 0.0, 0.0});
  target.detection_windows = {{3.0, 6.0, 0.0}};
  TargetSpec decoy = point_target(2, {3000.0, 5000.0, 0.0}, {0.0, 0.0, 0.0});
  decoy.in_truth = false;
  scenario.targets = {target, decoy};
  for (const auto& b : run(scenario, 13)) {
    const double t = b.plots.time;
    // THEN the target's plot is missing exactly in the window, the decoy always plots
    EXPECT_EQ(b.plots.plots.size(), (t >= 3.0 && t < 6.0) ? 1u : 2u) << "t=" << t;
    ASSERT_EQ(b.truth.objects.size(), 1u);
    EXPECT_EQ(b.truth.objects[0].id, 1);
  }
}

TEST(Simulator, ClutterPatchesAddToTheBackground) {
  Scenario scenario = base_scenario();
  scenario.clutter.mean = 10.0;
  ClutterSpec patch;
  patch.mean = 30.0;
  patch.region = ClutterSpec::Region::kBox;
  patch.x = {1000.0, 2000.0};
  patch.y = {1000.0, 2000.0};
  scenario.clutter_patches = {patch};
  double total = 0.0;
  const auto batches = run(scenario, 14);
  for (const auto& b : batches) total += static_cast<double>(b.plots.plots.size());
  EXPECT_NEAR(total / batches.size(), 40.0, 0.8);  // standard error 0.2
}

TEST(Simulator, SecondaryRadarReportsIdentitiesAndRoundedFlightLevels) {
  // GIVEN a 3-D scenario seen by a secondary radar (no elevation, Mode C flight levels) and
  // an aircraft at 3000 m with a Mode S address, another without altitude reporting
  Scenario scenario = base_scenario();
  scenario.dimensions = 3;
  scenario.duration = 5.0;
  scenario.sensor.elevation = false;
  scenario.sensor.flight_level_step = 1.0;
  TargetSpec reporting = point_target(1, {0.0, 10000.0, 3000.0}, {100.0, 0.0, 0.0});
  reporting.mode_s = 0x4CA2D7;
  reporting.mode3a = 02270;
  TargetSpec silent = point_target(2, {0.0, 20000.0, 3000.0}, {100.0, 0.0, 0.0});
  silent.reports_altitude = false;
  scenario.targets = {reporting, silent};
  // WHEN it is simulated (elevation needs no sigma)
  const auto batches = run(scenario, 3);
  ASSERT_FALSE(batches.empty());
  for (const SimulatedBatch& b : batches) {
    EXPECT_FALSE(b.plots.sigma.elevation.has_value());
    ASSERT_EQ(b.plots.plots.size(), 2u);
    for (const Plot& plot : b.plots.plots) {
      EXPECT_FALSE(plot.elevation.has_value());
      if (plot.range < 15000.0) {
        // THEN the aircraft's plot carries its identities and its altitude in whole flight
        // levels (3000 m + 7.8 m for the earth's curve = FL 98.7 -> 99)
        EXPECT_EQ(plot.mode_s, 0x4CA2D7u);
        EXPECT_EQ(plot.mode3a, 02270);
        ASSERT_TRUE(plot.flight_level.has_value());
        EXPECT_EQ(*plot.flight_level, 99.0);
      } else {
        EXPECT_FALSE(plot.flight_level.has_value());  // AND the other reports none
        EXPECT_FALSE(plot.mode_s.has_value());
      }
    }
  }
}

TEST(Simulator, RejectsASensorWithoutTheSigmasItNeeds) {
  Scenario scenario = base_scenario();
  scenario.dimensions = 3;  // needs elevation
  const auto simulator = Simulator::create(scenario, 1);
  ASSERT_FALSE(simulator);
  EXPECT_NE(simulator.error().message.find("elevation"), std::string::npos);
}

}  // namespace
}  // namespace skytrack::sim
