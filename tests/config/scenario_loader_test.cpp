#include <filesystem>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "skytrack/config/scenario_loader.hpp"
#include "skytrack/sim/simulator.hpp"

namespace skytrack::config {
namespace {

using ::testing::HasSubstr;

constexpr const char* kMinimal = R"(
scenario: {name: minimal, duration: 10}
sensor:
  scan_period: 1
  sigma: {range: 10, azimuth: 0.001}
)";

TEST(ScenarioLoader, EveryShippedScenarioLoadsAndSimulates) {
  const std::filesystem::path dir = std::filesystem::path(SKYTRACK_SOURCE_DIR) / "config/scenarios";
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".yaml") continue;
    ++files;
    SCOPED_TRACE(entry.path().string());
    auto scenario = load_scenario(entry.path().string());
    ASSERT_TRUE(scenario) << scenario.error().message;
    auto simulator = sim::Simulator::create(*scenario, scenario->seed);
    ASSERT_TRUE(simulator) << simulator.error().message;
    const auto first = simulator->next();
    ASSERT_TRUE(first.has_value());
  }
  EXPECT_GE(files, 1);
}

TEST(ScenarioLoader, ReadsAMinimalScenarioWithDefaults) {
  const auto scenario = parse_scenario(kMinimal, "minimal.yaml");
  ASSERT_TRUE(scenario) << scenario.error().message;
  EXPECT_EQ(scenario->dimensions, 2);
  EXPECT_EQ(scenario->sensor.type, sim::SensorSpec::Type::kPolar);
  EXPECT_EQ(scenario->sensor.sigma.range, 10.0);
  EXPECT_TRUE(scenario->targets.empty());
}

TEST(ScenarioLoader, ReadsTargetsSegmentsAndGroups) {
  const auto scenario = parse_scenario(std::string(kMinimal) + R"(
targets:
  - id: 1
    position: [0, 1000]
    velocity: [300, 0]
    segments:
      - {type: cv, duration: 10}
      - {type: ct, duration: 20, g: 4, direction: right}
      - {type: ct, duration: 5, turn_rate: 0.1}
      - {type: ca, duration: 5, acceleration: [1, 0]}
  - id: 2
    kind: group
    parent: 1
    birth: 5
    offset: [0, 50]
    velocity: [0, 10]
    members: 12
    shape: [[400, 0], [0, 100]]
)",
                                       "targets.yaml");
  ASSERT_TRUE(scenario) << scenario.error().message;
  ASSERT_EQ(scenario->targets.size(), 2u);
  const auto& segments = scenario->targets[0].trajectory.segments;
  ASSERT_EQ(segments.size(), 4u);
  EXPECT_EQ(segments[1].g_load, 4.0);
  EXPECT_FALSE(segments[1].turn_left);
  EXPECT_EQ(segments[2].turn_rate, 0.1);
  EXPECT_EQ(scenario->targets[1].kind, ObjectKind::kGroup);
  EXPECT_EQ(scenario->targets[1].members, 12);
  EXPECT_EQ(scenario->targets[1].parent, 1);
}

TEST(ScenarioLoader, ReadsARandomPopulationAndNamesItsMistakes) {
  const auto scenario = parse_scenario(std::string(kMinimal) + R"(
random_targets: {count: 5, x: [-400, 400], y: [-400, 400], velocity_sigma: 5,
                 acceleration_noise: 0.5, first_id: 10}
)",
                                       "population.yaml");
  ASSERT_TRUE(scenario) << scenario.error().message;
  ASSERT_TRUE(scenario->random_targets);
  EXPECT_EQ(scenario->random_targets->count, 5);
  EXPECT_EQ(scenario->random_targets->first_id, 10);
  EXPECT_EQ(scenario->random_targets->step, 1.0);
  const auto wrong = parse_scenario(std::string(kMinimal) + R"(
random_targets: {count: 0, x: [400, -400], z: [0, 1]}
)",
                                    "wrong.yaml");
  ASSERT_FALSE(wrong);
  const std::string& message = wrong.error().message;
  EXPECT_NE(message.find("random_targets.count"), std::string::npos) << message;
  EXPECT_NE(message.find("random_targets.x: expected [min, max]"), std::string::npos) << message;
  EXPECT_NE(message.find("random_targets.y: missing required key"), std::string::npos) << message;
  EXPECT_NE(message.find("random_targets.z: only in a 3-D scenario"), std::string::npos) << message;
}

