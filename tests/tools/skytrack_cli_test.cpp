// Runs the `skytrack` binary as a user would and checks what it prints.
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <simdjson.h>
#include "cli_runner.hpp"

namespace {

using ::testing::HasSubstr;

using skytrack::testing::RunResult;

RunResult run(const std::string& arguments) {
  return skytrack::testing::run_skytrack(arguments);
}

std::string data(const std::string& name) {
  return skytrack::testing::tool_data(name);
}

/// A number from the JSON summary line that `eval --json` prints.
double json_value(const std::string& output, const char* key) {
  const std::size_t start = output.find("{\"gospa_mean\"");
  if (start == std::string::npos) return std::nan("");
  const std::string line = output.substr(start, output.find('\n', start) - start);
  simdjson::dom::parser parser;
  double value = std::nan("");
  const auto element = parser.parse(line)[key];
  if (element.get_double().get(value) != simdjson::SUCCESS) {
    std::int64_t integer = 0;
    if (element.get_int64().get(integer) == simdjson::SUCCESS) value = static_cast<double>(integer);
  }
  return value;
}

TEST(SkytrackEval, HandMadeCaseGivesTheHandComputedGospa) {
  // t=0: truth {(0,0), (100,0)}, firm tracks {(3,4), (500,0)}, c = 20, p = 2:
  //   GOSPA^2 = 5^2 + c^2/2 (1 missed + 1 false) = 425, OSPA^2 = (25 + 400) / 2.
  // t=1: truth {(10,0)}, no tracks: GOSPA^2 = c^2/2 = 200, OSPA = c.
  const RunResult r = run("eval --truth " + data("hand.truth.jsonl") + " --tracks " +
                          data("hand.tracks.jsonl") + " --cutoff 20 --order 2 --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NEAR(json_value(r.output, "gospa_mean"), (std::sqrt(425.0) + std::sqrt(200.0)) / 2, 1e-9);
  EXPECT_NEAR(json_value(r.output, "ospa_mean"), (std::sqrt(425.0 / 2) + 20.0) / 2, 1e-9);
  EXPECT_NEAR(json_value(r.output, "gospa_missed_mean"), 1.0, 1e-12);
  EXPECT_NEAR(json_value(r.output, "gospa_false_mean"), 0.5, 1e-12);
  EXPECT_NEAR(json_value(r.output, "rmse_position"), 5.0, 1e-9);
  EXPECT_EQ(json_value(r.output, "scans"), 2.0);
  EXPECT_EQ(json_value(r.output, "track_lines_rejected"), 1.0);
  EXPECT_THAT(r.output, HasSubstr("hand.tracks.jsonl:2: invalid JSON"));
}

TEST(SkytrackSimulateAndEval, TruthAgainstItselfScoresZero) {
  const auto dir = std::filesystem::temp_directory_path() / "skytrack_cli_test";
  std::filesystem::create_directories(dir);
  const std::string plots = (dir / "d.plots.jsonl").string(),
                    truth = (dir / "d.truth.jsonl").string();
  const RunResult sim =
      run("simulate --scenario " + std::string(SKYTRACK_SOURCE_DIR) +
          "/config/scenarios/default.yaml --plots " + plots + " --truth " + truth + " --seed 5");
  ASSERT_EQ(sim.exit_code, 0) << sim.output;
  EXPECT_THAT(sim.output, HasSubstr("seed 5"));
  const RunResult r = run("eval --truth " + truth + " --tracks " + truth + " --json --plot " +
                          (dir / "d.svg").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(json_value(r.output, "gospa_mean"), 0.0);
  EXPECT_EQ(json_value(r.output, "ospa_mean"), 0.0);
  EXPECT_EQ(json_value(r.output, "id_changes"), 0.0);
  EXPECT_GT(json_value(r.output, "scans"), 10.0);
  EXPECT_GT(std::filesystem::file_size(dir / "d.svg"), 1000u);
  std::filesystem::remove_all(dir);
}

TEST(SkytrackSimulate, BadScenarioIsReportedWithItsKeyAndFails) {
  const RunResult r = run("simulate --scenario " + data("hand.truth.jsonl") +
                          " --plots /dev/null --truth /dev/null");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_THAT(r.output, HasSubstr("hand.truth.jsonl"));
}

TEST(SkytrackTrack, ThreeDimensionalProfileOnPlotsWithoutHeightStopsWithTheReason) {
  // GIVEN secondary-radar plots without flight levels and a profile that forces 3-D
  const auto dir = std::filesystem::temp_directory_path() / "skytrack_cli_refusal";
  std::filesystem::create_directories(dir);
  const std::string plots = (dir / "p.jsonl").string();
  {
    std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(plots.c_str(), "w"), std::fclose);
    ASSERT_TRUE(f);
    for (int k = 0; k < 3; ++k) {
      std::fprintf(f.get(),
                   "{\"sensor\": 1, \"scan\": %d, \"time\": %d, \"plots\": [{\"id\": 0, "
                   "\"range\": 40000, \"azimuth\": 0.5}]}\n",
                   k, 4 * k);
    }
  }
  // WHEN it is tracked
  const RunResult r = run("track --quiet --profile " + std::string(SKYTRACK_SOURCE_DIR) +
                          "/config/profiles/airborne.yaml --plots " + plots + " --out " +
                          (dir / "t.jsonl").string());
  // THEN the run stops at the first batch, naming the profile and what to change
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("batch 0: profile 'airborne' asks for 3-D tracking"));
  EXPECT_THAT(r.output, HasSubstr("use dimension: auto or 2"));
  std::filesystem::remove_all(dir);
}

TEST(SkytrackCheckProfile, TinySigmaIsRefusedWithItsKeyValueAndRange) {
  // GIVEN a profile whose range sigma is positive but absurd (squared, it is 0: a singular R)
  const auto dir = std::filesystem::temp_directory_path() / "skytrack_cli_check_profile";
  std::filesystem::create_directories(dir);
  const std::string profile = (dir / "tiny.yaml").string();
  {
    std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(profile.c_str(), "w"), std::fclose);
    ASSERT_TRUE(f);
    std::fputs(
        "profile: {name: tiny, version: 1}\nmeasurement:\n"
        "  default_sigma: {range: 1.0e-300}\n",
        f.get());
  }
  // WHEN check-profile reads it
  const RunResult r = run("check-profile " + profile);
  // THEN it fails, naming the key, the value and the accepted range
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("tiny.yaml:3: measurement.default_sigma.range: expected a "
                                  "number in [0.001, 100000], got 1e-300"));
  std::filesystem::remove_all(dir);
}

