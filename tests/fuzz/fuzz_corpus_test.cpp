// The fuzz targets of fuzz/ (fuzz_targets.hpp) over their committed seed corpora,
// fuzz/seeds/<target>/, without mutation: a regression on these inputs, or on a reproducer
// a fuzzing run added, fails here in every build, not only under libFuzzer. A target aborts
// on a broken invariant, which fails the test program.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>
#include <string>
#include <vector>

#include "fuzz_targets.hpp"

namespace {

using FuzzTarget = int (*)(const std::uint8_t*, std::size_t);

struct Harness {
  const char* name;  // its seed folder under fuzz/seeds/
  FuzzTarget target;
};
void PrintTo(const Harness& h, std::ostream* os) {
  *os << h.name;
}

const Harness kHarnesses[] = {
    {"plot_line", skytrack_plot_line_fuzz_one},   {"track_line", skytrack_track_line_fuzz_one},
    {"truth_line", skytrack_truth_line_fuzz_one}, {"profile", skytrack_profile_fuzz_one},
    {"scenario", skytrack_scenario_fuzz_one},     {"plot_batch", skytrack_plot_batch_fuzz_one},
};

std::vector<std::uint8_t> read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class FuzzSeeds : public testing::TestWithParam<Harness> {};

TEST_P(FuzzSeeds, EveryCommittedInputAndSomeOfItsPrefixesPassTheFuzzTarget) {
  // GIVEN the target's committed seeds
  const Harness& h = GetParam();
  const auto folder = std::filesystem::path(SKYTRACK_SOURCE_DIR) / "fuzz/seeds" / h.name;
  ASSERT_TRUE(std::filesystem::is_directory(folder)) << folder;
  std::size_t inputs = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (!entry.is_regular_file() || entry.path().extension() == ".md") continue;
    const std::vector<std::uint8_t> bytes = read_bytes(entry.path());
    // WHEN the target takes each whole, THEN it returns 0 (it aborts on a broken invariant)
    EXPECT_EQ(h.target(bytes.data(), bytes.size()), 0) << entry.path();
    // ... and 64 of its prefixes, evenly spaced: truncation is the commonest damage.
    const std::size_t step = std::max<std::size_t>(1, bytes.size() / 64);
    for (std::size_t n = 0; n < bytes.size(); n += step) {
      EXPECT_EQ(h.target(bytes.data(), n), 0) << entry.path() << " cut at " << n;
    }
    ++inputs;
  }
  EXPECT_GE(inputs, 3u) << folder;
}

// A reproducer of an open finding (fuzz/findings/<target>/, docs/hardening.md) still breaks
// its target's invariant. When this fails, the finding is fixed: move the file into
// fuzz/seeds/<target>/, where the test above keeps it fixed.
TEST_P(FuzzSeeds, EveryOpenFindingStillReproduces) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const Harness& h = GetParam();
  const auto folder = std::filesystem::path(SKYTRACK_SOURCE_DIR) / "fuzz/findings" / h.name;
  if (!std::filesystem::is_directory(folder)) return;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (!entry.is_regular_file() || entry.path().extension() == ".md") continue;
    const std::vector<std::uint8_t> bytes = read_bytes(entry.path());
    EXPECT_DEATH(h.target(bytes.data(), bytes.size()), "fuzz invariant broken")
        << entry.path() << " no longer breaks the target: move it into fuzz/seeds/" << h.name;
  }
}

INSTANTIATE_TEST_SUITE_P(Harnesses, FuzzSeeds, testing::ValuesIn(kHarnesses),
                         [](const testing::TestParamInfo<Harness>& info) {
                           std::string name = info.param.name;
                           std::erase(name, '_');
                           return name;
                         });

}  // namespace
