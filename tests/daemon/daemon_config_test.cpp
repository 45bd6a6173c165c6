#include "skytrack/daemon/daemon_config.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace skytrack::daemon {
namespace {

using ::testing::HasSubstr;

const std::string kSource = SKYTRACK_SOURCE_DIR;

TEST(DaemonConfig, ShippedFileLoadsWithTheBuiltInDefaults) {
  // GIVEN the shipped configuration WHEN loaded
  const auto config = load_daemon_config(kSource + "/config/skytrackd.yaml");
  ASSERT_TRUE(config) << config.error().message;
  // THEN its values are the built-in defaults the tools use without --config
  const DaemonConfig defaults;
  EXPECT_EQ(config->profile, kSource + "/config/profiles/default.yaml");  // relative to file
  EXPECT_EQ(config->instance, defaults.instance);
  EXPECT_EQ(config->dds.domain, defaults.dds.domain);
  EXPECT_EQ(config->dds.topics.plots, defaults.dds.topics.plots);
  EXPECT_EQ(config->dds.topics.tracks, defaults.dds.topics.tracks);
  EXPECT_EQ(config->dds.topics.status, defaults.dds.topics.status);
  EXPECT_EQ(config->dds.plots.reliability, Reliability::kReliable);
  EXPECT_EQ(config->dds.plots.history_depth, defaults.dds.plots.history_depth);
  EXPECT_EQ(config->dds.tracks.durability, Durability::kTransientLocal);
  EXPECT_EQ(config->dds.tracks.history_depth, defaults.dds.tracks.history_depth);
  EXPECT_EQ(config->dds.status.deadline, defaults.dds.status.deadline);
  EXPECT_EQ(config->queue.capacity, defaults.queue.capacity);
  EXPECT_EQ(config->queue.overload, defaults.queue.overload);
  EXPECT_EQ(config->max_plots_per_scan, defaults.max_plots_per_scan);
  EXPECT_EQ(config->status_period, defaults.status_period);
  EXPECT_TRUE(config->sensors.empty());
  EXPECT_TRUE(config->dds.partitions.empty());
  EXPECT_FALSE(config->max_ahead_of_host);  // sensors' time bases vary: off unless set
}

TEST(DaemonConfig, ReadsEverySetting) {
  const auto config = parse_daemon_config(R"(
skytrackd: {instance: t1, profile: p.yaml, sensors: [1, 4], max_plots_per_scan: 500,
            status_period: 0.5, max_ahead_of_host: 30}
dds:
  domain: 17
  partition: radar-a
  topics: {plots: p, tracks: t, status: s}
  qos:
    plots: {reliability: best_effort, history_depth: 4}
    tracks: {durability: volatile, history_depth: 2}
    status: {deadline: 1.5}
queue: {capacity: 8, overload: drop_newest}
logging: {level: debug, sink: file, file: log/skytrackd.log, max_size_mb: 2, max_files: 3}
)",
                                          "inline.yaml", "/etc/skytrack");
  ASSERT_TRUE(config) << config.error().message;
  EXPECT_EQ(config->instance, "t1");
  EXPECT_EQ(config->profile, "/etc/skytrack/p.yaml");
  EXPECT_EQ(config->sensors, (std::vector<std::int64_t>{1, 4}));
  EXPECT_EQ(config->max_plots_per_scan, 500);
  EXPECT_EQ(config->status_period, 0.5);
  EXPECT_EQ(config->max_ahead_of_host, 30.0);
  EXPECT_EQ(config->dds.domain, 17);
  EXPECT_EQ(config->dds.partitions, (std::vector<std::string>{"radar-a"}));
  EXPECT_EQ(config->dds.topics.status, "s");
  EXPECT_EQ(config->dds.plots.reliability, Reliability::kBestEffort);
  EXPECT_EQ(config->dds.plots.history_depth, 4);
  EXPECT_EQ(config->dds.tracks.durability, Durability::kVolatile);
  EXPECT_EQ(config->dds.tracks.history_depth, 2);
  EXPECT_EQ(config->dds.status.deadline, 1.5);
  EXPECT_EQ(config->queue.capacity, 8);
  EXPECT_EQ(config->queue.overload, OverloadPolicy::kDropNewest);
  EXPECT_EQ(config->logging.sink, LogSink::kFile);
  EXPECT_EQ(config->logging.file, "/etc/skytrack/log/skytrackd.log");
  EXPECT_EQ(config->logging.max_files, 3);
}

