// TrackFusion's memory stays bounded: the heap in use does not grow between cycle 200 and
// cycle 1000 while local tracks are renumbered, appear and vanish.
#include <malloc.h>

#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "fusion_test_support.hpp"
#include "skytrack/fusion/track_fusion.hpp"

namespace skytrack::fusion {
namespace {

TEST(TrackFusionMemory, HeapDoesNotGrowOver1000Cycles) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  GTEST_SKIP() << "the sanitizers own malloc";
#endif
  TrackFusion fusion{FusionSpec{}};
  std::size_t at_200 = 0;
  std::size_t frames_out = 0;
  for (int c = 0; c < 1000; ++c) {
    // GIVEN 2 sensors x 50 targets; sensor 1 renumbers every 50 cycles, and a tenth of the
    // targets is missing in each 7th cycle
    for (std::uint32_t s = 1; s <= 2; ++s) {
      TrackFrame f;
      f.sensor = s;
      f.time = c;
      for (int t = 0; t < 50; ++t) {
        if (c % 7 == 0 && t % 10 == 0) continue;
        const std::int64_t id = s == 1 ? t + 1000 * (c / 50) : t;
        f.tracks.push_back(testing::report({id, 100.0 * c, 2000.0 * t}));
      }
      frames_out += fusion.add(f).size();
    }
    if (c == 199) at_200 = mallinfo2().uordblks;
  }
  const std::size_t at_1000 = mallinfo2().uordblks;
  EXPECT_GT(frames_out, 990u);
  // THEN no growth beyond allocator noise
  EXPECT_LT(static_cast<double>(at_1000), static_cast<double>(at_200) + 64 * 1024)
      << "heap at cycle 200: " << at_200 << " B, at 1000: " << at_1000 << " B";
}

}  // namespace
}  // namespace skytrack::fusion
