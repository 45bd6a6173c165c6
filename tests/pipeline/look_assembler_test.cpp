// LookAssembler: a rotating antenna's plots regrouped into looks that end at cuts no search
// region straddles, whatever batches they arrive in.
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <span>
#include <vector>

#include <gtest/gtest.h>

#include "skytrack/geometry/angles.hpp"
#include "skytrack/pipeline/look_assembler.hpp"

namespace skytrack {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kPeriod = 4.0;  // [s]
constexpr double kTiny = 1e-6;   // [rad] the assembler's own edge

/// A clockwise antenna of known period: sweep s is body azimuth wrap(s).
AntennaSweep clockwise_antenna() {
  config::AntennaSpec spec;
  spec.rotation = config::AntennaRotation::kRotating;
  spec.period = kPeriod;
  spec.direction = config::RotationDirection::kClockwise;
  return AntennaSweep(spec);
}

/// A batch of polar plots at sweeps `sweeps` (a clockwise antenna from time 0: azimuth and own
/// time follow the sweep), stamped at its latest plot's time.
PlotScan batch(std::uint64_t number, const std::vector<double>& sweeps) {
  PlotScan scan;
  scan.sensor = 1;
  scan.scan = number;
  scan.time = 0.0;
  for (std::size_t i = 0; i < sweeps.size(); ++i) {
    Plot p;
    p.id = static_cast<std::int64_t>(i);
    p.range = 30000.0;
    p.azimuth = wrap_angle(sweeps[i]);
    p.time = sweeps[i] / kTwoPi * kPeriod;
    scan.time = std::max(scan.time, *p.time);
    scan.plots.push_back(p);
  }
  return scan;
}

std::vector<std::int64_t> ids(const Look& look) {
  std::vector<std::int64_t> out;
  for (const Plot& p : look.scan.plots) out.push_back(p.id);
  return out;
}

TEST(LookAssembler, HoldsAPlotBackUntilTheBeamHasPassedTheSpanAroundIt) {
  const AntennaSweep antenna = clockwise_antenna();
  LookAssembler looks;
  Look look;
  // GIVEN a batch of plots at sweeps 2 pi + {0.1, 0.5, 1.0}, the beam known to have reached
  // 2 pi + 1.2, and a search region spanning azimuths 1.0 +- 0.3 (around the third plot)
  const double r0 = kTwoPi;
  const std::vector<AzimuthSpan> spans{{1.0, 0.3}};
  looks.add(batch(0, {r0 + 0.1, r0 + 0.5, r0 + 1.0}), std::vector{r0 + 0.1, r0 + 0.5, r0 + 1.0},
            r0 + 1.2);
  // WHEN looks are taken
  ASSERT_TRUE(looks.take(spans, antenna, look));
  // THEN the first look ends at the span's near edge: the two plots before it, covering the
  // sector swept from the first plot to that edge
  EXPECT_EQ(ids(look), (std::vector<std::int64_t>{0, 1}));
  EXPECT_NEAR(look.sweep_to, r0 + 0.7, 1e-12);
  ASSERT_TRUE(look.scan.coverage);
  EXPECT_NEAR(look.scan.coverage->from, 0.1, 1e-5);
  EXPECT_NEAR(look.scan.coverage->to, 0.7, 1e-12);
  EXPECT_FALSE(look.whole);
  EXPECT_EQ(looks.held(), 1u);
  EXPECT_FALSE(looks.take(spans, antenna, look));  // no further cut yet
  // ... and while the beam is still inside the span (a batch with no plots reaches 1.25) the
  // third plot stays held
  looks.add(batch(1, {}), {}, r0 + 1.25);
  EXPECT_FALSE(looks.take(spans, antenna, look));
  EXPECT_EQ(looks.held(), 1u);
  // WHEN a batch shows the beam past the span's far edge (1.3)
  looks.add(batch(2, {r0 + 2.0}), std::vector{r0 + 2.0}, r0 + 2.1);
  ASSERT_TRUE(looks.take(spans, antenna, look));
  // THEN the held plot goes with the new one, keeping its own batch's header, and the look
  // covers what was swept since the previous cut
  ASSERT_EQ(look.scan.plots.size(), 2u);
  EXPECT_EQ(look.scan.scan, 2u);  // the latest batch's header
  ASSERT_EQ(look.batch_of.size(), 2u);
  const auto held = std::find(look.sweep.begin(), look.sweep.end(), r0 + 1.0);
  ASSERT_NE(held, look.sweep.end());
  const int from_batch = look.batch_of[static_cast<std::size_t>(held - look.sweep.begin())];
  ASSERT_GE(from_batch, 0);
  EXPECT_EQ(look.batches[static_cast<std::size_t>(from_batch)].scan, 0u);
  EXPECT_TRUE(look.batches[static_cast<std::size_t>(from_batch)].plots.empty());
  EXPECT_NEAR(look.sweep_to, r0 + 2.1, 1e-12);
  ASSERT_TRUE(look.scan.coverage);
  EXPECT_NEAR(look.scan.coverage->from, 0.7, 1e-5);
  EXPECT_NEAR(look.scan.coverage->to, 2.1, 1e-12);
  EXPECT_EQ(looks.held(), 0u);
  EXPECT_NEAR(looks.from(), r0 + 2.1, 1e-12);
}

TEST(LookAssembler, WithoutSpansALookEndsWhereTheBeamHasReached) {
  // GIVEN plots before and after the beam's known position (none straddled)
  const AntennaSweep antenna = clockwise_antenna();
  LookAssembler looks;
  Look look;
  const double r0 = 2.0 * kTwoPi;
  looks.add(batch(0, {r0 + 0.2, r0 + 0.4, r0 + 0.9}), std::vector{r0 + 0.2, r0 + 0.4, r0 + 0.9},
            r0 + 0.5);
  // WHEN a look is taken with no search regions
  ASSERT_TRUE(looks.take({}, antenna, look));
  // THEN it holds the plots up to `reached`, and the later one waits
  EXPECT_EQ(ids(look), (std::vector<std::int64_t>{0, 1}));
  EXPECT_NEAR(look.sweep_to, r0 + 0.5, 1e-12);
  EXPECT_EQ(looks.held(), 1u);
}

TEST(LookAssembler, SpansOfHalfARevolutionOrMoreAreIgnored) {
  const AntennaSweep antenna = clockwise_antenna();
  const double r0 = kTwoPi;
  const std::vector<double> sweeps{r0 + 0.1, r0 + 0.5, r0 + 1.0};
  // GIVEN the same batch given to two assemblers
  LookAssembler without, with_wide;
  Look a, b;
  without.add(batch(0, sweeps), sweeps, r0 + 1.2);
  with_wide.add(batch(0, sweeps), sweeps, r0 + 1.2);
  // WHEN one is given a span of exactly half a revolution (half = pi / 2) around the last
  // plot, and one round the radar (half = pi)
  const std::vector<AzimuthSpan> wide{{1.0, 0.5 * std::numbers::pi}, {-2.0, std::numbers::pi}};
  ASSERT_TRUE(without.take({}, antenna, a));
  ASSERT_TRUE(with_wide.take(wide, antenna, b));
  // THEN they give the same look: every plot up to `reached`
  EXPECT_EQ(ids(b), ids(a));
  EXPECT_EQ(ids(b), (std::vector<std::int64_t>{0, 1, 2}));
  EXPECT_EQ(b.sweep_to, a.sweep_to);
  // ... while a span just narrower than half a revolution does hold the plot back
  LookAssembler narrower;
  Look c;
  narrower.add(batch(0, sweeps), sweeps, r0 + 1.2);
  const std::vector<AzimuthSpan> under{{1.0, 0.5 * std::numbers::pi - 0.01}};
  if (narrower.take(under, antenna, c)) {
    EXPECT_EQ(std::count(c.sweep.begin(), c.sweep.end(), r0 + 1.0), 0);
  }
  EXPECT_GE(narrower.held(), 1u);
}

/// Spans that together cover every azimuth (each narrower than half a revolution).
std::vector<AzimuthSpan> blocking_spans() {
  std::vector<AzimuthSpan> spans;
  for (int k = 0; k < 8; ++k) spans.push_back({wrap_angle(k * kTwoPi / 8.0), 0.5});
  return spans;
}

TEST(LookAssembler, AWholeRevolutionSweptWithTheSweepBlockedForcesAOneRevolutionLook) {
  // GIVEN search regions whose spans leave no azimuth free for a cut
  const AntennaSweep antenna = clockwise_antenna();
  const std::vector<AzimuthSpan> spans = blocking_spans();
  LookAssembler looks;
  Look look;
  const double r0 = kTwoPi;
  std::vector<double> first;  // a plot every 0.25 rad over 0.9 of a revolution
  for (double s = r0 + 0.1; s < r0 + 0.9 * kTwoPi; s += 0.25) first.push_back(s);
  looks.add(batch(0, first), first, first.back());
  // WHEN less than a revolution has been swept
  // THEN no look can be taken
  EXPECT_FALSE(looks.take(spans, antenna, look));
  EXPECT_EQ(looks.held(), first.size());
  // WHEN the sweep passes a revolution after the previous cut (just before the first plot)
  std::vector<double> second;
  for (double s = first.back() + 0.25; s < r0 + 1.5 * kTwoPi; s += 0.25) second.push_back(s);
  looks.add(batch(1, second), second, second.back());
  ASSERT_TRUE(looks.take(spans, antenna, look));
  // THEN one look of exactly one revolution is forced: every plot of that revolution, no later
  // one, and all directions covered
  const double cut = r0 + 0.1 + kTwoPi;
  EXPECT_NEAR(look.sweep_to, cut, 1e-6);
  EXPECT_FALSE(look.scan.coverage);
  std::size_t expected = 0;
  for (const double s : first) expected += s <= cut ? 1 : 0;
  for (const double s : second) expected += s <= cut ? 1 : 0;
  EXPECT_EQ(look.scan.plots.size(), expected);
  for (const double s : look.sweep) EXPECT_LE(s, cut);
  EXPECT_EQ(looks.held(), first.size() + second.size() - expected);
  // ... and no second look until another revolution is swept
  EXPECT_FALSE(looks.take(spans, antenna, look));
}

TEST(LookAssembler, TakeAllGivesOneLookAtEverythingMarkedWhole) {
  // GIVEN plots held from two batches (some beyond a span's cut)
  const AntennaSweep antenna = clockwise_antenna();
  LookAssembler looks;
  Look look;
  const double r0 = kTwoPi;
  looks.add(batch(0, {r0 + 0.1, r0 + 1.0}), std::vector{r0 + 0.1, r0 + 1.0}, r0 + 1.1);
  const std::vector<AzimuthSpan> spans{{1.0, 0.3}};
  ASSERT_TRUE(looks.take(spans, antenna, look));
  ASSERT_EQ(looks.held(), 1u);
  looks.add(batch(1, {r0 + 4.0, r0 + 5.5}), std::vector{r0 + 4.0, r0 + 5.5}, r0 + 5.6);
  // WHEN all are taken
  looks.take_all(look);
  // THEN one look holds every held plot, with no coverage (all directions) and `whole` set
  EXPECT_EQ(look.scan.plots.size(), 3u);
  EXPECT_FALSE(look.scan.coverage);
  EXPECT_TRUE(look.whole);
  EXPECT_TRUE(look.sources().whole);
  EXPECT_EQ(look.scan.scan, 1u);
  EXPECT_EQ(looks.held(), 0u);
  // ... and the next look starts where it ended
  EXPECT_NEAR(looks.from(), r0 + 5.6, 1e-12);
  EXPECT_FALSE(looks.take(spans, antenna, look));
}

TEST(LookAssembler, LooksNeverHoldTwoPlotsOfOneAzimuthFromDifferentRevolutions) {
  // GIVEN six targets at fixed azimuths seen every revolution for 12 revolutions, delivered
  // in blocks of 1-5 plots (fixed seed), each with a search region around its azimuth
  std::mt19937_64 rng(7);
  const AntennaSweep antenna = clockwise_antenna();
  const std::vector<double> azimuths{0.3, 1.1, 1.25, 2.8, -2.9, -1.0};
  std::vector<AzimuthSpan> spans;
  for (const double a : azimuths) spans.push_back({a, 0.2});
  struct Seen {
    double sweep;
    std::size_t target;
  };
  std::vector<Seen> stream;
  for (int r = 1; r <= 12; ++r) {
    for (std::size_t t = 0; t < azimuths.size(); ++t) {
      stream.push_back({r * kTwoPi + wrap_angle_positive(azimuths[t]), t});
    }
  }
  std::sort(stream.begin(), stream.end(),
            [](const Seen& a, const Seen& b) { return a.sweep < b.sweep; });
  LookAssembler looks;
  Look look;
  std::uniform_int_distribution<std::size_t> block(1, 5);
  std::map<double, int> released;  // sweep -> times released
  double previous_to = -INFINITY;
  std::uint64_t number = 0;
  int taken = 0;
  for (std::size_t i = 0; i < stream.size();) {
    const std::size_t n = std::min(block(rng), stream.size() - i);
    std::vector<double> sweeps;
    for (std::size_t k = i; k < i + n; ++k) sweeps.push_back(stream[k].sweep);
    PlotScan b = batch(number++, sweeps);
    for (std::size_t k = 0; k < n; ++k)
      b.plots[k].id = static_cast<std::int64_t>(stream[i + k].target);
    i += n;
    // WHEN each batch is added and every look it completes is taken
    looks.add(b, sweeps, sweeps.back());
    while (looks.take(spans, antenna, look)) {
      ++taken;
      // THEN a look holds each target (azimuth) at most once ...
      std::set<std::int64_t> targets;
      for (const Plot& p : look.scan.plots) {
        EXPECT_TRUE(targets.insert(p.id).second) << "target " << p.id << " twice in one look";
      }
      // ... spans less than a revolution, and follows the previous look
      if (!look.sweep.empty()) {
        const auto [low, high] = std::minmax_element(look.sweep.begin(), look.sweep.end());
        EXPECT_LT(*high - *low, kTwoPi);
        EXPECT_GT(*low, previous_to);
        EXPECT_LE(*high, look.sweep_to);
      }
      previous_to = look.sweep_to;
      for (const double s : look.sweep) ++released[s];
    }
  }
  // ... and every plot but the last few is released exactly once, in at least a look a
  // revolution
  EXPECT_GE(taken, 12);
  for (const auto& [sweep, times] : released) EXPECT_EQ(times, 1) << "sweep " << sweep;
  EXPECT_EQ(released.size() + looks.held(), stream.size());
  EXPECT_LE(looks.held(), azimuths.size());
}

}  // namespace
}  // namespace skytrack
