// skytrackd in operation: overload drops, SIGHUP reload, SIGTERM, bad configuration, no daemon.
#include <chrono>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <thread>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "end_to_end_test_support.hpp"
#include "process_helpers.hpp"

namespace skytrack::test {
namespace {

using namespace std::chrono_literals;
using ::testing::HasSubstr;

TEST_F(EndToEnd, OverloadDropsAreCountedAndTheNewestScanIsTracked) {
  // GIVEN skytrackd with a queue of 2 scans (drop oldest) and a replay allowed 64 scans in
  // flight, far more than the tracker can take at once
  simulate_and_track_offline();
  const std::string config = write_config(kProfile, "", "{capacity: 2, overload: drop_oldest}");
  Child daemon({kDaemon, "--config", config}, path("daemon.log"));
  ASSERT_TRUE(daemon.wait_for_log("running", 10s)) << daemon.log();
  // WHEN the scenario is replayed at max rate
  ASSERT_EQ(run({kTool, "replay", "--config", config, "--plots", path("plots.jsonl"), "--rate",
                 "max", "--window", "64", "--quiet"},
                path("replay.log"), 60s),
            0)
      << read_file(path("replay.log"));
  std::this_thread::sleep_for(500ms);  // the next status covers every scan
  ASSERT_EQ(run({kTool, "status", "--config", config}, path("status.log")), 0);
  daemon.signal(SIGTERM);
  ASSERT_EQ(daemon.wait(5s), 0) << daemon.log();
  // THEN every scan was either tracked or dropped and counted, and the drops were logged
  std::map<std::string, std::uint64_t> plots, scans;
  const auto numbers = status_numbers(read_file(path("status.log")), plots, scans);
  const auto sent = static_cast<double>(read_tracks(path("offline.tracks.jsonl")).size());
  EXPECT_EQ(numbers.at("scans_processed") + numbers.at("scans_dropped"), sent);
  EXPECT_GT(numbers.at("scans_dropped"), 0.0);
  EXPECT_TRUE(scans.empty());
  EXPECT_THAT(daemon.log(), HasSubstr("overload (drop_oldest, queue of 2): dropped"));
  // the last scan is never the one dropped, so its TrackBatch answered every scan sent
  EXPECT_THAT(read_file(path("replay.log")), HasSubstr("0 scans unanswered"));
}

TEST_F(EndToEnd, SighupReloadsAValidProfileAndKeepsTheOldOneOtherwise) {
  // GIVEN skytrackd running on a copy of the default profile
  const std::string profile = path("profile.yaml");
  std::filesystem::copy_file(kProfile, profile);
  const std::string original = read_file(profile);
  Child daemon({kDaemon, "--config", write_config(profile)}, path("daemon.log"));
  ASSERT_TRUE(daemon.wait_for_log("running", 10s)) << daemon.log();

  // WHEN only the version changes THEN the tracks are kept
  std::string renamed = original;
  renamed.replace(renamed.find("version: \"1\""), 12, "version: \"2\"");
  std::ofstream(profile) << renamed;
  daemon.signal(SIGHUP);
  ASSERT_TRUE(daemon.wait_for_log("tracking parameters unchanged, tracks kept", 5s))
      << daemon.log();
  // WHEN the profile is broken THEN the old one stays, with the error named
  std::ofstream(profile) << original << "\nnot_a_key: 1\n";
  daemon.signal(SIGHUP);
  ASSERT_TRUE(daemon.wait_for_log("not reloaded, keeping 'default' version 2", 5s)) << daemon.log();
  EXPECT_THAT(daemon.log(), HasSubstr("not_a_key"));
  // WHEN a tracking parameter changes THEN the daemon says why the tracks restart
  std::string tuned = original;
  tuned.replace(tuned.find("confirm_m: 3"), 12, "confirm_m: 2");
  std::ofstream(profile) << tuned;
  daemon.signal(SIGHUP);
  ASSERT_TRUE(daemon.wait_for_log("changes point.track_life", 5s)) << daemon.log();
  EXPECT_TRUE(daemon.running());

  // WHEN SIGTERM arrives THEN it exits 0 within a second
  const auto t0 = std::chrono::steady_clock::now();
  daemon.signal(SIGTERM);
  EXPECT_EQ(daemon.wait(5s), 0) << daemon.log();
  EXPECT_LT(std::chrono::steady_clock::now() - t0, 1s);
}

TEST_F(EndToEnd, InvalidConfigurationStartsNothing) {
  const std::string config = path("bad.yaml");
  std::ofstream(config)
      << "skytrackd: {instance: x}\ndds:\n  domain: 5\n  qos: {plots: {depth: 3}}\n";
  Child daemon({kDaemon, "--config", config}, path("daemon.log"));
  EXPECT_EQ(daemon.wait(10s), 2);
  EXPECT_THAT(daemon.log(), HasSubstr(config + ":4: dds.qos.plots.depth: unknown key"));
  EXPECT_THAT(daemon.log(), ::testing::Not(HasSubstr("DDS:")));
}

TEST_F(EndToEnd, LatencyBenchmarkAtARadarsPeriodAnswersEveryScanNoSooner) {
  // GIVEN skytrackd on the default profile
  const std::string config = write_config(kProfile);
  Child daemon({kDaemon, "--config", config}, path("daemon.log"));
  ASSERT_TRUE(daemon.wait_for_log("running", 10s)) << daemon.log();

  // WHEN the latency benchmark sends a scan every 100 ms, 2 of warm-up and 4 timed
  const auto start = std::chrono::steady_clock::now();
  const int code = run({kTool, "bench-latency", "--config", config, "--targets", "10", "--warmup",
                        "2", "--scans", "4", "--period-ms", "100"},
                       path("bench.log"), 60s);
  const auto elapsed = std::chrono::steady_clock::now() - start;
  daemon.signal(SIGTERM);
  ASSERT_EQ(daemon.wait(5s), 0) << daemon.log();

  // THEN every scan is answered, and the six went out at the period, not back to back
  EXPECT_EQ(code, 0) << read_file(path("bench.log"));
  EXPECT_THAT(read_file(path("bench.log")), HasSubstr("unanswered 0"));
  EXPECT_GE(elapsed, 500ms);  // the sixth scan leaves five periods after the first
}

TEST_F(EndToEnd, ReplayWithoutADaemonGivesUpAfterItsWait) {
  simulate_and_track_offline();
  const std::string config = write_config(kProfile);
  Child replay({kTool, "replay", "--config", config, "--plots", path("plots.jsonl"), "--wait",
                "0.5", "--quiet"},
               path("replay.log"));
  EXPECT_EQ(replay.wait(10s), 3);
  EXPECT_THAT(replay.log(), HasSubstr("no reader of 'skytrack_plots' matched"));
}

}  // namespace
}  // namespace skytrack::test
