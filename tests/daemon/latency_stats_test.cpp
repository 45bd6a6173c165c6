#include "skytrack/daemon/latency_stats.hpp"

#include <gtest/gtest.h>

namespace skytrack::daemon {
namespace {

TEST(LatencyStats, EmptyGivesZeros) {
  const LatencyStats stats(8);
  EXPECT_EQ(stats.percentile(0.5), 0.0);
  EXPECT_EQ(stats.max(), 0.0);
  EXPECT_EQ(stats.count(), 0u);
}

TEST(LatencyStats, NearestRankPercentilesOfOneToHundred) {
  // GIVEN the values 1..100 in a scrambled order
  LatencyStats stats(100);
  for (int i = 0; i < 100; ++i) stats.add(static_cast<double>((i * 37) % 100 + 1));
  // THEN nearest rank: p50 is the 50th value, p99 the 99th, p100 the largest
  EXPECT_EQ(stats.percentile(0.50), 50.0);
  EXPECT_EQ(stats.percentile(0.99), 99.0);
  EXPECT_EQ(stats.percentile(1.0), 100.0);
  EXPECT_EQ(stats.percentile(0.0), 1.0);
  EXPECT_EQ(stats.max(), 100.0);
}

TEST(LatencyStats, WindowForgetsOldSamplesButMaxDoesNot) {
  // GIVEN a window of 4 that saw one slow scan and then four fast ones
  LatencyStats stats(4);
  stats.add(9.0);
  for (int i = 0; i < 4; ++i) stats.add(1.0);
  // THEN the percentiles cover the window only, the maximum the whole run
  EXPECT_EQ(stats.percentile(0.99), 1.0);
  EXPECT_EQ(stats.max(), 9.0);
  EXPECT_EQ(stats.count(), 5u);
  EXPECT_EQ(stats.window_size(), 4u);
}

}  // namespace
}  // namespace skytrack::daemon
