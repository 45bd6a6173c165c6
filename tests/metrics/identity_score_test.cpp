// score_identities: tracks scored against the transponder identities their plots carry, on
// hand-made cases whose breaks, purity and coverage are counted by hand.
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "skytrack/metrics/identity_score.hpp"

namespace skytrack::metrics {
namespace {

constexpr double kScan = 4.0;     // [s] between an identity's plots
constexpr double kSpeed = 200.0;  // [m/s] the hand-made aircraft's
constexpr double kExact = 1e-12;

/// `n` plots of `identity` every kScan seconds from `first`, flying east at kSpeed from x0,
/// each held by `track` (nullopt: not held).
std::vector<IdentityPlot> flight(const std::string& identity, double first, int n, double x0,
                                 double y, std::optional<std::int64_t> track) {
  std::vector<IdentityPlot> out;
  for (int k = 0; k < n; ++k) {
    const double t = first + k * kScan;
    const double x = x0 + kSpeed * (t - first);
    out.push_back({t, identity, x, y, std::hypot(x, y), track});
  }
  return out;
}

void append(std::vector<IdentityPlot>& to, const std::vector<IdentityPlot>& from) {
  to.insert(to.end(), from.begin(), from.end());
}

TEST(IdentityScore, ATrackThatSwitchesAircraftCostsABreakAndPurity) {
  // GIVEN two aircraft over the same 40 s, far apart:
  //   A:1234, 10 plots (t = 0..36), all held by track 1;
  //   A:4321, 20 plots (t = 0..76): track 2 holds t = 0..36 (10), t = 40 is not held, and
  //   track 1, its own aircraft gone, holds t = 44..76 (9)
  std::vector<IdentityPlot> plots = flight("A:1234", 0.0, 10, 10000.0, 0.0, 1);
  append(plots, flight("A:4321", 0.0, 10, -30000.0, 20000.0, 2));
  append(plots, flight("A:4321", 40.0, 1, -30000.0 + kSpeed * 40.0, 20000.0, std::nullopt));
  append(plots, flight("A:4321", 44.0, 9, -30000.0 + kSpeed * 44.0, 20000.0, 1));
  // WHEN scored (gap 20 s)
  const IdentityScore s = score_identities(plots, {});
  // THEN by hand: 2 segments; A:4321's is held by 2 tracks (3+ plots each): 1 break
  EXPECT_EQ(s.identity_plots, 30);
  EXPECT_EQ(s.held_plots, 29);
  EXPECT_EQ(s.segments, 2);
  EXPECT_EQ(s.breaks, 1);
  EXPECT_EQ(s.segments_with_breaks, 1);
  EXPECT_NEAR(s.breaks_per_segment, 0.5, kExact);
  EXPECT_EQ(s.code_changes, 0);  // A:4321 started before A:1234 ended: no code change
  // ... purity: track 1's dominant identity has 10 of its 19, track 2's all its 10
  EXPECT_NEAR(s.purity, (10.0 + 10.0) / 29.0, kExact);
  // ... coverage: 29 of 30 identity plots held
  EXPECT_NEAR(s.coverage, 29.0 / 30.0, kExact);
  // ... the worst segment is the broken one, its tracks by plots held
  ASSERT_EQ(s.worst.size(), 2u);
  EXPECT_EQ(s.worst[0].identity, "A:4321");
  EXPECT_EQ(s.worst[0].breaks, 1);
  EXPECT_EQ(s.worst[0].plots, 20);
  EXPECT_EQ(s.worst[0].held, 19);
  EXPECT_EQ(s.worst[0].tracks, (std::vector<std::int64_t>{2, 1}));
  EXPECT_NEAR(s.worst[0].first, 0.0, kExact);
  EXPECT_NEAR(s.worst[0].last, 76.0, kExact);
  EXPECT_EQ(s.worst[1].identity, "A:1234");
  EXPECT_EQ(s.worst[1].breaks, 0);
  EXPECT_EQ(s.worst[1].tracks, (std::vector<std::int64_t>{1}));
}

TEST(IdentityScore, ACodeChangeWhereTheOldCodeEndedIsLinkedAndKeepsPurity) {
  // GIVEN an aircraft squawking A:1234 (t = 0..36), then A:5201 from t = 40 where the first
  // code ended (one scan's flight on), all held by track 1
  std::vector<IdentityPlot> plots = flight("A:1234", 0.0, 10, 10000.0, 0.0, 1);
  const double x_end = plots.back().x;
  append(plots, flight("A:5201", 40.0, 10, x_end + kSpeed * kScan, 0.0, 1));
  // WHEN scored
  const IdentityScore s = score_identities(plots, {.gap = 20.0});
  // THEN the change is linked: the track holds one aircraft, pure, without breaks
  EXPECT_EQ(s.code_changes, 1);
  EXPECT_EQ(s.segments, 2);
  EXPECT_EQ(s.breaks, 0);
  EXPECT_NEAR(s.purity, 1.0, kExact);
  EXPECT_NEAR(s.coverage, 1.0, kExact);

  // GIVEN the same, but the new code appears 100 km away (another aircraft)
  std::vector<IdentityPlot> far = flight("A:1234", 0.0, 10, 10000.0, 0.0, 1);
  append(far, flight("A:5201", 40.0, 10, x_end + 100000.0, 0.0, 1));
  // THEN nothing is linked and the track holds two identities: purity 10 of 20
  const IdentityScore f = score_identities(far, {.gap = 20.0});
  EXPECT_EQ(f.code_changes, 0);
  EXPECT_NEAR(f.purity, 0.5, kExact);

  // GIVEN the new code starting more than `gap` after the old one ended (t = 36 + 24)
  std::vector<IdentityPlot> late = flight("A:1234", 0.0, 10, 10000.0, 0.0, 1);
  append(late, flight("A:5201", 60.0, 10, x_end + kSpeed * 24.0, 0.0, 1));
  // THEN it is not a code change either
  const IdentityScore l = score_identities(late, {.gap = 20.0});
  EXPECT_EQ(l.code_changes, 0);
  EXPECT_NEAR(l.purity, 0.5, kExact);
}

TEST(IdentityScore, GenericCodesAreNotIdentities) {
  // GIVEN the conspicuity, emergency and test codes (octal)
  for (const std::uint16_t code : {00000, 01200, 02000, 07000, 07500, 07600, 07700, 07777}) {
    // THEN a plot squawking one has no identity
    EXPECT_EQ(plot_identity(code, std::nullopt), "") << "code " << std::oct << code;
    // ... unless it carries a Mode S address, which is the identity
    EXPECT_EQ(plot_identity(code, 0x4CA2D7u), "S:4CA2D7");
  }
  // ... while other codes are, written as 4 octal digits
  EXPECT_EQ(plot_identity(02270, std::nullopt), "A:2270");
  EXPECT_EQ(plot_identity(00001, std::nullopt), "A:0001");
  EXPECT_EQ(plot_identity(std::nullopt, std::nullopt), "");
}

TEST(IdentityScore, PlotsWithoutIdentityAreNotScored) {
  // GIVEN an identified aircraft held by track 1, and as many plots without identity (generic
  // code) held by track 2 or by track 1
  std::vector<IdentityPlot> plots = flight("A:1234", 0.0, 10, 10000.0, 0.0, 1);
  append(plots, flight("", 0.0, 10, -20000.0, 0.0, 2));
  append(plots, flight("", 0.0, 5, 10000.0, 50.0, 1));
  // WHEN scored
  const IdentityScore s = score_identities(plots, {});
  // THEN only the identified plots count
  EXPECT_EQ(s.identity_plots, 10);
  EXPECT_EQ(s.held_plots, 10);
  EXPECT_EQ(s.segments, 1);
  EXPECT_NEAR(s.purity, 1.0, kExact);
  EXPECT_NEAR(s.coverage, 1.0, kExact);
}

TEST(IdentityScore, ASilenceLongerThanTheGapSplitsASegment) {
  // GIVEN one identity seen t = 0..36, silent 24 s, then seen t = 60..96; track 1 holds the
  // first part and track 2 the second
  std::vector<IdentityPlot> plots = flight("A:1234", 0.0, 10, 10000.0, 0.0, 1);
  append(plots, flight("A:1234", 60.0, 10, 10000.0 + kSpeed * 60.0, 0.0, 2));
  // WHEN scored with a 20 s gap
  const IdentityScore split = score_identities(plots, {.gap = 20.0});
  // THEN the silence ends a segment: two segments, each held by one track, no break
  EXPECT_EQ(split.segments, 2);
  EXPECT_EQ(split.breaks, 0);
  // ... and both are one aircraft (one identity): each track is pure
  EXPECT_NEAR(split.purity, 1.0, kExact);
  EXPECT_EQ(split.code_changes, 0);
  // WHEN scored with a 30 s gap
  const IdentityScore whole = score_identities(plots, {.gap = 30.0});
  // THEN it is one segment held by two tracks: one break
  EXPECT_EQ(whole.segments, 1);
  EXPECT_EQ(whole.breaks, 1);
  EXPECT_EQ(whole.worst.at(0).tracks, (std::vector<std::int64_t>{1, 2}));
}

TEST(IdentityScore, ATrackHoldingFewerThanThreePlotsIsNoBreak) {
  // GIVEN an aircraft held by track 1 except two plots taken by track 2
  std::vector<IdentityPlot> plots = flight("S:4CA2D7", 0.0, 10, 10000.0, 0.0, 1);
  plots[4].track = 2;
  plots[5].track = 2;
  // WHEN scored
  const IdentityScore s = score_identities(plots, {});
  // THEN no break, but track 2 holds no plot of its own: purity stays 1 (each track's plots
  // are all this identity's)
  EXPECT_EQ(s.breaks, 0);
  EXPECT_EQ(s.worst.at(0).tracks, (std::vector<std::int64_t>{1}));
  EXPECT_NEAR(s.purity, 1.0, kExact);
  // ... and a third plot makes it one
  plots[6].track = 2;
  EXPECT_EQ(score_identities(plots, {}).breaks, 1);
}

}  // namespace
}  // namespace skytrack::metrics
