// The fuzz target (fuzz/asterix_fuzz_target.cpp) over the committed seed corpus, without
// mutation: a regression in the decoder's handling of these inputs fails here, in every build,
// not only under libFuzzer. The target aborts on a broken invariant.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

int skytrack_asterix_fuzz_one(const std::uint8_t* data, std::size_t size);

namespace {

TEST(FuzzCorpus, EveryCommittedInputPassesTheFuzzTarget) {
  const std::filesystem::path corpus = std::filesystem::path(SKYTRACK_SOURCE_DIR) / "fuzz/corpus";
  std::size_t inputs = 0;
  for (const auto& entry : std::filesystem::directory_iterator(corpus)) {
    if (!entry.is_regular_file() || entry.path().extension() == ".md") continue;
    std::ifstream in(entry.path(), std::ios::binary);
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                          std::istreambuf_iterator<char>());
    EXPECT_EQ(skytrack_asterix_fuzz_one(bytes.data(), bytes.size()), 0) << entry.path();
    // Every prefix too: truncation is the commonest damage.
    for (std::size_t n = 0; n < bytes.size() && n < 512; ++n) {
      skytrack_asterix_fuzz_one(bytes.data(), n);
    }
    ++inputs;
  }
  EXPECT_GE(inputs, 10u);
}

}  // namespace