TEST(ScenarioLoader, ReadsDetectionWindowsPatchesAndFalseObjects) {
  const auto scenario = parse_scenario(std::string(kMinimal) + R"(
clutter: {mean: 5, range: [100, 1000]}
clutter_patches:
  - {mean: 60, region: box, x: [0, 10], y: [0, 10]}
targets:
  - id: 1
    position: [0, 1000]
    velocity: [300, 0]
    detection_windows: [{from: 3, to: 6, probability: 0}]
  - {id: 2, parent: 1, birth: 2, truth: false}
)",
                                       "more.yaml");
  ASSERT_TRUE(scenario) << scenario.error().message;
  ASSERT_EQ(scenario->clutter_patches.size(), 1u);
  EXPECT_EQ(scenario->clutter_patches[0].mean, 60.0);
  ASSERT_EQ(scenario->targets[0].detection_windows.size(), 1u);
  EXPECT_EQ(scenario->targets[0].detection_windows[0].to, 6.0);
  EXPECT_FALSE(scenario->targets[1].in_truth);
  EXPECT_TRUE(scenario->targets[1].velocity_from_parent);
}

TEST(ScenarioLoader, ReadsASecondaryRadarAndTransponders) {
  const auto scenario = parse_scenario(R"(
scenario: {name: ssr, duration: 10, dimensions: 3}
sensor:
  scan_period: 4
  elevation: false
  flight_level_step: 0.25
  sigma: {range: 10, azimuth: 0.001}
targets:
  - {id: 1, position: [0, 1000, 3000], mode3a: "2270", mode_s: "4ca2d7"}
  - {id: 2, position: [0, 2000, 3000], reports_altitude: false}
)",
                                       "ssr.yaml");
  ASSERT_TRUE(scenario) << scenario.error().message;
  EXPECT_FALSE(scenario->sensor.elevation);
  EXPECT_EQ(scenario->sensor.flight_level_step, 0.25);
  EXPECT_EQ(scenario->targets[0].mode3a, 02270);
  EXPECT_EQ(scenario->targets[0].mode_s, 0x4CA2D7u);
  EXPECT_TRUE(scenario->targets[0].reports_altitude);
  EXPECT_FALSE(scenario->targets[1].mode3a.has_value());
  EXPECT_FALSE(scenario->targets[1].reports_altitude);
  // A code that is not 4 octal digits is named.
  const auto bad = parse_scenario(std::string(kMinimal) + R"(
targets:
  - {id: 1, position: [0, 1000], mode3a: "2298"}
)",
                                  "bad.yaml");
  ASSERT_FALSE(bad);
  EXPECT_THAT(bad.error().message, HasSubstr("mode3a: expected 4 octal digits"));
}

