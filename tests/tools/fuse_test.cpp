// `skytrack fuse` end to end: two small track files (one with a malformed line) into one
// fused file, read back.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cli_runner.hpp"

#include "skytrack/io/jsonl_reader.hpp"
#include "skytrack/io/jsonl_writer.hpp"

namespace skytrack {
namespace {

using ::testing::HasSubstr;

TrackReport local(std::int64_t id, double x, double y) {
  TrackReport t;
  t.id = id;
  t.status = TrackStatus::kConfirmed;
  t.position = {x, y, 0.0};
  t.velocity = {100.0, 0.0, 0.0};
  t.covariance = {400, 0, 0, 0, 0, 25, 0, 0, 0, 0, 400, 0, 0, 0, 0, 25};
  return t;
}

/// Sensor `sensor`'s file: two targets, 10 scans of 1 s, numbered base + 1 and base + 2.
std::string write_input(const std::filesystem::path& dir, std::uint32_t sensor, double dy,
                        bool broken_line) {
  const std::string path = (dir / ("s" + std::to_string(sensor) + ".tracks.jsonl")).string();
  std::ofstream out(path);
  for (int k = 0; k < 10; ++k) {
    TrackFrame f;
    f.sensor = sensor;
    f.scan = static_cast<std::uint64_t>(k);
    f.time = k;
    f.tracks = {local(sensor * 10 + 1, 100.0 * k, dy), local(sensor * 10 + 2, 100.0 * k, 8000)};
    out << io::to_json(f) << "\n";
    if (broken_line && k == 4) out << "{\"sensor\": 2, \"time\": \n";
  }
  return path;
}

TEST(SkytrackFuse, FusesTwoFilesAndReportsABadLine) {
  const auto dir = std::filesystem::temp_directory_path() / "skytrack_fuse_test";
  std::filesystem::create_directories(dir);
  const std::string a = write_input(dir, 1, 0.0, false);
  const std::string b = write_input(dir, 2, 15.0, true);
  const std::string out = (dir / "fused.tracks.jsonl").string();
  const auto r = testing::run_skytrack("fuse --tracks " + a + " --tracks " + b + " --out " + out +
                                       " --config " + SKYTRACK_SOURCE_DIR + "/config/fusion.yaml");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("s2.tracks.jsonl:6:"));  // file:line: reason
  EXPECT_THAT(r.output, HasSubstr("frames in: 20"));
  EXPECT_THAT(r.output, HasSubstr("cycles out: 10"));
  EXPECT_THAT(r.output, HasSubstr("system tracks: 2"));
  EXPECT_THAT(r.output, HasSubstr("1 lines rejected"));

  std::vector<TrackFrame> fused;
  auto reader = io::TrackReader::open(out);
  ASSERT_TRUE(reader) << reader.error().message;
  while (auto f = reader->next()) fused.push_back(std::move(*f));
  ASSERT_EQ(fused.size(), 10u);
  EXPECT_EQ(fused.back().time, 9.0);
  ASSERT_EQ(fused.back().tracks.size(), 2u);
  for (const TrackReport& t : fused.back().tracks) {
    ASSERT_EQ(t.sources.size(), 2u);
    EXPECT_EQ(t.sources[1].track - t.sources[0].track, 10);
  }
  std::filesystem::remove_all(dir);
}

TEST(SkytrackFuse, ABadConfigurationIsRefusedWithItsLine) {
  const auto dir = std::filesystem::temp_directory_path() / "skytrack_fuse_cfg_test";
  std::filesystem::create_directories(dir);
  const std::string cfg = (dir / "f.yaml").string();
  std::ofstream(cfg) << "fusion:\n  gate: -2\n";
  const auto r = testing::run_skytrack("fuse --tracks x --out y --config " + cfg);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.output, HasSubstr("f.yaml:2: fusion.gate"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace skytrack
