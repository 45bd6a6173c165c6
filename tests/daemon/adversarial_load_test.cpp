// tools/experiments/adversarial-load.sh in a reduced mode (tiny phases, a few seconds): the
// real skytrackd on a private loopback domain, fed by skytrack-adversary. Checks that the run
// completes, the daemon survives and stops cleanly, and the report names what it measured.
#include <cstdlib>
#include <filesystem>
#include <regex>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "process_helpers.hpp"
#include "support/test_domain.hpp"

namespace skytrack::test {
namespace {

using namespace std::chrono_literals;
using ::testing::HasSubstr;

TEST(AdversarialLoad, ReducedRunCompletesAndReportsEveryPhase) {
  // GIVEN the wrapper script, the built daemon and adversary, and a private domain
  const std::string dir =
      (std::filesystem::temp_directory_path() / ("skytrack_adversary_" + std::to_string(getpid())))
          .string();
  std::filesystem::create_directories(dir);
  setenv("SKYTRACK_BUILD_DIR", SKYTRACK_BUILD_DIR, 1);
  const TestDomain lease;
  setenv("ADVERSARY_DOMAIN", std::to_string(lease.id()).c_str(), 1);
  setenv("ADVERSARY_MAX_PLOTS", "2000", 1);
  const std::string log = dir + "/run.log";

  // WHEN it runs with tiny phases: two clouds, one burst, huge batches of 1999 and 2001
  // plots, malformed samples and the clock hijack, at 10x real time
  Child run({"/bin/bash",
             std::string(SKYTRACK_SOURCE_DIR) + "/tools/experiments/adversarial-load.sh",
             "--sectors",
             "4",
             "--rate",
             "10",
             "--warmup",
             "8",
             "--phase",
             "4",
             "--settle",
             "2",
             "--recovery",
             "4",
             "--period",
             "2",
             "--cloud-sizes",
             "30,300",
             "--bursts",
             "1",
             "--burst-batches",
             "20",
             "--burst-plots",
             "3",
             "--drain",
             "5"},
            log);
  const auto code = run.wait(30s);

  // THEN it completes and the daemon stops cleanly
  const std::string out = run.log();
  ASSERT_EQ(code, 0) << out;
  EXPECT_THAT(out, HasSubstr("skytrackd exited 0 after SIGTERM"));
  // ... every phase has its block, and the summary its lines
  for (const char* phase : {"warm-up", "cloud 30", "cloud 300", "burst 1x20", "huge 1999",
                            "huge 2001", "malformed", "clock hijack", "recovery"}) {
    EXPECT_THAT(out, HasSubstr(std::string(": ") + phase + " (stream")) << phase;
  }
  EXPECT_THAT(out, HasSubstr("sensor 1 latency: "));
  EXPECT_THAT(out, HasSubstr("skytrackd memory: VmRSS max "));
  EXPECT_THAT(out, HasSubstr("== summary"));
  EXPECT_THAT(out, HasSubstr("sensor 1 frames unchanged: "));
  EXPECT_THAT(out, HasSubstr("run: "));
  EXPECT_THAT(out, HasSubstr("completed"));
  // ... and the daemon's status counted what the adversary sent
  EXPECT_THAT(out, HasSubstr("too many plots: 1"));
  EXPECT_THAT(out, HasSubstr("malformed sample: "));
  EXPECT_THAT(out, HasSubstr("time jumps forward: "));
  EXPECT_THAT(out, HasSubstr("clock disagrees with the other sensors: 1"));
  // ... and the good sensor's tracks were those of its run alone, in every frame, the clock
  // hijack included (before the sensor timeline, the hijack restarted them)
  std::smatch unchanged;
  ASSERT_TRUE(std::regex_search(out, unchanged,
                                std::regex(R"(sensor 1 frames unchanged: (\d+) / (\d+) \()")))
      << out;
  EXPECT_EQ(unchanged[1], unchanged[2]) << out;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace skytrack::test