TEST(ScenarioLoader, NamesFileLineKeyAndExpectationForMistakes) {
  const struct {
    const char* yaml;
    const char* message;
  } cases[] = {
      {R"(
scenario: {name: x, duration: 10, dimension: 3}
sensor: {scan_period: 1, sigma: {range: 10, azimuth: 0.001}}
)",
       "bad.yaml:2: scenario.dimension: unknown key"},
      {R"(
scenario: {name: x, duration: ten}
sensor: {scan_period: 1, sigma: {range: 10, azimuth: 0.001}}
)",
       "bad.yaml:2: scenario.duration: expected a finite number >= 0"},
      {R"(
scenario: {name: x, duration: 10}
sensor: {scan_period: 0, sigma: {range: 10, azimuth: 0.001}}
)",
       "bad.yaml:3: sensor.scan_period: expected a number > 0, got 0"},
      {R"(
scenario: {name: x, duration: 10}
sensor: {scan_period: 1, antenna: spinning, sigma: {range: 10, azimuth: 0.001}}
)",
       "sensor.antenna: expected one of snapshot, rotating, got 'spinning'"},
      {R"(
scenario: {name: x, duration: 10}
sensor: {scan_period: 1, detection_probability: 1.2, sigma: {range: 10, azimuth: 0.001}}
)",
       "sensor.detection_probability: expected a number in [0, 1], got 1.2"},
      {R"(
scenario: {name: x, duration: 10}
sensor: {scan_period: 1, sigma: {range: 10, azimuth: 0.001}}
targets:
  - {id: 1, position: [0, 0], segments: [{type: ct, duration: 5}]}
)",
       "targets[0].segments[0].turn_rate: a ct segment needs exactly one of turn_rate"},
      {R"(
scenario: {name: x, duration: 10}
sensor: {scan_period: 1, sigma: {range: 10, azimuth: 0.001}}
targets:
  - {id: 1, position: [0, 0, 5]}
)",
       "targets[0].position: expected a list of 2 numbers, got 3"},
      {R"(
scenario: {name: x, duration: 10}
sensor: {scan_period: 1, sigma: {range: 10, azimuth: 0.001}}
targets:
  - {id: 1, position: [0, 0]}
  - {id: 1, position: [5, 0]}
)",
       "targets[1].id: duplicate target id 1"},
      {R"(
scenario: {name: x, duration: 10}
sensor: {scan_period: 1, sigma: {range: 10, azimuth: 0.001}}
targets:
  - {id: 1, kind: extended, position: [0, 0], plot_rate: 5, shape: [[1, 2], [2, 1]]}
)",
       "targets[0].shape: expected a symmetric positive-definite shape matrix"},
      {R"(
scenario: {name: x, duration: 10}
sensor: {scan_period: 1, sigma: {range: 10, azimuth: 0.001}}
targets:
  - {id: 2, parent: 7, velocity: [1, 0]}
)",
       "target 2 names parent 7 that is not in the list"},
      {R"(
scenario: {name: x, duration: 10}
sensor: {scan_period: 1, sigma: {range: 10, azimuth: 0.001}}
targets:
  - {id: 1, position: [0, 0], offset: [5, 0]}
)",
       "targets[0].offset: an offset needs a parent"},
      {R"(
scenario: {name: x, duration: 10}
sensor: {scan_period: 1, sigma: {range: 10, azimuth: 0.001}}
targets:
  - {id: 1, position: [0, 0], detection_windows: [{from: 5, to: 5, probability: 0}]}
)",
       "targets[0].detection_windows[0].to: must be after from"},
      {R"(
scenario: {name: x, duration: 10, dimensions: 3}
sensor: {scan_period: 1, sigma: {range: 10, azimuth: 0.001, elevation: 0.001}}
clutter: {mean: 5, range: [0, 100]}
)",
       "clutter.elevation: a 3-D polar clutter region needs an elevation interval"},
      {"scenario: {name: x\n  duration: [", "bad.yaml: line"},
  };
  for (const auto& c : cases) {
    const auto scenario = parse_scenario(c.yaml, "bad.yaml");
    ASSERT_FALSE(scenario) << c.yaml;
    EXPECT_THAT(scenario.error().message, HasSubstr(c.message)) << c.yaml;
  }
}

TEST(ScenarioLoader, ReportsEveryMistakeOfAFileAtOnce) {
  const auto scenario = parse_scenario(R"(
scenario: {name: x, duration: -1, colour: red}
sensor: {scan_period: 1, sigma: {range: 10, azimuth: 0.001}}
)",
                                       "bad.yaml");
  ASSERT_FALSE(scenario);
  EXPECT_THAT(scenario.error().message, HasSubstr("scenario.duration"));
  EXPECT_THAT(scenario.error().message, HasSubstr("scenario.colour: unknown key"));
}

TEST(ScenarioLoader, MissingFileIsNamed) {
  const auto scenario = load_scenario("/nonexistent/scenario.yaml");
  ASSERT_FALSE(scenario);
  EXPECT_THAT(scenario.error().message, HasSubstr("/nonexistent/scenario.yaml: cannot open"));
}

}  // namespace
}  // namespace skytrack::config
