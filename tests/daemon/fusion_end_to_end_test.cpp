// The fusion role end to end over DDS on loopback: two skytrackd trackers (one per radar of
// the shipped two-radar scenario), one skytrackd in the fusion role, `skytrack replay` and two
// recorders, all separate processes on this test's own DDS domain. The fused picture is
// scored against the truth and compared with `skytrack fuse` run on the recorded local tracks.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <optional>
#include <set>

#include <gtest/gtest.h>
#include <simdjson.h>

#include "process_helpers.hpp"
#include "skytrack/io/jsonl_reader.hpp"
#include "skytrack/io/jsonl_writer.hpp"
#include "support/test_domain.hpp"

namespace skytrack::test {
namespace {

using namespace std::chrono_literals;

const std::string kSource = SKYTRACK_SOURCE_DIR;
const std::string kTool = SKYTRACK_TOOL;
const std::string kDaemon = SKYTRACKD;
const std::string kScenarios = kSource + "/config/scenarios/";
const std::string kFusionFile = kSource + "/config/fusion.yaml";
// Scored as the deployment docs score it: 500 m, a few times these radars' cross-range
// errors at 40-60 km (2 mrad).
const std::string kCutoff = "500";

struct Score {
  double gospa = 0.0;
  int id_changes = -1;
  std::size_t scans = 0;
  std::size_t right_count = 0;  // scans after warm-up with as many firm tracks as targets
  std::size_t counted = 0;      // scans after warm-up
};

class FusionEndToEnd : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("skytrack_fusion_" + std::string(info->name()) + "_" + std::to_string(getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    domain_ = lease_.id();
  }
  void TearDown() override {
    fusion_.reset();  // kills what is still running
    tracker1_.reset();
    tracker2_.reset();
    if (!HasFailure()) std::filesystem::remove_all(dir_);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  /// A daemon configuration on this test's domain.
  std::string write_config(const std::string& name, const std::string& skytrackd,
                           const std::string& rest = "") const {
    const std::string file = path(name);
    std::ofstream(file) << "skytrackd: {status_period: 0.2, " << skytrackd << "}\n"
                        << "dds: {domain: " << domain_
                        << ", qos: {status: {deadline: 1.0}, tracks: {history_depth: 1000}}}\n"
                        << rest;
    return file;
  }
  std::string write_recorder_config(const std::string& name, const std::string& topic) const {
    const std::string file = path(name);
    std::ofstream(file) << "dds: {domain: " << domain_ << ", topics: {tracks: " << topic
                        << "}, qos: {tracks: {history_depth: 1000}}}\n";
    return file;
  }

  void simulate(const std::string& scenario) {
    ASSERT_EQ(run({kTool, "simulate", "--scenario", kScenarios + scenario + ".yaml", "--plots",
                   path(scenario + ".plots.jsonl"), "--truth", path(scenario + ".truth.jsonl")},
                  path("simulate.log")),
              0)
        << read_file(path("simulate.log"));
  }

  /// Runs the two trackers, the fusion node and the recorders on `plots` (one file per radar).
  void run_deployment(const std::vector<std::string>& plots) {
    const std::string profile = kSource + "/config/profiles/default.yaml";
    const std::string t1 =
        write_config("radar1.yaml", "instance: radar1, profile: " + profile + ", sensors: [1]");
    const std::string t2 =
        write_config("radar2.yaml", "instance: radar2, profile: " + profile + ", sensors: [2]");
    const std::string node =
        write_config("fusion.yaml", "instance: fusion, role: fusion, sensors: [1, 2]",
                     "fusion: {config: " + kFusionFile + "}\n");
    tracker1_.emplace(std::vector<std::string>{kDaemon, "--config", t1}, path("radar1.log"));
    tracker2_.emplace(std::vector<std::string>{kDaemon, "--config", t2}, path("radar2.log"));
    fusion_.emplace(std::vector<std::string>{kDaemon, "--config", node}, path("fusion.log"));
    for (const Child* child : {&*tracker1_, &*tracker2_, &*fusion_}) {
      ASSERT_TRUE(child->wait_for_log("running", 10s)) << child->log();
    }
    Child local(
        {kTool, "record", "--config", write_recorder_config("local.yaml", "skytrack_tracks"),
         "--tracks", path("local.tracks.jsonl"), "--until-idle", "2"},
        path("record-local.log"));
    Child fused({kTool, "record", "--config", write_recorder_config("fused.yaml", "skytrack_fused"),
                 "--tracks", path("fused.tracks.jsonl"), "--until-idle", "3"},
                path("record-fused.log"));
    ASSERT_TRUE(local.wait_for_log("matched a TrackBatch writer", 10s)) << local.log();
    ASSERT_TRUE(fused.wait_for_log("matched a TrackBatch writer", 10s)) << fused.log();
    // As fast as the trackers answer, one scan in flight: the two trackers' frames reach the
    // fusion node in time order across sensors, as they do live.
    std::vector<std::string> replay = {kTool, "replay",   "--config", t1,       "--rate",
                                       "max", "--window", "1",        "--quiet"};
    for (const std::string& file : plots) {
      replay.push_back("--plots");
      replay.push_back(file);
    }
    ASSERT_EQ(run(replay, path("replay.log"), 60s), 0) << read_file(path("replay.log"));
    ASSERT_EQ(local.wait(30s), 0) << local.log();
    for (Child* tracker : {&*tracker1_, &*tracker2_}) {
      tracker->signal(SIGTERM);
      ASSERT_EQ(tracker->wait(5s), 0) << tracker->log();
    }
    fusion_->signal(SIGTERM);  // fuses the cycles still open and publishes them
    ASSERT_EQ(fusion_->wait(5s), 0) << fusion_->log();
    ASSERT_EQ(fused.wait(30s), 0) << fused.log();
  }

  /// `skytrack eval` of `tracks` against the truth, with the per-scan count of firm tracks.
  Score score(const std::string& tracks, double warm_up) {
    const std::string json = path("eval.json");
    const std::string scans = path("eval.scans.jsonl");
    std::filesystem::remove(json);  // run() appends to its log
    std::filesystem::remove(scans);
    const int rc = run({kTool, "eval", "--truth", path("fusion_two_radars.truth.jsonl"), "--tracks",
                        tracks, "--cutoff", kCutoff, "--json", "--per-scan", scans},
                       json);
    EXPECT_EQ(rc, 0) << read_file(json);
    Score out;
    // The log holds eval's notes (stderr) and then its JSON line (stdout).
    const std::string printed = read_file(json);
    const std::size_t start = printed.find("\n{");
    const std::string line = printed.rfind('{', 0) == 0   ? printed
                             : start == std::string::npos ? std::string()
                                                          : printed.substr(start + 1);
    simdjson::dom::parser parser;
    simdjson::dom::element summary;
    if (parser.parse(line).get(summary) != simdjson::SUCCESS) {
      ADD_FAILURE() << "eval printed no JSON: " << read_file(json);
      return out;
    }
    out.gospa = summary["gospa_mean"].get_double().value_unsafe();
    out.id_changes = static_cast<int>(summary["id_changes"].get_int64().value_unsafe());
    std::ifstream in(scans);
    for (std::string line; std::getline(in, line);) {
      simdjson::dom::element scan;
      if (parser.parse(line).get(scan) != simdjson::SUCCESS) continue;
      ++out.scans;
      if (scan["time"].get_double().value_unsafe() < warm_up) continue;
      ++out.counted;
      if (scan["tracks"].get_int64().value_unsafe() == scan["truths"].get_int64().value_unsafe()) {
        ++out.right_count;
      }
    }
    return out;
  }

  std::filesystem::path dir_;
  TestDomain lease_;
  int domain_ = 0;
  std::optional<Child> tracker1_, tracker2_, fusion_;
};

std::vector<TrackFrame> read_tracks(const std::string& file) {
  std::vector<TrackFrame> frames;
  auto reader = io::TrackReader::open(file);
  if (!reader) return frames;
  while (auto frame = reader->next()) frames.push_back(std::move(*frame));
  return frames;
}

// Local trackers confirm a target after a few revolutions of 4 s: the count is judged after.
constexpr double kWarmUp = 20.0;

TEST_F(FusionEndToEnd, FusedPictureBeatsEitherRadarAndMatchesTheOfflineFusion) {
  // GIVEN the two radars' plots, and each radar tracked alone (offline, default profile)
  simulate("fusion_two_radars");
  simulate("fusion_two_radars_sensor2");
  const std::vector<std::string> plots = {path("fusion_two_radars.plots.jsonl"),
                                          path("fusion_two_radars_sensor2.plots.jsonl")};
  double best_single = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < plots.size(); ++i) {
    const std::string out = path("radar" + std::to_string(i + 1) + ".tracks.jsonl");
    ASSERT_EQ(
        run({kTool, "track", "--plots", plots[i], "--out", out, "--quiet"}, path("track.log")), 0)
        << read_file(path("track.log"));
    best_single = std::min(best_single, score(out, kWarmUp).gospa);
  }
  // WHEN both are replayed into their trackers and the fusion node fuses the two streams
  ASSERT_NO_FATAL_FAILURE(run_deployment(plots));
  // THEN the fused picture is better than the better radar's, with the right number of
  // system tracks in at least 95 % of scans and no number change
  const Score fused = score(path("fused.tracks.jsonl"), kWarmUp);
  std::cout << "fused GOSPA " << fused.gospa << " m, better radar alone " << best_single
            << " m; right count in " << fused.right_count << " of " << fused.counted << " scans\n";
  ASSERT_EQ(fused.scans, 75u);
  EXPECT_LT(fused.gospa, best_single);
  EXPECT_GE(static_cast<double>(fused.right_count), 0.95 * static_cast<double>(fused.counted))
      << fused.right_count << " of " << fused.counted;
  EXPECT_EQ(fused.id_changes, 0);
  // ... every fused track lists its local tracks, from both radars for most of them
  const auto live = read_tracks(path("fused.tracks.jsonl"));
  std::set<std::uint32_t> sensors;
  for (const auto& frame : live) {
    for (const auto& track : frame.tracks) {
      if (track.status == TrackStatus::kDeleted) continue;
      EXPECT_FALSE(track.sources.empty()) << "system track " << track.id << " t " << frame.time;
      for (const auto& source : track.sources) sensors.insert(source.sensor);
    }
  }
  EXPECT_EQ(sensors, (std::set<std::uint32_t>{1, 2}));
  // ... and `skytrack fuse` on the recorded local tracks gives the same frames
  ASSERT_EQ(run({kTool, "fuse", "--tracks", path("local.tracks.jsonl"), "--out",
                 path("offline.fused.jsonl"), "--config", kFusionFile},
                path("fuse.log")),
            0)
      << read_file(path("fuse.log"));
  const auto offline = read_tracks(path("offline.fused.jsonl"));
  ASSERT_EQ(live.size(), offline.size());
  for (std::size_t i = 0; i < live.size(); ++i) {
    EXPECT_EQ(live[i].scan, offline[i].scan);
    EXPECT_EQ(live[i].time, offline[i].time);
    ASSERT_EQ(live[i].tracks.size(), offline[i].tracks.size()) << "t " << live[i].time;
    for (std::size_t t = 0; t < live[i].tracks.size(); ++t) {
      const TrackReport& a = live[i].tracks[t];
      const TrackReport& b = offline[i].tracks[t];
      EXPECT_EQ(a.id, b.id);
      EXPECT_EQ(a.status, b.status);
      EXPECT_EQ(a.sources, b.sources);
      EXPECT_LE((a.position - b.position).cwiseAbs().maxCoeff(), 1e-9);
    }
  }
}

TEST_F(FusionEndToEnd, SystemNumbersSurviveARadarGoingSilent) {
  // GIVEN radar 2's plots only up to t = 150 s (its feed stops halfway)
  simulate("fusion_two_radars");
  simulate("fusion_two_radars_sensor2");
  {
    auto reader = io::PlotStreamReader::open(path("fusion_two_radars_sensor2.plots.jsonl"));
    ASSERT_TRUE(reader);
    auto writer = io::JsonLinesWriter::open(path("radar2.half.plots.jsonl"));
    ASSERT_TRUE(writer);
    while (auto scan = reader->next()) {
      if (scan->time <= 150.0) {
        ASSERT_TRUE(writer->write(*scan));
      }
    }
    ASSERT_TRUE(writer->close());
  }
  // WHEN both are replayed through the deployment
  ASSERT_NO_FATAL_FAILURE(
      run_deployment({path("fusion_two_radars.plots.jsonl"), path("radar2.half.plots.jsonl")}));
  // THEN the picture goes on from radar 1 alone with the same system numbers
  const Score fused = score(path("fused.tracks.jsonl"), kWarmUp);
  EXPECT_EQ(fused.scans, 75u);
  EXPECT_EQ(fused.id_changes, 0);
  const auto live = read_tracks(path("fused.tracks.jsonl"));
  ASSERT_FALSE(live.empty());
  EXPECT_GT(live.back().time, 250.0);
  for (const auto& track : live.back().tracks) {
    for (const auto& source : track.sources) EXPECT_EQ(source.sensor, 1u);
  }
}

}  // namespace
}  // namespace skytrack::test
