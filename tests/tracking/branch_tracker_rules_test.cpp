// Branch tracking by paper 003 §1 rules (5)-(10): sons, grandsons, caps, pruning; switched off.
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "skytrack/tracking/point_tracker.hpp"

#include "branch_tracker_test_support.hpp"

namespace skytrack {
namespace {

using test::branch_profile;
using test::Script;
using test::shown;

/// The provisional number shown as n.
std::int64_t provisional(std::int64_t n) {
  return kProvisionalNumber + n - 1;
}

TEST(BranchTracker, FatherManoeuvrePairStartsAHiddenSonFromTheFathersLastPlot) {
  // GIVEN confirmed track 1
  Script s(branch_profile());
  s.start();
  // WHEN the next plot is 150 m off its prediction (manoeuvre gate only)
  s.scan(4, {{400.0, 150.0}});
  // THEN son 2 is created from that plot (rule 6, §2.3 (5)) and only the father is reported
  EXPECT_EQ(s.events(TrackEventType::kBranchCreated),
            (std::vector<std::string>{"1: son 2 of track 1 from plot 401"}));
  EXPECT_EQ(s.reported(), (std::vector<std::int64_t>{1}));
  EXPECT_EQ(s.frame.tracks[0].status, TrackStatus::kCoasting);
  EXPECT_TRUE(s.associated(2, 401));  // the branch's pair is in the associations
  const BranchNode* son = s.tracker.branch_tree().find(provisional(2));
  ASSERT_NE(son, nullptr);
  EXPECT_EQ(son->type, BranchType::kSon);
  EXPECT_EQ(shown(son->parent), 1);
  EXPECT_EQ(s.report.point.branches, 1);
  // AND the son starts from the father's latest update (plot 301 at t = 3): the father's
  // state predicted by the manoeuvre models and updated with the new plot, so it sits on the
  // plot and its velocity has turned towards it
  const auto& tracks = s.tracker.tracks();
  const auto it = std::find_if(tracks.begin(), tracks.end(),
                               [](const PointTrack& t) { return t.branch == BranchType::kSon; });
  ASSERT_NE(it, tracks.end());
  ASSERT_TRUE(it->first_plot.has_value());
  EXPECT_EQ(it->first_plot->plot_id, 301);
  const Gaussian g = ImmFilter::from_profile(branch_profile(), 2)->combine(it->estimate);
  EXPECT_NEAR(g.mean[StateLayout::position(0)], 400.0, 15.0);
  EXPECT_NEAR(g.mean[StateLayout::position(1)], 150.0, 15.0);
  EXPECT_NEAR(g.mean[StateLayout::velocity(0)], 100.0, 20.0);
  EXPECT_GT(g.mean[StateLayout::velocity(1)], 100.0);
}

TEST(BranchTracker, ConfirmedSonReplacesTheFatherAndKeepsItsNumber) {
  // GIVEN son 2 of track 1 (as above)
  Script s(branch_profile());
  s.start();
  s.scan(4, {{400.0, 150.0}});
  // WHEN the son's next plot falls in its non-manoeuvre gate
  s.scan(5, {{500.0, 300.0}});
  // THEN the son is updated, passes confirmation and replaces the father (rules 8, 10;
  // §2.3 (2)): track 1 is now where the son is, the father is gone, no number changes
  EXPECT_EQ(s.events(TrackEventType::kBranchPromoted).size(), 1u);
  EXPECT_EQ(
      s.events(TrackEventType::kBranchPromoted)[0].rfind("1: son 2 of track 1 replaces track 1", 0),
      0u);
  EXPECT_EQ(s.reported(), (std::vector<std::int64_t>{1}));
  ASSERT_NE(s.track(1), nullptr);
  EXPECT_EQ(s.track(1)->status, TrackStatus::kConfirmed);
  EXPECT_NEAR(s.track(1)->position.y(), 300.0, 30.0);
  EXPECT_TRUE(s.associated(2, 501));
  EXPECT_TRUE(s.events(TrackEventType::kDeleted).empty());
  EXPECT_EQ(s.live_branches(), 0);
  EXPECT_FALSE(s.tracker.branch_tree().contains(provisional(2)));
  EXPECT_EQ(s.tracker.branch_tree().find(1)->type, BranchType::kFather);
  // AND the track goes on along the son's line under number 1
  s.scan(6, {{600.0, 450.0}});
  EXPECT_EQ(s.reported(), (std::vector<std::int64_t>{1}));
  EXPECT_TRUE(s.associated(1, 601));
}

TEST(BranchTracker, FatherNonManoeuvreUpdateDeletesSonsWithoutOne) {
  // GIVEN son 2 of track 1, never updated by a non-manoeuvre pair
  Script s(branch_profile());
  s.start();
  s.scan(4, {{400.0, 150.0}});
  // WHEN the father's own next plot arrives (the 150 m plot was a false alarm)
  s.scan(5, {{500.0, 0.0}});
  // THEN the father is updated and the son deleted (rule 5, §2.3 (1))
  EXPECT_EQ(s.events(TrackEventType::kBranchPruned),
            (std::vector<std::string>{"1: son 2 of track 1: track 1 took plot 501 (rule 5)"}));
  EXPECT_EQ(s.reported(), (std::vector<std::int64_t>{1}));
  EXPECT_TRUE(s.associated(1, 501));
  EXPECT_NEAR(s.track(1)->position.y(), 0.0, 30.0);
  EXPECT_EQ(s.live_branches(), 0);
  EXPECT_TRUE(s.tracker.branch_tree().find(1)->children.empty());
}

TEST(BranchTracker, SonWithANonManoeuvreUpdateBecomesAnIndependentFather) {
  // GIVEN confirmation needs 4 of 4 scans, so a son survives one update unconfirmed
  config::TrackingProfile profile = branch_profile();
  profile.point.track_life.confirm_m = 4;
  Script s(profile);
  for (int t = 0; t <= 3; ++t) s.scan(t, {{100.0 * t, 0.0}});
  ASSERT_EQ(s.frame.tracks.at(0).status, TrackStatus::kConfirmed);
  s.scan(4, {{400.0, 150.0}});  // son 2
  s.scan(5, {{500.0, 300.0}});  // son 2's non-manoeuvre update: 3 of 4, not confirmed
  ASSERT_TRUE(s.events(TrackEventType::kBranchPromoted).empty());
  ASSERT_TRUE(s.tracker.branch_tree().find(provisional(2))->non_manoeuvre_updated);
  // WHEN the father takes its own plot again, and the son its own
  s.scan(6, {{600.0, 0.0}, {600.0, 450.0}});
  // THEN the son leaves the tree as father 2 with its own number (rule 5, §2.3 (1)) and both
  // are reported
  EXPECT_EQ(s.events(TrackEventType::kInitiated).size(), 1u);
  EXPECT_EQ(s.events(TrackEventType::kInitiated)[0].rfind("2: independent son 2 of track 1", 0),
            0u);
  EXPECT_EQ(s.reported(), (std::vector<std::int64_t>{1, 2}));
  EXPECT_NEAR(s.track(1)->position.y(), 0.0, 30.0);
  EXPECT_NEAR(s.track(2)->position.y(), 450.0, 30.0);
  // (a confirmed father: numbered 2, the next number)
  ASSERT_NE(s.tracker.branch_tree().find(2), nullptr);
  EXPECT_EQ(s.tracker.branch_tree().find(2)->type, BranchType::kFather);
  EXPECT_EQ(s.live_branches(), 0);
}

TEST(BranchTracker, SonManoeuvrePairStartsAGrandsonThatReplacesTheFather) {
  // GIVEN son 2 of track 1
  Script s(branch_profile());
  s.start();
  s.scan(4, {{400.0, 150.0}});
  // WHEN the next plot misses the son's non-manoeuvre gate but lies in its manoeuvre gate
  s.scan(5, {{500.0, 100.0}});
  // THEN grandson 3 is created from it (rule 7, §2.3 (4)), starting at the son's first plot
  // (x = 300 at t = 3), so its velocity is (100, 50) m/s
  EXPECT_EQ(s.events(TrackEventType::kBranchCreated),
            (std::vector<std::string>{"1: grandson 3 of son 2 from plot 501"}));
  const BranchNode* grandson = s.tracker.branch_tree().find(provisional(3));
  ASSERT_NE(grandson, nullptr);
  EXPECT_EQ(grandson->type, BranchType::kGrandson);
  EXPECT_EQ(shown(grandson->parent), 2);
  EXPECT_EQ(s.reported(), (std::vector<std::int64_t>{1}));
  // WHEN the grandson's next plot falls in its manoeuvre gate
  s.scan(6, {{600.0, 150.0}});
  // THEN it is updated (rule 9), confirmed and replaces the father under number 1; the son
  // (no non-manoeuvre update) is deleted (rule 10, §2.3 (3))
  EXPECT_EQ(s.events(TrackEventType::kBranchPromoted).size(), 1u);
  EXPECT_EQ(s.events(TrackEventType::kBranchPromoted)[0].rfind(
                "1: grandson 3 of son 2 replaces track 1", 0),
            0u);
  EXPECT_EQ(s.events(TrackEventType::kBranchPruned).size(), 1u);
  EXPECT_EQ(s.events(TrackEventType::kBranchPruned)[0].rfind("1: son 2 of track 1", 0), 0u);
  EXPECT_EQ(s.reported(), (std::vector<std::int64_t>{1}));
  EXPECT_NEAR(s.track(1)->position.y(), 150.0, 30.0);
  EXPECT_EQ(s.live_branches(), 0);
}

TEST(BranchTracker, GrandsonIsUpdatedThroughItsManoeuvreGate) {
  // GIVEN grandson 3 (as above)
  Script s(branch_profile());
  s.start();
  s.scan(4, {{400.0, 150.0}});
  s.scan(5, {{500.0, 100.0}});
  ASSERT_TRUE(s.tracker.branch_tree().contains(provisional(3)));
  // WHEN a plot lies exactly on its prediction
  s.scan(6, {{600.0, 150.0}});
  // THEN its association is a manoeuvre one: the grandson was updated (it replaced the
  // father), and no non-manoeuvre rule fired for it (rule 8 prunes only grandsons of an
  // updated son)
  EXPECT_TRUE(s.associated(3, 601));
  EXPECT_EQ(s.events(TrackEventType::kBranchPromoted).size(), 1u);
}

TEST(BranchTracker, TwoPlotsInTheManoeuvreGateStartTwoSonsAndTheLikelierWins) {
  // GIVEN track 1 and two plots in its manoeuvre gate only (paper 003 §4.3)
  Script s(branch_profile());
  s.start();
  s.scan(4, {{400.0, 150.0}, {400.0, -175.0}});
  EXPECT_EQ(s.events(TrackEventType::kBranchCreated).size(), 2u);
  EXPECT_EQ(s.tracker.branch_tree().branch_count(1), 2);
  // WHEN the next plot continues one of them
  s.scan(5, {{500.0, -350.0}});
  // THEN that son replaces the father under number 1 and the other son is deleted
  EXPECT_EQ(s.events(TrackEventType::kBranchPromoted).size(), 1u);
  EXPECT_EQ(s.events(TrackEventType::kBranchPruned).size(), 1u);
  EXPECT_EQ(s.reported(), (std::vector<std::int64_t>{1}));
  EXPECT_NEAR(s.track(1)->position.y(), -350.0, 30.0);
  EXPECT_EQ(s.live_branches(), 0);
}

TEST(BranchTracker, AtTheBranchCapTheLeastLikelyBranchIsPruned) {
  // GIVEN at most one branch per father, and two plots in track 1's manoeuvre gate, one
  // nearer its prediction (more probable)
  config::TrackingProfile profile = branch_profile();
  profile.point.branching.max_branches_per_father = 1;
  Script s(profile);
  s.start();
  s.scan(4, {{400.0, 150.0}, {400.0, -175.0}});
  // THEN one son is created and the other decision is a pruning at the cap
  EXPECT_EQ(s.events(TrackEventType::kBranchCreated),
            (std::vector<std::string>{"1: son 2 of track 1 from plot 401"}));
  ASSERT_EQ(s.events(TrackEventType::kBranchPruned).size(), 1u);
  EXPECT_NE(s.events(TrackEventType::kBranchPruned)[0].find("cap of 1 per father"),
            std::string::npos);
  EXPECT_EQ(s.tracker.branch_tree().branch_count(1), 1);
}

TEST(BranchTracker, NoRoomLeftUnderMaxChildrenCreatesNoMoreSons) {
  config::TrackingProfile profile = branch_profile();
  profile.point.branching.max_children = 1;
  Script s(profile);
  s.start();
  s.scan(4, {{400.0, 150.0}, {400.0, -175.0}});
  EXPECT_EQ(s.events(TrackEventType::kBranchCreated).size(), 1u);
  EXPECT_EQ(s.tracker.branch_tree().branch_count(1), 1);
}

TEST(BranchTracker, BranchWithoutPlotsIsPrunedByItsTrackLife) {
  Script s(branch_profile());
  s.start();
  s.scan(4, {{400.0, 150.0}});  // son 2 (tentative, deleted after 2 consecutive misses)
  s.scan(5, {});
  EXPECT_TRUE(s.events(TrackEventType::kBranchPruned).empty());
  s.scan(6, {});
  EXPECT_EQ(s.events(TrackEventType::kBranchPruned),
            (std::vector<std::string>{"1: son 2 of track 1: no plot"}));
  EXPECT_EQ(s.reported(), (std::vector<std::int64_t>{1}));
}

TEST(BranchTracker, SwitchedOffItIsPlainImmJpda) {
  // GIVEN the same script with branching off
  config::TrackingProfile profile = branch_profile();
  profile.point.branching.enabled = false;
  Script s(profile);
  s.start();
  s.scan(4, {{400.0, 150.0}});
  s.scan(5, {{500.0, 300.0}});
  // THEN no branch exists and no branch event is written
  for (const TrackEvent& e : s.frame.events)
    EXPECT_EQ(type_name(e).rfind("branch_", 0), std::string::npos);
  EXPECT_EQ(s.live_branches(), 0);
  EXPECT_EQ(s.report.point.branches, 0);
}

}  // namespace
}  // namespace skytrack
