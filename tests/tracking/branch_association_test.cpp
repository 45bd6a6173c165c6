// Ordered confirmation of plot-track pairs, paper 003 §2.2.
#include "skytrack/tracking/branch_association.hpp"

#include <gtest/gtest.h>

namespace skytrack {
namespace {

using K = PairKind;

TEST(BranchAssociation, KindsAreConfirmedInThePapersOrder) {
  // GIVEN one pair of each kind, each on its own track and plot, listed backwards and with
  // the later kinds more probable
  const std::vector<BranchPair> pairs = {{K::kFatherManoeuvre, 4, 4, 0.9},
                                         {K::kSonManoeuvre, 3, 3, 0.8},
                                         {K::kGrandsonManoeuvre, 2, 2, 0.7},
                                         {K::kSonNonManoeuvre, 1, 1, 0.6},
                                         {K::kFatherNonManoeuvre, 0, 0, 0.5}};
  const auto confirmed = confirm_pairs(pairs, 5, 5);
  // THEN father NM > son NM > grandson M > son M > father M
  ASSERT_EQ(confirmed.size(), 5u);
  for (int i = 0; i < 5; ++i) EXPECT_EQ(static_cast<int>(confirmed[i].kind), i);
}

TEST(BranchAssociation, APlotIsTakenOnceByTheEarlierKind) {
  // GIVEN plot 0 in a father's non-manoeuvre gate and in a son's, the son's pair likelier
  const std::vector<BranchPair> pairs = {{K::kSonNonManoeuvre, 1, 0, 0.99},
                                         {K::kFatherNonManoeuvre, 0, 0, 0.6}};
  const auto confirmed = confirm_pairs(pairs, 2, 1);
  // THEN the father's kind comes first and the son's pair is dropped
  ASSERT_EQ(confirmed.size(), 1u);
  EXPECT_EQ(confirmed[0].track, 0);
}

TEST(BranchAssociation, InsideAKindTheMoreProbablePairWins) {
  // GIVEN two fathers wanting plot 0 and father 0 also gating plot 1
  const std::vector<BranchPair> pairs = {{K::kFatherNonManoeuvre, 0, 0, 0.5},
                                         {K::kFatherNonManoeuvre, 1, 0, 0.7},
                                         {K::kFatherNonManoeuvre, 0, 1, 0.3}};
  const auto confirmed = confirm_pairs(pairs, 2, 2);
  // THEN father 1 takes plot 0 (0.7) and father 0 falls back on plot 1
  ASSERT_EQ(confirmed.size(), 2u);
  EXPECT_EQ(confirmed[0].track, 1);
  EXPECT_EQ(confirmed[0].plot, 0);
  EXPECT_EQ(confirmed[1].track, 0);
  EXPECT_EQ(confirmed[1].plot, 1);
}

TEST(BranchAssociation, AnUpdatedTrackTakesOnePlotAndCreatesNoBranch) {
  // GIVEN a father with two plots in its non-manoeuvre gate and a third in its manoeuvre gate
  const std::vector<BranchPair> pairs = {{K::kFatherNonManoeuvre, 0, 0, 0.6},
                                         {K::kFatherNonManoeuvre, 0, 1, 0.3},
                                         {K::kFatherManoeuvre, 0, 2, 0.4}};
  const auto confirmed = confirm_pairs(pairs, 1, 3);
  // THEN only its best non-manoeuvre pair is confirmed (no son: rule 6)
  ASSERT_EQ(confirmed.size(), 1u);
  EXPECT_EQ(confirmed[0].plot, 0);
}

TEST(BranchAssociation, ACreatingTrackMayStartOneBranchPerPlot) {
  // GIVEN two plots in a father's manoeuvre gate (paper 003 §4.3) and one of them also in
  // a son's manoeuvre gate
  const std::vector<BranchPair> pairs = {{K::kFatherManoeuvre, 0, 0, 0.5},
                                         {K::kFatherManoeuvre, 0, 1, 0.4},
                                         {K::kSonManoeuvre, 1, 1, 0.2}};
  const auto confirmed = confirm_pairs(pairs, 2, 2);
  // THEN the son's pair takes plot 1 (son M > father M) and the father starts from plot 0
  ASSERT_EQ(confirmed.size(), 2u);
  EXPECT_EQ(confirmed[0].kind, K::kSonManoeuvre);
  EXPECT_EQ(confirmed[1].kind, K::kFatherManoeuvre);
  EXPECT_EQ(confirmed[1].plot, 0);
  // AND without the son both plots start branches of the father
  const auto alone = confirm_pairs(std::span(pairs).first(2), 2, 2);
  EXPECT_EQ(alone.size(), 2u);
}

}  // namespace
}  // namespace skytrack
