// Batches from sector messages (coverage and time), late plots, the fall-back to revolutions,
// revolutions fitted from azimuths and times, and blocks of N plots.
#include <gtest/gtest.h>

#include <cmath>

#include "skytrack/asterix/batcher.hpp"

namespace skytrack::asterix {
namespace {

constexpr double kTwoPi = 6.283185307179586;

TargetReport plot(double time, double azimuth, std::uint32_t sensor = 7) {
  TargetReport r;
  r.sensor = sensor;
  r.time = time;
  r.azimuth = azimuth;
  r.range = 1000.0;
  return r;
}

ServiceMessage sector(double time, double azimuth, std::uint32_t sensor = 7) {
  ServiceMessage m;
  m.sensor = sensor;
  m.kind = azimuth == 0.0 ? ServiceKind::kNorthMarker : ServiceKind::kSectorCrossing;
  m.time = time;
  m.azimuth = azimuth;
  return m;
}

struct Scans {
  std::vector<PlotScan> all;
  Batcher::ScanSink sink() {
    return [this](PlotScan&& s) { all.push_back(std::move(s)); };
  }
};

/// A radar turning once per `period` seconds from north at t = 0, one plot every `step` s.
void turn(Batcher& b, double from, double to, double period, double step) {
  for (double t = from; t < to - 1e-9; t += step) {
    b.add(plot(t, std::fmod(t / period, 1.0) * kTwoPi));
  }
}

TEST(Batcher, SectorMessagesCloseBatchesWithTheirCoverageAndTime) {
  Scans scans;
  Batcher b({}, scans.sink());
  // GIVEN four sectors per turn of 4 s, a message at each sector's end
  for (int k = 1; k <= 8; ++k) {
    turn(b, (k - 1) * 1.0 + 0.05, k * 1.0, 4.0, 0.1);
    b.add(sector(k * 1.0, std::fmod(k * kTwoPi / 4.0, kTwoPi)));
  }
  b.finish();
  // THEN the first batch (start unknown) has no coverage, the others their quarter
  ASSERT_EQ(scans.all.size(), 8u);
  EXPECT_FALSE(scans.all[0].coverage);
  for (std::size_t i = 1; i < scans.all.size(); ++i) {
    const PlotScan& s = scans.all[i];
    EXPECT_EQ(s.scan, i);
    EXPECT_EQ(s.sensor, 7u);
    EXPECT_DOUBLE_EQ(s.time, static_cast<double>(i + 1));
    ASSERT_TRUE(s.coverage);
    EXPECT_NEAR(s.coverage->from, std::fmod(i * kTwoPi / 4.0, kTwoPi), 1e-12);
    EXPECT_EQ(s.plots.size(), 10u);
    for (const Plot& p : s.plots) EXPECT_TRUE(s.coverage->contains(p.azimuth));
    EXPECT_EQ(s.plots.back().id, 9);
  }
}

TEST(Batcher, NorthMarkersOnlyGiveWholeTurnsWithoutCoverage) {
  Scans scans;
  Batcher b({}, scans.sink());
  turn(b, 0.05, 4.0, 4.0, 0.5);
  b.add(sector(4.0, 0.0));
  turn(b, 4.05, 8.0, 4.0, 0.5);
  b.add(sector(8.0, 0.0));
  b.finish();
  ASSERT_EQ(scans.all.size(), 2u);
  EXPECT_FALSE(scans.all[1].coverage);
  EXPECT_DOUBLE_EQ(scans.all[1].time, 8.0);
}

TEST(Batcher, LatePlotsJoinTheBatchTheirMessageClosed) {
  Scans scans;
  Batcher b({}, scans.sink());
  b.add(sector(0.0, 0.0));
  b.add(plot(1.0, 1.0));
  b.add(sector(4.0, 0.0));
  b.add(plot(3.98, kTwoPi - 0.03));  // measured before the marker, sent after it
  b.add(plot(4.02, 0.03));           // the next turn
  b.add(plot(3.99, kTwoPi - 0.02));  // still late: no plot 0.1 s past the marker yet
  b.add(plot(4.5, 0.8));
  b.finish();
  ASSERT_EQ(scans.all.size(), 2u);
  EXPECT_EQ(scans.all[0].plots.size(), 3u);
  EXPECT_EQ(scans.all[1].plots.size(), 2u);
}

TEST(Batcher, WithoutSectorMessagesItFallsBackToRevolutions) {
  Scans scans;
  Batcher b({}, scans.sink());
  turn(b, 0.1, 40.0, 4.0, 0.2);  // ten turns, no message at all
  b.finish();
  ASSERT_GE(scans.all.size(), 9u);
  for (std::size_t i = 1; i + 1 < scans.all.size(); ++i) {
    EXPECT_EQ(scans.all[i].plots.size(), 20u) << i;
    EXPECT_NEAR(scans.all[i].time, 4.0 * static_cast<double>(i + 1), 0.05) << i;
  }
}

TEST(Batcher, RevolutionsAreFittedThroughJitterAndGaps) {
  Scans scans;
  BatchOptions options;
  options.mode = BatchMode::kRevolution;
  Batcher b(options, scans.sink());
  // GIVEN plots with azimuth jitter (one slightly behind the antenna across north) and a
  // sector without plots wider than half a turn
  for (int k = 0; k < 6; ++k) {
    for (int i = 1; i <= 7; ++i) b.add(plot(4.0 * k + 0.2 * i, 0.05 * i * kTwoPi));
    b.add(plot(4.0 * k + 3.9, 0.975 * kTwoPi));
    b.add(plot(4.0 * k + 4.02, 0.005 * kTwoPi));
    b.add(plot(4.0 * k + 4.03, 0.999 * kTwoPi));  // behind north, sent after
  }
  b.finish();
  ASSERT_EQ(scans.all.size(), 7u);
  for (std::size_t i = 1; i + 1 < scans.all.size(); ++i) {
    EXPECT_EQ(scans.all[i].plots.size(), 10u) << i;
    EXPECT_NEAR(scans.all[i].time, 4.0 * static_cast<double>(i + 1), 0.05) << i;
  }
  ASSERT_TRUE(b.rotation_period(7));
  EXPECT_NEAR(*b.rotation_period(7), 4.0, 0.05);
}

TEST(Batcher, BlocksOfNPlotsPerSensor) {
  Scans scans;
  auto options = parse_batch_mode("block:3");
  ASSERT_TRUE(options);
  Batcher b(*options, scans.sink());
  for (int i = 0; i < 7; ++i) b.add(plot(i, 0.1 * i, i % 2 == 0 ? 7u : 8u));
  b.finish();
  ASSERT_EQ(scans.all.size(), 3u);  // sensor 7: 3 + 1; sensor 8: 3
  EXPECT_EQ(scans.all[0].sensor, 7u);
  EXPECT_EQ(scans.all[0].plots.size(), 3u);
  EXPECT_DOUBLE_EQ(scans.all[0].time, 4.0);
  EXPECT_FALSE(scans.all[0].coverage);
  EXPECT_EQ(scans.all[1].sensor, 8u);
  EXPECT_EQ(scans.all[2].scan, 1u);
}

TEST(Batcher, BatchTimesNeverGoBackwards) {
  Scans scans;
  Batcher b({}, scans.sink());
  b.add(plot(1.0, 1.0));
  b.add(sector(5.0, 0.0));
  b.add(plot(6.0, 1.0));
  b.add(sector(4.0, 0.0));  // a message timed before the previous one
  b.finish();
  ASSERT_EQ(scans.all.size(), 2u);
  EXPECT_GE(scans.all[1].time, scans.all[0].time);
}

TEST(Batcher, ParsesTheBatchOption) {
  EXPECT_EQ(parse_batch_mode("sector")->mode, BatchMode::kSector);
  EXPECT_EQ(parse_batch_mode("revolution")->mode, BatchMode::kRevolution);
  EXPECT_EQ(parse_batch_mode("block:12")->block_plots, 12u);
  EXPECT_FALSE(parse_batch_mode("block:0"));
  EXPECT_FALSE(parse_batch_mode("block:"));
  EXPECT_FALSE(parse_batch_mode("scan"));
}

}  // namespace
}  // namespace skytrack::asterix

namespace skytrack::asterix {
namespace {

TEST(Batcher, UntimedSectorMessagesBeforeAnyPlotCloseNothing) {
  // Found by fuzzing: such a batch had no time to give (it was -inf).
  Scans scans;
  Batcher b({}, scans.sink());
  ServiceMessage untimed = sector(0.0, 0.0);
  untimed.time.reset();
  b.add(untimed);
  untimed.azimuth = 1.0;
  untimed.kind = ServiceKind::kSectorCrossing;
  b.add(untimed);
  b.add(plot(5.0, 1.5));
  b.add(sector(6.0, 2.0));
  b.finish();
  ASSERT_EQ(scans.all.size(), 1u);
  EXPECT_DOUBLE_EQ(scans.all[0].time, 6.0);
  EXPECT_EQ(scans.all[0].scan, 0u);
  ASSERT_TRUE(scans.all[0].coverage);  // still by sector, from the last message's azimuth
  EXPECT_DOUBLE_EQ(scans.all[0].coverage->from, 1.0);
}

}  // namespace
}  // namespace skytrack::asterix
