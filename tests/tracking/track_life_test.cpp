#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "skytrack/tracking/track_life.hpp"

namespace skytrack {
namespace {

config::TrackLifeSpec spec() {
  config::TrackLifeSpec s;
  s.confirmation = config::ConfirmationMethod::kMOfN;
  s.confirm_m = 3;
  s.confirm_n = 4;
  s.delete_tentative_misses = 2;
  s.delete_confirmed_misses = 3;
  s.delete_position_sigma = 1000.0;
  return s;
}

config::TrackLifeSpec existence_spec() {
  config::TrackLifeSpec s = spec();
  s.confirmation = config::ConfirmationMethod::kExistence;
  s.confirm_existence = 0.95;
  s.delete_existence = 0.01;
  s.survival_probability = 0.98;
  return s;
}

TEST(TrackLife, ExistenceFollowsTheIpdaRecursion) {
  // GIVEN existence 0.5, P_S 0.98, P_D 0.9, P_G 0.999
  TrackLife life;
  life.existence = 0.5;
  // WHEN a scan has no plot in the gate: chi- = 0.49, delta = 0.8991,
  // chi = 0.1009 * 0.49 / (1 - 0.8991 * 0.49) = 0.0494410 / 0.5594410 (by hand)
  update_existence(life, 0.0, 0.9, 0.999, existence_spec());
  EXPECT_NEAR(life.existence, 0.0494410 / 0.5594410, 1e-9);
  // WHEN a plot 100 times likelier under the track than as clutter arrives:
  // delta = 0.9 (0.999 - 100) = -89.1009; chi = 90.1009 chi- / (1 + 89.1009 chi-)
  const double before = 0.98 * life.existence;
  update_existence(life, 100.0, 0.9, 0.999, existence_spec());
  EXPECT_NEAR(life.existence, 90.1009 * before / (1.0 + 89.1009 * before), 1e-12);
  EXPECT_GT(life.existence, 0.85);
  // WHEN the gate holds only clutter whose likelihoods sum to P_G (its mean): delta = 0,
  // the existence only decays by survival
  const double last = life.existence;
  update_existence(life, 0.999, 0.9, 0.999, existence_spec());
  EXPECT_NEAR(life.existence, 0.98 * last, 1e-12);
  // AND nothing non-finite gets in
  update_existence(life, std::numeric_limits<double>::quiet_NaN(), 0.9, 0.999, existence_spec());
  EXPECT_TRUE(std::isfinite(life.existence));
  EXPECT_GT(life.existence, 0.0);
}

TEST(TrackLife, ExistenceConfirmsAndDeletesOnItsThresholds) {
  const config::TrackLifeSpec s = existence_spec();
  // GIVEN a new track at existence 0.1: one strong plot does not confirm it (0.1 -> ~0.9)...
  TrackLife life = initiated_life(3, 3);
  life.existence = 0.1;
  update_existence(life, 100.0, 0.9, 0.999, s);
  EXPECT_FALSE(advance_life(life, true, 10.0, s).confirmed);
  // ...a second one does, whatever the M-of-N count says
  update_existence(life, 100.0, 0.9, 0.999, s);
  EXPECT_GE(life.existence, 0.95);
  EXPECT_TRUE(advance_life(life, true, 10.0, s).confirmed);
  // A confirmed track whose existence collapses is deleted before its miss limit.
  life.existence = 0.005;
  const LifeChange change = advance_life(life, true, 10.0, s);
  EXPECT_TRUE(change.deleted);
  // AND a tentative clutter chain with only clutter-like plots never confirms and dies.
  TrackLife chain = initiated_life(3, 3);
  chain.existence = 0.1;
  bool deleted = false;
  for (int scan = 0; scan < 40 && !deleted; ++scan) {
    update_existence(chain, scan % 2 == 0 ? 0.999 : 0.0, 0.9, 0.999, s);
    const LifeChange c = advance_life(chain, scan % 2 == 0, 10.0, s);
    EXPECT_FALSE(c.confirmed);
    deleted = c.deleted;
  }
  EXPECT_TRUE(deleted);
}

TEST(TrackLife, ExistenceToOutliveAMissSeparatesTracksALookWithoutAPlotDeletes) {
  const config::TrackLifeSpec s = existence_spec();
  config::DetectabilitySpec detectability;
  detectability.hide = 0.05;  // a fresh track's miss then weighs at P_D 0.855
  const double pd = 0.9, pg = 0.999;
  const double threshold = existence_to_outlive_a_miss(pd, pg, s, detectability);
  ASSERT_GT(threshold, 0.0);
  ASSERT_LT(threshold, s.confirm_existence);
  const auto after_a_miss = [&](double existence) {
    TrackLife life = initiated_life(3, 3);
    life.existence = existence;
    update_existence(life, 0.0, support_detection_probability(life, pd, detectability), pg, s);
    return advance_life(life, false, 10.0, s);
  };
  // Just above the threshold a new track outlives a look without a plot; just below it is
  // deleted by that look (the miss weighed as the tracker weighs it, on the detectability
  // chain).
  EXPECT_FALSE(after_a_miss(threshold * 1.001).deleted);
  EXPECT_TRUE(after_a_miss(threshold * 0.999).deleted);
  // Weighed at the full P_D (no masking), the miss costs more: below the threshold it still
  // deletes.
  detectability.hide = 0.0;
  EXPECT_TRUE(after_a_miss(threshold * 0.999).deleted);
  // M of N: the existence deletes no track, so none is too weak.
  EXPECT_EQ(existence_to_outlive_a_miss(pd, pg, spec(), detectability), 0.0);
}

TEST(TrackLife, SupportIsTheLogRatioOfTheScansBestHypothesis) {
  // A miss: 1 - P_D P_G; a plot likelier than that: P_D L / lambda; never below the miss.
  EXPECT_NEAR(scan_support(0.0, 0.9, 0.999), std::log(1.0 - 0.9 * 0.999), 1e-12);
  EXPECT_NEAR(scan_support(20.0, 0.9, 0.999), std::log(0.9 * 20.0), 1e-12);
  EXPECT_NEAR(scan_support(0.05, 0.9, 0.999), std::log(1.0 - 0.9 * 0.999), 1e-12);
  EXPECT_NEAR(scan_support(std::numeric_limits<double>::quiet_NaN(), 0.9, 0.999),
              std::log(1.0 - 0.9 * 0.999), 1e-12);
  // P_D = P_G = 1 and no plot: very unlikely, still finite.
  EXPECT_TRUE(std::isfinite(scan_support(0.0, 1.0, 1.0 - 1e-12)));
}

TEST(TrackLife, DetectabilityChainMakesARunOfMissesCheaperThanIndependentMisses) {
  // GIVEN P_D 0.9, P_G 0.999 and the default chain: hidden with 0.05, detectable again with
  // 0.3 per scan; a track just detected (detectability 1)
  const config::DetectabilitySpec chain{.hide = 0.05, .reveal = 0.3};
  TrackLife life;
  // WHEN it misses four scans in a row with nothing in its gate
  double support = 0.0;
  double predicted = 0.95;  // (1 - hide) * 1 + reveal * 0
  for (int scan = 0; scan < 4; ++scan) {
    const double pd = support_detection_probability(life, 0.9, chain);
    EXPECT_NEAR(pd, 0.9 * predicted, 1e-12);
    support += scan_support(0.0, pd, 0.999);
    update_detectability(life, 0.0, 0.9, 0.999, chain);
    // by hand: a hidden target explains the miss at 1, a detectable one at 1 - P_D P_G
    const double seen = predicted * (1.0 - 0.9 * 0.999);
    EXPECT_NEAR(life.detectable, seen / (seen + 1.0 - predicted), 1e-12);
    predicted = 0.95 * life.detectable + 0.3 * (1.0 - life.detectable);
  }
  // THEN each miss costs less than the one before, and the run about -3.9 instead of the
  // -9.2 of four independent misses at 1 - P_D
  EXPECT_NEAR(support, -3.87, 0.02);
  EXPECT_LT(4.0 * std::log(1.0 - 0.9 * 0.999), support - 5.0);
  // WHEN the target returns with a plot 20 times likelier under the track than as clutter
  const double pd = support_detection_probability(life, 0.9, chain);
  EXPECT_LT(pd, 0.35);  // a return after four misses is itself less likely
  EXPECT_NEAR(scan_support(20.0, pd, 0.999), std::log(pd * 20.0), 1e-12);
  update_detectability(life, 20.0, 0.9, 0.999, chain);
  // THEN the target is detectable again, nearly surely
  EXPECT_GT(life.detectable, 0.9);
  // AND clutter alone in the gate (likelihoods summing to P_G) leaves the odds unchanged
  TrackLife cluttered;
  cluttered.detectable = 0.6;
  update_detectability(cluttered, 0.999, 0.9, 0.999, chain);
  EXPECT_NEAR(cluttered.detectable, 0.95 * 0.6 + 0.3 * 0.4, 1e-12);
  // AND hide 0 keeps every scan at P_D: independent misses
  TrackLife plain;
  const config::DetectabilitySpec off{.hide = 0.0, .reveal = 0.3};
  for (int scan = 0; scan < 4; ++scan) {
    EXPECT_NEAR(support_detection_probability(plain, 0.9, off), 0.9, 1e-12);
    update_detectability(plain, 0.0, 0.9, 0.999, off);
  }
}

TEST(TrackLife, ConfirmsOnMOfNCountedFromTheFirstPlot) {
  // GIVEN a track initiated from 2 plots in 2 scans
  TrackLife life = initiated_life(2, 2);
  // WHEN it misses once and then hits: 3 hits in the last 4 scans
  EXPECT_FALSE(advance_life(life, false, 10.0, spec()).confirmed);
  EXPECT_EQ(life.status, TrackStatus::kTentative);
  const LifeChange change = advance_life(life, true, 10.0, spec());
  // THEN it is confirmed
  EXPECT_TRUE(change.confirmed);
  EXPECT_EQ(life.status, TrackStatus::kConfirmed);
}

TEST(TrackLife, TentativeTrackDiesAfterItsMissLimit) {
  TrackLife life = initiated_life(2, 2);
  advance_life(life, false, 10.0, spec());
  const LifeChange change = advance_life(life, false, 10.0, spec());
  EXPECT_TRUE(change.deleted);
  EXPECT_EQ(life.status, TrackStatus::kDeleted);
}

TEST(TrackLife, ConfirmedTrackCoastsThenDiesAfterKMisses) {
  TrackLife life = initiated_life(3, 3);
  advance_life(life, true, 10.0, spec());
  ASSERT_EQ(life.status, TrackStatus::kConfirmed);
  EXPECT_TRUE(advance_life(life, false, 10.0, spec()).started_coasting);
  EXPECT_EQ(life.status, TrackStatus::kCoasting);
  EXPECT_FALSE(advance_life(life, false, 10.0, spec()).started_coasting);  // only once
  EXPECT_TRUE(advance_life(life, false, 10.0, spec()).deleted);            // third miss
}

TEST(TrackLife, CoastingTrackRecoversOnAHit) {
  TrackLife life = initiated_life(3, 3);
  advance_life(life, true, 10.0, spec());
  advance_life(life, false, 10.0, spec());
  advance_life(life, true, 10.0, spec());
  EXPECT_EQ(life.status, TrackStatus::kConfirmed);
  EXPECT_EQ(life.consecutive_misses, 0);
}

TEST(TrackLife, UncertaintyBeyondTheLimitDeletes) {
  TrackLife life = initiated_life(3, 3);
  advance_life(life, true, 10.0, spec());
  EXPECT_TRUE(advance_life(life, true, 5000.0, spec()).deleted);
}

}  // namespace
}  // namespace skytrack
