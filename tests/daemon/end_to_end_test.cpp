// End to end over DDS on loopback: skytrackd, `skytrack replay` and `skytrack record` as
// separate processes, compared with the offline `skytrack track` run of the same input and
// profile. Each test uses its own DDS domain (ctest -j runs them in parallel) and directory.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <simdjson.h>

#include "process_helpers.hpp"
#include "skytrack/daemon/dds_session.hpp"
#include "skytrack/daemon/tsan_suppressions.hpp"
#include "skytrack/dds/conversion.hpp"
#include "skytrack/io/jsonl_reader.hpp"
#include "skytrack/io/jsonl_writer.hpp"
#include "support/test_domain.hpp"

namespace skytrack::test {
namespace {

using namespace std::chrono_literals;
using ::testing::HasSubstr;

const std::string kSource = SKYTRACK_SOURCE_DIR;
const std::string kTool = SKYTRACK_TOOL;
const std::string kDaemon = SKYTRACKD;
const std::string kProfile = kSource + "/config/profiles/default.yaml";

class EndToEnd : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("skytrack_e2e_" + std::string(info->name()) + "_" + std::to_string(getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    domain_ = lease_.id();
  }
  void TearDown() override {
    if (!HasFailure()) std::filesystem::remove_all(dir_);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  /// A daemon configuration on this test's domain; `extra` goes into the skytrackd section.
  /// `qos_extra`: more of dds.qos, e.g. ", tracks: {history_depth: 1000}".
  std::string write_config(const std::string& profile, const std::string& extra = "",
                           const std::string& queue = "{capacity: 256}",
                           const std::string& qos_extra = "") const {
    const std::string file = path("skytrackd.yaml");
    std::ofstream(file) << "skytrackd: {instance: e2e, profile: " << profile
                        << ", status_period: 0.2" << extra << "}\n"
                        << "dds: {domain: " << domain_ << ", qos: {status: {deadline: 1.0}"
                        << qos_extra << "}}\n"
                        << "queue: " << queue << "\n";
    return file;
  }

  /// Simulates the shipped default scenario and tracks it offline with the default profile.
  /// Replays plots.jsonl over DDS at max rate; the replay must succeed.
  void replay_at_max_rate(const std::string& config) {
    ASSERT_EQ(run({kTool, "replay", "--config", config, "--plots", path("plots.jsonl"), "--rate",
                   "max", "--quiet"},
                  path("replay.log"), 60s),
              0)
        << read_file(path("replay.log"));
  }

  void simulate_and_track_offline(const std::string& scenario = "default",
                                  const std::string& profile = kProfile) {
    ASSERT_EQ(
        run({kTool, "simulate", "--scenario", kSource + "/config/scenarios/" + scenario + ".yaml",
             "--plots", path("plots.jsonl"), "--truth", path("truth.jsonl")},
            path("simulate.log")),
        0)
        << read_file(path("simulate.log"));
    ASSERT_EQ(run({kTool, "track", "--profile", profile, "--plots", path("plots.jsonl"), "--out",
                   path("offline.tracks.jsonl"), "--quiet"},
                  path("track.log")),
              0)
        << read_file(path("track.log"));
  }

  std::filesystem::path dir_;
  TestDomain lease_;
  int domain_ = 0;
};

std::vector<TrackFrame> read_tracks(const std::string& file) {
  std::vector<TrackFrame> frames;
  auto reader = io::TrackReader::open(file);
  if (!reader) return frames;
  while (auto frame = reader->next()) frames.push_back(std::move(*frame));
  return frames;
}

/// Same scans, same track numbers and statuses, positions and velocities equal to 1e-9.
void expect_same_tracks(const std::vector<TrackFrame>& live,
                        const std::vector<TrackFrame>& offline) {
  ASSERT_EQ(live.size(), offline.size());
  std::size_t tracks = 0;
  for (std::size_t i = 0; i < live.size(); ++i) {
    const TrackFrame& a = live[i];
    const TrackFrame& b = offline[i];
    ASSERT_EQ(a.sensor, b.sensor) << "frame " << i;
    ASSERT_EQ(a.scan, b.scan) << "frame " << i;
    EXPECT_EQ(a.time, b.time) << "frame " << i;
    ASSERT_EQ(a.tracks.size(), b.tracks.size()) << "scan " << a.scan;
    for (std::size_t t = 0; t < a.tracks.size(); ++t) {
      EXPECT_EQ(a.tracks[t].id, b.tracks[t].id) << "scan " << a.scan;
      EXPECT_EQ(a.tracks[t].status, b.tracks[t].status) << "scan " << a.scan;
      EXPECT_LE((a.tracks[t].position - b.tracks[t].position).cwiseAbs().maxCoeff(), 1e-9);
      EXPECT_LE((a.tracks[t].velocity - b.tracks[t].velocity).cwiseAbs().maxCoeff(), 1e-9);
      EXPECT_EQ(a.tracks[t].kind, b.tracks[t].kind) << "scan " << a.scan;
      EXPECT_EQ(a.tracks[t].members, b.tracks[t].members) << "scan " << a.scan;
      ASSERT_EQ(a.tracks[t].extent.has_value(), b.tracks[t].extent.has_value());
      if (a.tracks[t].extent) {
        EXPECT_LE((*a.tracks[t].extent - *b.tracks[t].extent).cwiseAbs().maxCoeff(), 1e-9);
      }
      ++tracks;
    }
    EXPECT_EQ(a.associations.size(), b.associations.size()) << "scan " << a.scan;
    EXPECT_EQ(a.events, b.events) << "scan " << a.scan;
  }
  EXPECT_GT(tracks, 0u) << "nothing was tracked: the comparison would prove nothing";
}

/// The daemon's latest TrackerStatus, via `skytrack status`.
std::map<std::string, double> status_numbers(const std::string& output,
                                             std::map<std::string, std::uint64_t>& plots,
                                             std::map<std::string, std::uint64_t>& scans) {
  std::map<std::string, double> out;
  simdjson::dom::parser parser;
  simdjson::dom::element doc;
  const std::string line = output.substr(0, output.find('\n'));
  if (parser.parse(line).get(doc) != simdjson::SUCCESS) return out;
  for (const char* key : {"scans_processed", "plots_processed", "scans_dropped", "queue_depth"}) {
    std::uint64_t v = 0;
    if (doc[key].get_uint64().get(v) == simdjson::SUCCESS) out[key] = static_cast<double>(v);
  }
  const auto counts = [&](const char* key, std::map<std::string, std::uint64_t>& into) {
    simdjson::dom::object object;
    if (doc[key].get_object().get(object) != simdjson::SUCCESS) return;
    for (auto [k, v] : object) into[std::string(k)] = v.get_uint64().value_unsafe();
  };
  counts("plots_rejected", plots);
  counts("scans_rejected", scans);
  return out;
}

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

/// Publishes samples straight onto the plot topic, so that values a JSON file cannot carry
/// (NaN, inf) and malformed samples reach the daemon.
class RawPublisher {
 public:
  explicit RawPublisher(int domain) {
    daemon::DdsSettings settings;
    settings.domain = domain;
    auto session = daemon::DdsSession::open(settings);
    if (!session) return;
    session_.emplace(std::move(*session));
    auto topic = session_->topic(&skytrack_dds_PlotBatch_desc, settings.topics.plots);
    if (!topic) return;
    auto writer = session_->writer(*topic, daemon::plots_writer_qos(settings).get());
    if (writer) writer_ = *writer;
  }
  bool ready() { return writer_ > 0 && daemon::wait_for_readers(writer_, 1, 10s); }
  bool write(const PlotScan& scan) {
    auto sample = dds::to_dds(scan);
    return sample && dds_write(writer_, sample->data()) == DDS_RETCODE_OK;
  }
  bool write(dds::PlotBatchSample& sample) {
    return dds_write(writer_, sample.data()) == DDS_RETCODE_OK;
  }

 private:
  std::optional<daemon::DdsSession> session_;
  dds_entity_t writer_ = 0;
};

Plot polar(std::int64_t id, double range) {
  Plot p;
  p.id = id;
  p.range = range;
  p.azimuth = 0.3;
  p.elevation = 0.01;
  return p;
}

TEST_F(EndToEnd, BadSamplesAreCountedAndTheGoodScansTracksAreUnchanged) {
  // GIVEN the default scenario tracked offline, and skytrackd accepting sensor 1 only with at
  // most 1000 plots per scan
  simulate_and_track_offline();
  std::vector<PlotScan> good;
  {
    auto reader = io::PlotStreamReader::open(path("plots.jsonl"));
    ASSERT_TRUE(reader);
    while (auto scan = reader->next()) good.push_back(std::move(*scan));
  }
  ASSERT_GT(good.size(), 30u);
  ASSERT_EQ(good.front().sensor, 1u);
  std::uint64_t good_plots = 0;
  for (const auto& s : good) good_plots += s.plots.size();
  const std::string config = write_config(kProfile, ", sensors: [1], max_plots_per_scan: 1000");
  Child daemon({kDaemon, "--config", config}, path("daemon.log"));
  ASSERT_TRUE(daemon.wait_for_log("running", 10s)) << daemon.log();
  Child record({kTool, "record", "--config", config, "--tracks", path("live.tracks.jsonl"),
                "--until-idle", "1.5"},
               path("record.log"));
  ASSERT_TRUE(record.wait_for_log("matched a TrackBatch writer", 10s)) << record.log();
  RawPublisher publisher(domain_);
  ASSERT_TRUE(publisher.ready());

  // WHEN the good scans go out with bad plots and bad samples mixed in
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < good.size(); ++i) {
    PlotScan scan = good[i];
    if (i == 5) scan.plots.push_back(polar(9001, nan));    // non-finite polar value
    if (i == 7) scan.plots.push_back(polar(9002, -50.0));  // negative range
    if (i == 9) {
      Plot p;
      p.id = 9003;
      p.form = PlotForm::kCartesian;
      p.x = std::numeric_limits<double>::infinity();
      scan.plots.push_back(p);  // non-finite Cartesian value
    }
    if (i == 11) scan.plots.push_back(polar(9004, 5e22));  // range beyond max_range
    ASSERT_TRUE(publisher.write(scan));
    const PlotScan& next = good[std::min(i + 1, good.size() - 1)];
    if (i == 10) {
      ASSERT_TRUE(publisher.write(good[i]));  // duplicate scan
    }
    if (i == 12) {
      ASSERT_TRUE(publisher.write(good[3]));  // out-of-order scan
    }
    if (i == 14) {
      PlotScan other = next;
      other.sensor = 99;  // unknown sensor
      ASSERT_TRUE(publisher.write(other));
    }
    if (i == 16) {
      PlotScan huge = next;
      huge.plots.clear();
      for (int k = 0; k < 1001; ++k) huge.plots.push_back(polar(k, 1000.0 + k));
      ASSERT_TRUE(publisher.write(huge));  // too many plots
    }
    if (i == 18) {
      auto sample = dds::to_dds(next);
      ASSERT_TRUE(sample);
      sample->get().plot_flags._length -= 1;  // malformed sample
      ASSERT_TRUE(publisher.write(*sample));
      sample->get().plot_flags._length += 1;
    }
    if (i == 20) {
      PlotScan when = next;
      when.time = nan;  // non-finite batch time
      ASSERT_TRUE(publisher.write(when));
    }
    if (i == 22) {
      PlotScan where = next;
      where.platform.position.z() = nan;  // non-finite platform state
      ASSERT_TRUE(publisher.write(where));
    }
    if (i == 24) {
      PlotScan back = next;
      back.time = good[i].time - 1.0;  // time goes backwards
      ASSERT_TRUE(publisher.write(back));
    }
    if (i == 26) {
      PlotScan ahead = next;
      ahead.time += 50.0 * 365.25 * 86400.0;  // time jumps forward: the sensor goes on
      ASSERT_TRUE(publisher.write(ahead));
    }
  }
  ASSERT_EQ(record.wait(30s), 0) << record.log();
  ASSERT_EQ(run({kTool, "status", "--config", config}, path("status.log")), 0)
      << read_file(path("status.log"));
  daemon.signal(SIGTERM);
  ASSERT_EQ(daemon.wait(5s), 0) << daemon.log();

  // THEN every bad sample is counted under its reason in TrackerStatus ...
  std::map<std::string, std::uint64_t> plots, scans;
  const auto numbers = status_numbers(read_file(path("status.log")), plots, scans);
  EXPECT_EQ(numbers.at("scans_processed"), static_cast<double>(good.size()));
  EXPECT_EQ(numbers.at("plots_processed"), static_cast<double>(good_plots + 4));
  EXPECT_EQ(numbers.at("scans_dropped"), 0.0);
  const std::map<std::string, std::uint64_t> expected_plots{{"non-finite polar value", 1},
                                                            {"negative range", 1},
                                                            {"non-finite Cartesian value", 1},
                                                            {"range beyond max_range", 1}};
  EXPECT_EQ(plots, expected_plots);
  const std::map<std::string, std::uint64_t> expected_scans{{"duplicate scan", 1},
                                                            {"out-of-order scan", 1},
                                                            {"unknown sensor", 1},
                                                            {"too many plots", 1},
                                                            {"malformed sample", 1},
                                                            {"non-finite batch time", 1},
                                                            {"non-finite platform state", 1},
                                                            {"time goes backwards", 1},
                                                            {"time jumps forward", 1}};
  EXPECT_EQ(scans, expected_scans);
  // ... and the tracks are those of the clean stream
  expect_same_tracks(read_tracks(path("live.tracks.jsonl")),
                     read_tracks(path("offline.tracks.jsonl")));
}

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
