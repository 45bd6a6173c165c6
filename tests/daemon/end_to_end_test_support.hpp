#pragma once
// The EndToEnd fixture (a DDS domain and directory of each test's own) and track comparisons.
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <simdjson.h>

#include "process_helpers.hpp"
#include "skytrack/core/track_report.hpp"
#include "skytrack/io/jsonl_reader.hpp"
#include "support/test_domain.hpp"

namespace skytrack::test {

inline const std::string kSource = SKYTRACK_SOURCE_DIR;
inline const std::string kTool = SKYTRACK_TOOL;
inline const std::string kDaemon = SKYTRACKD;
inline const std::string kProfile = kSource + "/config/profiles/default.yaml";

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
    using namespace std::chrono_literals;
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

inline std::vector<TrackFrame> read_tracks(const std::string& file) {
  std::vector<TrackFrame> frames;
  auto reader = io::TrackReader::open(file);
  if (!reader) return frames;
  while (auto frame = reader->next()) frames.push_back(std::move(*frame));
  return frames;
}

/// Same scans, same track numbers and statuses, positions and velocities equal to 1e-9.
inline void expect_same_tracks(const std::vector<TrackFrame>& live,
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
inline std::map<std::string, double> status_numbers(const std::string& output,
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

}  // namespace skytrack::test
