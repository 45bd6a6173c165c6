// Branch tracking of an undecided father (branching.ambiguity_beta): sons from its plots decide.
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

TEST(BranchTracker, AmbiguousUpdateLetsTheSonsFromItsPlotsDecideWhileTheFatherIsReported) {
  // GIVEN ambiguity_beta 0.3 and two plots 60 m apart, each about half of track 1's weight
  config::TrackingProfile profile = branch_profile();
  profile.point.branching.ambiguity_beta = 0.3;
  Script s(profile);
  s.start();
  s.scan(4, {{400.0, 30.0}, {400.0, -30.0}});
  // THEN the father is undecided (still reported) and each plot starts a son
  EXPECT_EQ(s.events(TrackEventType::kUndecided).size(), 1u);
  EXPECT_TRUE(s.events(TrackEventType::kSuspended).empty());
  EXPECT_EQ(s.reported(), (std::vector<std::int64_t>{1}));
  EXPECT_EQ(s.events(TrackEventType::kBranchCreated),
            (std::vector<std::string>{"1: son 2 of track 1 from plot 401",
                                      "1: son 3 of track 1 from plot 402"}));
  // WHEN the next plot continues the upper one, THEN that son replaces the father under
  // number 1 and the other is pruned (no non-manoeuvre update since its birth, rule 5)
  s.scan(5, {{500.0, 60.0}});
  EXPECT_FALSE(s.associated(1, 501));  // the undecided father takes no non-manoeuvre pair
  EXPECT_EQ(s.events(TrackEventType::kBranchPromoted),
            (std::vector<std::string>{
                "1: son 2 of track 1 replaces track 1: confirmed with plot 501 (rule 10)"}));
  EXPECT_EQ(s.reported(), (std::vector<std::int64_t>{1}));
  EXPECT_NEAR(s.track(1)->position.y(), 60.0, 30.0);
  EXPECT_EQ(s.live_branches(), 0);
}

TEST(BranchTracker, SonUpdatedWhenItsSiblingWinsBecomesATrackOfItsOwn) {
  // GIVEN track 1 undecided between two plots 60 m apart (two aircraft, one unseen so far)
  config::TrackingProfile profile = branch_profile();
  profile.point.branching.ambiguity_beta = 0.3;
  Script s(profile);
  s.start();
  s.scan(4, {{400.0, 30.0}, {400.0, -30.0}});
  ASSERT_EQ(s.live_branches(), 2);
  // WHEN both sons' targets are seen again, son 2's on its prediction, son 3's 50 m off it
  // (both plots lie in both sons' gates: a son starts wide)
  s.scan(5, {{500.0, 60.0}, {500.0, -110.0}});
  // THEN both sons are confirmed in this scan; the likelier (son 2) replaces the father under
  // number 1 and son 3, updated in the same scan, becomes a track of its own (§2.3 (2)),
  // numbered 2 (the next number), instead of being deleted as a son without a non-manoeuvre
  // update
  EXPECT_EQ(s.events(TrackEventType::kBranchPromoted),
            (std::vector<std::string>{
                "1: son 2 of track 1 replaces track 1: confirmed with plot 501 (rule 10)"}));
  EXPECT_EQ(s.events(TrackEventType::kInitiated),
            (std::vector<std::string>{
                "2: independent son 3 of track 1: confirmed with plot 501 (rule 10)"}));
  EXPECT_TRUE(s.events(TrackEventType::kBranchPruned).empty());
  EXPECT_EQ(s.live_branches(), 0);
  ASSERT_EQ(s.reported(), (std::vector<std::int64_t>{1, 2}));
  EXPECT_NEAR(s.track(1)->position.y(), 60.0, 20.0);
  EXPECT_NEAR(s.track(2)->position.y(), -110.0, 20.0);
  // AND both keep their numbers on their targets
  s.scan(6, {{600.0, 90.0}, {600.0, -190.0}});
  ASSERT_EQ(s.reported(), (std::vector<std::int64_t>{1, 2}));
  EXPECT_NEAR(s.track(1)->position.y(), 90.0, 20.0);
  EXPECT_NEAR(s.track(2)->position.y(), -190.0, 30.0);
}

TEST(BranchTracker, AnotherTracksLikeliestPlotMakesNoAmbiguity) {
  // GIVEN ambiguity_beta 0.3 and two targets 10 m apart flying east side by side (a
  // formation): each track weighs both plots about half and half
  config::TrackingProfile profile = branch_profile();
  profile.point.branching.ambiguity_beta = 0.3;
  Script s(profile);
  int undecided = 0, sons = 0;
  for (int t = 0; t <= 8; ++t) {
    s.scan(t, {{100.0 * t, 5.0}, {100.0 * t, -5.0}});
    undecided += static_cast<int>(s.events(TrackEventType::kUndecided).size());
    sons += static_cast<int>(s.events(TrackEventType::kBranchCreated).size());
  }
  // THEN the other plot of each track is the other track's likeliest: neither track is ever
  // undecided, no son starts, and tracks 1 and 2 keep their numbers
  EXPECT_EQ(undecided, 0);
  EXPECT_EQ(sons, 0);
  EXPECT_EQ(s.reported(), (std::vector<std::int64_t>{1, 2}));
  for (const TrackReport& t : s.frame.tracks) EXPECT_EQ(t.status, TrackStatus::kConfirmed);
}

TEST(BranchTracker, UndecidedFatherWhoseSonsAreGoneTakesPlotsAgain) {
  // GIVEN track 1 undecided between two plots (as above)
  config::TrackingProfile profile = branch_profile();
  profile.point.branching.ambiguity_beta = 0.3;
  Script s(profile);
  s.start();
  s.scan(4, {{400.0, 30.0}, {400.0, -30.0}});
  ASSERT_EQ(s.live_branches(), 2);
  // WHEN neither son gets a plot until their track life ends them
  for (int t = 5; t <= 8 && s.live_branches() > 0; ++t) s.scan(t, {});
  ASSERT_EQ(s.live_branches(), 0);
  ASSERT_EQ(s.reported(), (std::vector<std::int64_t>{1}));
  // THEN the father is a plain father again and takes the target's plot
  const double t = s.frame.time + 1.0;
  s.scan(t, {{100.0 * t, 0.0}});
  EXPECT_TRUE(s.associated(1, static_cast<std::int64_t>(100 * t) + 1));
  EXPECT_EQ(s.frame.tracks[0].status, TrackStatus::kConfirmed);
}

}  // namespace
}  // namespace skytrack