TEST(SkytrackEval, MissingFileFailsWithItsName) {
  const RunResult r = run("eval --truth /nonexistent/t.jsonl --tracks /nonexistent/k.jsonl");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_THAT(r.output, HasSubstr("/nonexistent/t.jsonl"));
}

TEST(SkytrackBenchLatency, WritePlotsGivesTheDaemonsLoadWithoutDds) {
  // GIVEN no daemon: --write-plots needs none
  const auto dir = std::filesystem::temp_directory_path() / "skytrack_cli_bench_plots";
  std::filesystem::create_directories(dir);
  const std::string plots = (dir / "bench.plots.jsonl").string();
  // WHEN the benchmark's scans are written (2 warm-up and 3 timed, 4 targets each)
  const RunResult w = run("bench-latency --targets 4 --scans 3 --warmup 2 --write-plots " + plots);
  ASSERT_EQ(w.exit_code, 0) << w.output;
  // THEN they are a plot stream the offline tracker reads whole, one scan per line
  const RunResult r =
      run("track --quiet --plots " + plots + " --out " + (dir / "t.jsonl").string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("5 batches (0 skipped), 20 plots (0 invalid"));
  EXPECT_THAT(r.output, HasSubstr("0 lines rejected"));
  std::filesystem::remove_all(dir);
}

}  // namespace
