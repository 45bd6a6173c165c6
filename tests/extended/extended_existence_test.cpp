// Existence probability of an extended track (extended_existence.hpp): the IPDA-style steps by
// hand.
#include <cmath>

#include <gtest/gtest.h>

#include "skytrack/extended/extended_estimator_mode.hpp"
#include "skytrack/extended/extended_existence.hpp"

namespace skytrack::extended {
namespace {

double odds(double log_odds) {
  return std::exp(log_odds);
}

TEST(ExtendedExistence, MissScalesTheOddsByOneLessTheChanceOfAUsablePartition) {
  // GIVEN P_D 0.95, gamma 8, a partition needs 2 plots: P(n >= 2) = 1 - 9 e^-8
  const ExistenceSpec spec;
  const double usable = 0.95 * (1.0 - 9.0 * std::exp(-8.0));
  // WHEN a scan brings no plots THEN the odds r / (1 - r) are multiplied by 1 - P_D'
  EXPECT_NEAR(odds(existence_miss(std::log(4.0), 2, spec)), 4.0 * (1.0 - usable), 1e-12);
}

TEST(ExtendedExistence, HitAddsThePlotCountsLikelihoodRatio) {
  // GIVEN 2 plots from a gate of 40 000 m^2 with clutter density 1e-6 (0.04 expected)
  const ExistenceSpec spec;
  const double object = std::exp(-8.0) * 64.0 / 2.0;      // Poisson(2; 8)
  const double clutter = std::exp(-0.04) * 0.0016 / 2.0;  // Poisson(2; 0.04)
  // WHEN the track takes them THEN ln L = ln(P_D Poisson(2; 8) / Poisson(2; 0.04))
  EXPECT_NEAR(existence_hit(0.0, 2, 40000.0, spec), std::log(0.95 * object / clutter), 1e-9);
  // AND more of an object's plots are more evidence than a pair
  EXPECT_GT(existence_hit(0.0, 8, 40000.0, spec), existence_hit(0.0, 2, 40000.0, spec) + 20.0);
}

TEST(ExtendedExistence, PredictionCapsTheProbabilityAtSurvival) {
  // GIVEN a track all but certain (r = 1 - 1e-20) WHEN a scan passes THEN r = p_s r
  const ExistenceSpec spec;
  const double r = existence_probability(existence_predict(46.0, spec));
  EXPECT_NEAR(r, spec.survival, 1e-12);
  EXPECT_NEAR(existence_probability(existence_predict(0.0, spec)), 0.5 * spec.survival, 1e-12);
}

TEST(ExtendedExistence, WellSeenTrackOutlivesThreeMissesAndAPairTrackDoesNot) {
  // GIVEN the defaults (P_D 0.95, p_s 0.99999, delete below r = 0.5)
  const ExistenceSpec spec;
  auto misses_survived = [&spec](double log_odds) {
    int survived = 0;
    for (;;) {
      log_odds = existence_miss(existence_predict(log_odds, spec), 2, spec);
      if (existence_probability(log_odds) < spec.delete_below) return survived;
      ++survived;
    }
  };
  // WHEN a track has taken 8 plots a scan (its existence at the cap) THEN it survives 3
  // scans without plots and goes at the 4th
  double seen = existence_birth(spec);
  for (int k = 0; k < 2; ++k) seen = existence_hit(existence_predict(seen, spec), 8, 4e4, spec);
  EXPECT_EQ(misses_survived(seen), 3);
  // WHEN a track was confirmed on pairs of plots (clutter) THEN it goes after at most 2
  double pair = existence_birth(spec);
  for (int k = 0; k < 2; ++k) pair = existence_hit(existence_predict(pair, spec), 2, 4e4, spec);
  EXPECT_LE(misses_survived(pair), 1);
}

TEST(ExtendedExistence, ModeRefusesParametersOutOfRange) {
  // GIVEN an extended profile WHEN P_D is 0 or the deletion threshold 1 THEN no mode
  config::TrackingProfile profile;
  profile.mode = config::TrackingMode::kExtended;
  EXPECT_TRUE(ExtendedMode::create(profile));
  profile.extended.existence.detection_probability = 0.0;
  EXPECT_FALSE(ExtendedMode::create(profile));
  profile.extended.existence.detection_probability = 0.95;
  profile.extended.existence.delete_below = 1.0;
  EXPECT_FALSE(ExtendedMode::create(profile));
  // AND with existence off its parameters are not used
  profile.extended.existence.enabled = false;
  EXPECT_TRUE(ExtendedMode::create(profile));
}

}  // namespace
}  // namespace skytrack::extended
