#include <sys/resource.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "skytrack/io/jsonl_reader.hpp"

namespace skytrack::io {
namespace {

using ::testing::HasSubstr;

std::string write_temp(const std::string& name, const std::string& content) {
  const auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << content;
  return path.string();
}

TEST(JsonLinesReader, ReportsBadLinesWithNumbersAndKeepsReading) {
  // GIVEN a stream whose 2nd and 4th lines are broken, a blank line and a bad plot
  const std::string path =
      write_temp("skytrack_reader_test.plots.jsonl",
                 "{\"sensor\":0,\"scan\":0,\"time\":0,\"plots\":[]}\n"
                 "{\"sensor\":0,\"scan\":1,\n"
                 "\n"
                 "not json at all\r\n"
                 "{\"sensor\":0,\"scan\":2,\"time\":2,\"plots\":["
                 "{\"id\":0,\"x\":1,\"y\":2},{\"id\":1,\"range\":-1,\"azimuth\":0}]}\n");
  std::vector<LineError> errors;
  auto reader = PlotStreamReader::open(path, [&](const LineError& e) { errors.push_back(e); });
  ASSERT_TRUE(reader);

  // WHEN it is read to the end
  std::vector<PlotScan> scans;
  while (auto scan = reader->next()) scans.push_back(std::move(*scan));

  // THEN the good lines are kept and every problem names its file and line
  ASSERT_EQ(scans.size(), 2u);
  EXPECT_EQ(scans[1].scan, 2u);
  EXPECT_EQ(scans[1].plots.size(), 1u);
  ASSERT_EQ(errors.size(), 3u);
  EXPECT_EQ(errors[0].line, 2u);
  EXPECT_EQ(errors[1].line, 4u);
  EXPECT_EQ(errors[2].line, 5u);
  EXPECT_THAT(to_string(errors[2]), HasSubstr("skytrack_reader_test.plots.jsonl:5: plot rejected"));
  EXPECT_EQ(reader->counts().records, 2u);
  EXPECT_EQ(reader->counts().rejected_lines, 2u);
  EXPECT_EQ(reader->counts().rejected_plots, 1u);
  EXPECT_EQ(reader->bytes_read(), reader->file_size());
  std::filesystem::remove(path);
}

TEST(JsonLinesReader, FailsToOpenAMissingFileWithItsName) {
  const auto reader = TruthReader::open("/nonexistent/truth.jsonl");
  ASSERT_FALSE(reader);
  EXPECT_THAT(reader.error().message, HasSubstr("/nonexistent/truth.jsonl"));
}

TEST(JsonLinesReader, RefusesADirectoryInsteadOfReadingNothing) {
  // GIVEN a directory named as the plot stream; THEN opening it fails, naming it (it used to
  // read as an empty file: "0 batches", exit 0)
  const auto reader = PlotStreamReader::open(std::filesystem::temp_directory_path().string());
  ASSERT_FALSE(reader);
  EXPECT_THAT(reader.error().message, HasSubstr("is a directory"));
}

TEST(JsonLinesReader, SkipsALineLongerThanTheLimitUnreadAndReadsOn) {
  // GIVEN a good line, a line of 300 kB (the limit set to 100 kB), a line that is not JSON
  // and another good line
  const std::string good = "{\"sensor\":0,\"scan\":0,\"time\":0,\"plots\":[]}\n";
  const std::string later = "{\"sensor\":0,\"scan\":1,\"time\":1,\"plots\":[]}\n";
  const std::string path = write_temp("skytrack_reader_long.plots.jsonl",
                                      good + std::string(300000, 'x') + "\n" + "{]\n" + later);
  std::vector<LineError> errors;
  auto reader = PlotStreamReader::open(
      path, [&](const LineError& e) { errors.push_back(e); }, 100000);
  ASSERT_TRUE(reader);
  // WHEN it is read to the end
  std::vector<PlotScan> scans;
  while (auto scan = reader->next()) scans.push_back(std::move(*scan));
  // THEN the long line is rejected with its number, unread, and the parser, after the bad
  // line, reads the next good one
  ASSERT_EQ(scans.size(), 2u);
  EXPECT_EQ(scans[1].scan, 1u);
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_EQ(errors[0].line, 2u);
  EXPECT_THAT(errors[0].reason, HasSubstr("longer than 100000 bytes"));
  EXPECT_EQ(errors[1].line, 3u);
  EXPECT_FALSE(reader->read_error());
  EXPECT_EQ(reader->bytes_read(), reader->file_size());
  std::filesystem::remove(path);
}

#if defined(__SANITIZE_ADDRESS__)
#define SKYTRACK_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SKYTRACK_TEST_ASAN 1
#endif
#endif

/// The process's virtual size [bytes] (/proc/self/statm, first field, in pages).
std::size_t virtual_size() {
  std::size_t pages = 0;
  std::ifstream("/proc/self/statm") >> pages;
  return pages * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
}

/// Exits 0 when an ordinary line parses after one whose parse ran out of memory.
[[noreturn]] void parse_beyond_memory_then_a_line() {
  std::string huge = R"({"sensor":1,"scan":1,"time":0,"plots":[)";
  while (huge.size() < (48u << 20)) huge += R"({"id":1,"x":1,"y":2},)";
  huge += R"({"id":2,"x":1,"y":2}]})";
  const rlimit limit{virtual_size() + (32u << 20), RLIM_INFINITY};
  if (setrlimit(RLIMIT_AS, &limit) != 0) _exit(2);
  const auto first = parse_plot_scan(huge);
  if (first || first.error().message.find("memory") == std::string::npos) _exit(3);
  const auto next = parse_plot_scan(R"({"sensor":1,"scan":2,"time":1,"plots":[]})");
  _exit(next ? 0 : 4);
}

TEST(JsonLineParser, ALineThatRunsOutOfMemoryLeavesTheNextOneReadable) {
#ifdef SKYTRACK_TEST_ASAN
  GTEST_SKIP() << "an address-space limit and ASan's shadow memory do not mix";
#endif
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  // In a child process: a 48 MiB line parsed under an address-space limit 32 MiB above what
  // the process holds, so the parser's allocation fails; then an ordinary line. Before the
  // parser was renewed after a failure, the second parse read the failed one's state
  // (SIGSEGV in simdjson's stage 2).
  EXPECT_EXIT(parse_beyond_memory_then_a_line(), ::testing::ExitedWithCode(0), "");
}

}  // namespace
}  // namespace skytrack::io
