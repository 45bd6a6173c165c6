// `skytrack import-asterix` on the committed excerpts (tests/data/asterix): what it prints,
// what it writes, its options and its reports of damaged input.
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cli_runner.hpp"

#include "skytrack/io/jsonl_reader.hpp"

namespace {

using ::testing::HasSubstr;

using skytrack::testing::RunResult;

RunResult run(const std::string& arguments) {
  return skytrack::testing::run_skytrack(arguments);
}

std::string excerpt(const std::string& name) {
  return std::string(SKYTRACK_SOURCE_DIR) + "/tests/data/asterix/" + name;
}

std::string temp(const std::string& name) {
  return (std::filesystem::temp_directory_path() /
          ("skytrack_import_" + std::to_string(getpid()) + "_" + name))
      .string();
}

std::vector<skytrack::PlotScan> read_scans(const std::string& path) {
  std::vector<skytrack::PlotScan> out;
  auto reader = skytrack::io::PlotStreamReader::open(path);
  if (!reader) return out;
  while (auto s = reader->next()) out.push_back(std::move(*s));
  return out;
}

TEST(ImportAsterix, CanalAExcerptGivesRevolutionsClosedByNorthMarkers) {
  const std::string out = temp("canalA.plots.jsonl");
  const RunResult r =
      run("import-asterix " + excerpt("canalA_excerpt.pcap") + " --plots " + out + " --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("325 plots in 10 batches"));
  EXPECT_THAT(r.output, HasSubstr("CAT001 291; CAT002 9"));
  EXPECT_THAT(r.output, HasSubstr("9 north markers"));
  EXPECT_THAT(r.output, HasSubstr("errors: 0"));
  const auto scans = read_scans(out);
  ASSERT_EQ(scans.size(), 10u);
  EXPECT_EQ(scans[0].sensor, 20u * 256u + 130u);
  EXPECT_FALSE(scans[1].coverage);  // a whole turn between north markers
  EXPECT_TRUE(scans[1].plots[0].mode3a);
  EXPECT_TRUE(scans[1].plots[0].flight_level);
  EXPECT_GT(scans[1].time, 66431.0);
  std::filesystem::remove(out);
}

TEST(ImportAsterix, BatchesPerNPlotsAndSelectsTheSensor) {
  const std::string out = temp("block.plots.jsonl");
  RunResult r = run("import-asterix " + excerpt("canalA_excerpt.pcap") + " --plots " + out +
                    " --batch block:100");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("325 plots in 4 batches"));
  r = run("import-asterix " + excerpt("canalA_excerpt.pcap") + " " + excerpt("bds30_excerpt.pcap") +
          " --plots " + out + " --sensor 20/4");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("30 plots in"));
  EXPECT_THAT(r.output, HasSubstr("other sensor 334"));
  std::filesystem::remove(out);
}

TEST(ImportAsterix, DamagedCaptureIsReportedWithItsByteOffsetAndTheRestRead) {
  // GIVEN the excerpt with one block's LEN overwritten to run past its datagram
  std::ifstream in(excerpt("bds30_excerpt.pcap"), std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t payload = 24 + 16 + 42;  // first frame: headers, then the block
  bytes[payload + 2] = static_cast<char>(0x7F);
  const std::string damaged = temp("damaged.pcap");
  std::ofstream(damaged, std::ios::binary) << bytes;
  const std::string out = temp("damaged.plots.jsonl");
  const RunResult r = run("import-asterix " + damaged + " --plots " + out);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("datagram 1, byte " + std::to_string(payload) +
                                  ": CAT048: length past end"));
  EXPECT_THAT(r.output, HasSubstr("29 plots"));
  EXPECT_THAT(r.output, HasSubstr("errors: 1; length past end 1"));
  std::filesystem::remove(damaged);
  std::filesystem::remove(out);
}

TEST(ImportAsterix, BadOptionsAndFilesExitWithTwo) {
  EXPECT_EQ(
      run("import-asterix " + excerpt("canalA_excerpt.pcap") + " --plots /tmp/x --batch scans")
          .exit_code,
      2);
  EXPECT_EQ(run("import-asterix " + excerpt("canalA_excerpt.pcap") + " --plots /tmp/x --sensor 20")
                .exit_code,
            2);
  EXPECT_EQ(run("import-asterix /nonexistent.pcap --plots /tmp/x").exit_code, 2);
}

TEST(ReplayAsterix, NeedsPlotsOrAsterixButNotBoth) {
  EXPECT_EQ(run("replay --wait 0").exit_code, 2);
  EXPECT_NE(run("replay --plots a --asterix b").exit_code, 0);
}

}  // namespace