TEST(DaemonConfig, EveryMistakeIsNamedWithFileLineAndKeyPath) {
  // GIVEN a file with an unknown key, a bad choice, an out-of-range domain and a bad sensor id
  const auto config = parse_daemon_config(R"(skytrackd:
  sensors: [1, x]
dds:
  domian: 3
  domain: 400
  qos:
    plots: {reliability: sometimes}
queue: {overload: drop_all}
)",
                                          "bad.yaml", "/tmp");
  // THEN all of them are reported, each with file, line and key path
  ASSERT_FALSE(config);
  const std::string& m = config.error().message;
  EXPECT_THAT(m, HasSubstr("bad.yaml:2: skytrackd.sensors"));
  EXPECT_THAT(m, HasSubstr("bad.yaml:4: dds.domian: unknown key"));
  EXPECT_THAT(m, HasSubstr("bad.yaml:5: dds.domain"));
  EXPECT_THAT(m, HasSubstr("dds.qos.plots.reliability: expected one of reliable, best_effort"));
  EXPECT_THAT(m, HasSubstr("queue.overload: expected one of drop_oldest, drop_newest"));
}

TEST(DaemonConfig, StatusDeadlineMustExceedThePeriod) {
  const auto config = parse_daemon_config(
      "skytrackd: {status_period: 2.0}\ndds: {qos: {status: {deadline: 1.0}}}\n", "d.yaml", "/");
  ASSERT_FALSE(config);
  EXPECT_THAT(config.error().message, HasSubstr("dds.qos.status.deadline"));
}

TEST(DaemonConfig, FileSinkNeedsAFileAndConsoleTakesNone) {
  const auto missing = parse_daemon_config("logging: {sink: file}\n", "l.yaml", "/");
  ASSERT_FALSE(missing);
  EXPECT_THAT(missing.error().message, HasSubstr("logging.file"));
  const auto extra = parse_daemon_config("logging: {file: x.log}\n", "l.yaml", "/");
  ASSERT_FALSE(extra);
  EXPECT_THAT(extra.error().message, HasSubstr("only used with sink: file"));
}

TEST(DaemonConfig, TheShippedTwoRadarDeploymentLoads) {
  // GIVEN the shipped trackers' and fusion node's configurations WHEN loaded
  for (const char* name : {"radar1", "radar2"}) {
    const auto tracker = load_daemon_config(kSource + "/config/two-radars/" + name + ".yaml");
    ASSERT_TRUE(tracker) << tracker.error().message;
    EXPECT_EQ(tracker->role, Role::kTracker);
    EXPECT_EQ(tracker->sensors.size(), 1u);
  }
  const auto node = load_daemon_config(kSource + "/config/two-radars/fusion.yaml");
  ASSERT_TRUE(node) << node.error().message;
  // THEN the node fuses the trackers' topic into its own, with the shipped fusion file
  EXPECT_EQ(node->role, Role::kFusion);
  EXPECT_EQ(node->sensors, (std::vector<std::int64_t>{1, 2}));
  EXPECT_EQ(node->fusion.config, kSource + "/config/fusion.yaml");
  EXPECT_EQ(node->fusion.input_topic, node->dds.topics.tracks);
  EXPECT_EQ(node->fusion.output_topic, "skytrack_fused");
}

TEST(DaemonConfig, TheFusionRoleRefusesWhatOnlyATrackerTakes) {
  const auto error_of = [](const std::string& yaml) {
    const auto config = parse_daemon_config(yaml, "d.yaml", "/etc");
    return config ? std::string("loaded") : config.error().message;
  };
  EXPECT_THAT(error_of("skytrackd: {role: fusion, profile: p.yaml}\n"),
              HasSubstr("skytrackd.profile: only used with role: tracker"));
  EXPECT_THAT(error_of("skytrackd: {role: fusion}\ninput: {from: asterix}\n"),
              HasSubstr("input: the fusion role takes TrackBatch over DDS only"));
  EXPECT_THAT(error_of("skytrackd: {role: fusion}\nfusion: {input_topic: a, output_topic: a}\n"),
              HasSubstr("fusion.output_topic: expected a topic other than input_topic"));
  EXPECT_THAT(error_of("fusion: {output_topic: b}\n"),
              HasSubstr("fusion: only used with skytrackd.role: fusion"));
  EXPECT_THAT(error_of("skytrackd: {role: fuser}\n"), HasSubstr("skytrackd.role"));
  const auto node = parse_daemon_config(
      "skytrackd: {role: fusion}\nfusion: {config: fusion.yaml, output_topic: f}\n", "d.yaml",
      "/etc");
  ASSERT_TRUE(node) << node.error().message;
  EXPECT_EQ(node->fusion.config, "/etc/fusion.yaml");  // relative to the file
  EXPECT_EQ(node->fusion.input_topic, "skytrack_tracks");
}

TEST(DaemonConfig, MissingFileAndSyntaxErrorsAreReported) {
  const auto missing = load_daemon_config("/nonexistent/skytrackd.yaml");
  ASSERT_FALSE(missing);
  EXPECT_THAT(missing.error().message, HasSubstr("/nonexistent/skytrackd.yaml: cannot open file"));
  const auto broken = parse_daemon_config("dds: {domain: [1\n", "broken.yaml", "/");
  ASSERT_FALSE(broken);
  EXPECT_THAT(broken.error().message, HasSubstr("broken.yaml"));
}

}  // namespace
}  // namespace skytrack::daemon
