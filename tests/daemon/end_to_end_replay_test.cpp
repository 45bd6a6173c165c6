// skytrackd over DDS on loopback records the offline tracks of replayed scenarios, per mode.
#include <algorithm>
#include <csignal>
#include <string>
#include <utility>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "end_to_end_test_support.hpp"
#include "process_helpers.hpp"
#include "skytrack/io/jsonl_reader.hpp"
#include "skytrack/io/jsonl_writer.hpp"

namespace skytrack::test {
namespace {

using namespace std::chrono_literals;
using ::testing::HasSubstr;

TEST_F(EndToEnd, ReplayAtMaxRateRecordsTheOfflineTracks) {
  // GIVEN the default scenario tracked offline, and skytrackd on the same profile
  simulate_and_track_offline();
  const std::string config = write_config(kProfile);
  Child daemon({kDaemon, "--config", config}, path("daemon.log"));
  ASSERT_TRUE(daemon.wait_for_log("running", 10s)) << daemon.log();
  Child record({kTool, "record", "--config", config, "--tracks", path("live.tracks.jsonl"),
                "--until-idle", "1.5"},
               path("record.log"));
  ASSERT_TRUE(record.wait_for_log("matched a TrackBatch writer", 10s)) << record.log();

  // WHEN the scenario is replayed over DDS at max rate and recorded
  ASSERT_NO_FATAL_FAILURE(replay_at_max_rate(config));
  ASSERT_EQ(record.wait(30s), 0) << record.log();
  // AND a display that joins late (transient-local tracks) ...
  ASSERT_EQ(run({kTool, "record", "--config", config, "--tracks", path("late.tracks.jsonl"),
                 "--until-idle", "0.5"},
                path("late.log"), 30s),
            0)
      << read_file(path("late.log"));
  daemon.signal(SIGTERM);
  ASSERT_EQ(daemon.wait(5s), 0) << daemon.log();

  // THEN the recorded tracks are the offline ones
  EXPECT_THAT(read_file(path("replay.log")), HasSubstr("0 scans unanswered"));
  const auto offline = read_tracks(path("offline.tracks.jsonl"));
  expect_same_tracks(read_tracks(path("live.tracks.jsonl")), offline);
  // ... and the late display received the current picture: the last scan's tracks
  expect_same_tracks(read_tracks(path("late.tracks.jsonl")), {offline.back()});
  EXPECT_THAT(daemon.log(), HasSubstr("config/dds/loopback.xml"));
}

/// The daemon on a mode's shipped profile records the offline tracks of a scenario of its
/// kind, replayed over DDS, and the mode's target is confirmed.
class ModeEndToEnd : public EndToEnd {
 protected:
  void records_the_offline_tracks(const std::string& scenario, const std::string& mode) {
    // GIVEN the mode's shipped profile on the scenario, tracked offline
    const std::string profile = kSource + "/config/profiles/" + mode + ".yaml";
    simulate_and_track_offline(scenario, profile);
    // Every frame kept for a late reader: the recorder's match may reach the daemon's writer
    // after the first frame under load, and a reader matched late gets the writer's history.
    const std::string config =
        write_config(profile, "", "{capacity: 256}", ", tracks: {history_depth: 1000}");
    Child daemon({kDaemon, "--config", config}, path("daemon.log"));
    ASSERT_TRUE(daemon.wait_for_log("running", 10s)) << daemon.log();
    Child record({kTool, "record", "--config", config, "--tracks", path("live.tracks.jsonl"),
                  "--until-idle", "1.5"},
                 path("record.log"));
    ASSERT_TRUE(record.wait_for_log("matched a TrackBatch writer", 10s)) << record.log();
    // WHEN its plots are replayed over DDS and the tracks recorded
    ASSERT_NO_FATAL_FAILURE(replay_at_max_rate(config));
    ASSERT_EQ(record.wait(30s), 0) << record.log();
    daemon.signal(SIGTERM);
    ASSERT_EQ(daemon.wait(5s), 0) << daemon.log();
    // THEN they are the offline ones, and the mode's target was confirmed
    EXPECT_THAT(read_file(path("replay.log")), HasSubstr("0 scans unanswered"));
    expect_same_tracks(read_tracks(path("live.tracks.jsonl")),
                       read_tracks(path("offline.tracks.jsonl")));
    EXPECT_THAT(read_file(path("live.tracks.jsonl")), HasSubstr("\"confirmed\""));
  }
};

TEST_F(ModeEndToEnd, BernoulliRecordsItsOfflineTracksOverDds) {
  records_the_offline_tracks("paper001_mmbpf", "bernoulli");
}

TEST_F(ModeEndToEnd, GroupRecordsItsOfflineTracksOverDds) {
  records_the_offline_tracks("paper000_exp1_groups", "group");
}

TEST_F(ModeEndToEnd, ExtendedRecordsItsOfflineTracksOverDds) {
  records_the_offline_tracks("paper002_extended", "extended");
}

TEST_F(EndToEnd, TwoSensorsOnOnePlotTopicGiveTheOfflineTracks) {
  // GIVEN the two-sensor fusion scenario merged into one stream in time order (sensors 1 and
  // 2, one scan each per second), tracked offline
  for (const char* name : {"paper004_fusion_merge", "paper004_fusion_merge_sensor2"}) {
    ASSERT_EQ(run({kTool, "simulate", "--scenario", kSource + "/config/scenarios/" + name + ".yaml",
                   "--plots", path(std::string(name) + ".plots.jsonl"), "--truth",
                   path(std::string(name) + ".truth.jsonl")},
                  path("simulate.log")),
              0)
        << read_file(path("simulate.log"));
  }
  std::vector<PlotScan> merged;
  for (const char* name : {"paper004_fusion_merge", "paper004_fusion_merge_sensor2"}) {
    auto reader = io::PlotStreamReader::open(path(std::string(name) + ".plots.jsonl"));
    ASSERT_TRUE(reader);
    while (auto scan = reader->next()) merged.push_back(std::move(*scan));
  }
  std::stable_sort(merged.begin(), merged.end(), [](const PlotScan& a, const PlotScan& b) {
    return a.time < b.time || (a.time == b.time && a.sensor < b.sensor);
  });
  {
    auto writer = io::JsonLinesWriter::open(path("plots.jsonl"));
    ASSERT_TRUE(writer);
    for (const auto& scan : merged) ASSERT_TRUE(writer->write(scan));
    ASSERT_TRUE(writer->close());
  }
  ASSERT_EQ(run({kTool, "track", "--profile", kProfile, "--plots", path("plots.jsonl"), "--out",
                 path("offline.tracks.jsonl"), "--quiet"},
                path("track.log")),
            0);
  const std::string config = write_config(kProfile, ", sensors: [1, 2]");
  Child daemon({kDaemon, "--config", config}, path("daemon.log"));
  ASSERT_TRUE(daemon.wait_for_log("running", 10s)) << daemon.log();
  Child record({kTool, "record", "--config", config, "--tracks", path("live.tracks.jsonl"),
                "--until-idle", "1.5"},
               path("record.log"));
  ASSERT_TRUE(record.wait_for_log("matched a TrackBatch writer", 10s)) << record.log();
  // WHEN it is replayed at max rate
  ASSERT_NO_FATAL_FAILURE(replay_at_max_rate(config));
  ASSERT_EQ(record.wait(30s), 0) << record.log();
  daemon.signal(SIGTERM);
  ASSERT_EQ(daemon.wait(5s), 0) << daemon.log();
  // THEN both sensors' scans were tracked as offline, one TrackBatch per scan
  const auto live = read_tracks(path("live.tracks.jsonl"));
  EXPECT_EQ(live.size(), merged.size());
  EXPECT_TRUE(std::any_of(live.begin(), live.end(), [](const auto& f) { return f.sensor == 2; }));
  expect_same_tracks(live, read_tracks(path("offline.tracks.jsonl")));
}

}  // namespace
}  // namespace skytrack::test
