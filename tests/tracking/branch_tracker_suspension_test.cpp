// Branch tracking of suspended fathers: the sons, plot chains and new tracks that replace them.
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

/// branch_profile() with a position-spread limit (12 m) that one missed scan exceeds.
config::TrackingProfile suspending_profile() {
  config::TrackingProfile p = branch_profile();
  p.point.track_life.delete_position_sigma = 12.0;
  return p;
}

TEST(BranchTracker, FatherDeletedByItsLifeWaitsUnreportedForItsSon) {
  // GIVEN a position-spread limit that one missed scan exceeds
  Script s(suspending_profile());
  s.start();
  // WHEN track 1 misses its plot and a plot lies in its manoeuvre gate
  s.scan(4, {{400.0, 150.0}});
  // THEN it is suspended (not reported, not deleted) and son 2 starts from the plot
  EXPECT_EQ(s.events(TrackEventType::kSuspended).size(), 1u);
  EXPECT_TRUE(s.events(TrackEventType::kDeleted).empty());
  EXPECT_TRUE(s.reported().empty());
  EXPECT_EQ(s.events(TrackEventType::kBranchCreated),
            (std::vector<std::string>{"1: son 2 of track 1 from plot 401"}));
  // WHEN the son's next plot arrives, THEN the son replaces it and number 1 is back
  s.scan(5, {{500.0, 300.0}});
  EXPECT_EQ(s.events(TrackEventType::kBranchPromoted).size(), 1u);
  EXPECT_EQ(s.reported(), (std::vector<std::int64_t>{1}));
  EXPECT_NEAR(s.track(1)->position.y(), 300.0, 30.0);
}

TEST(BranchTracker, FatherTooUncertainToGateYieldsToItsSon) {
  // GIVEN a position-spread limit above track 1's spread after one missed scan, with 1.2
  // times it (the suspension before gating) below its prediction over two, and son 2
  // started in the scan it missed
  config::TrackingProfile profile = branch_profile();
  profile.point.track_life.delete_position_sigma = 13.0;
  Script s(profile);
  s.start();
  s.scan(4, {{400.0, 150.0}});
  ASSERT_EQ(s.events(TrackEventType::kBranchCreated),
            (std::vector<std::string>{"1: son 2 of track 1 from plot 401"}));
  ASSERT_TRUE(s.events(TrackEventType::kSuspended).empty());
  // WHEN the next scan has a plot on the father's straight line and one on the son's
  s.scan(5, {{500.0, 0.0}, {500.0, 300.0}});
  // THEN the father, too uncertain to gate, is suspended before it can take the plot and cut
  // its son (rule 5); the son takes its plot, is confirmed and keeps number 1 (rule 10)
  EXPECT_EQ(s.events(TrackEventType::kSuspended).size(), 1u);
  EXPECT_FALSE(s.associated(1, 501));
  EXPECT_TRUE(s.associated(2, 502));
  EXPECT_EQ(s.events(TrackEventType::kBranchPromoted).size(), 1u);
  EXPECT_EQ(s.reported(), (std::vector<std::int64_t>{1}));
  EXPECT_NEAR(s.track(1)->position.y(), 300.0, 30.0);
}

TEST(BranchTracker, FatherSuspendedByItsUpdateStartsSonsFromItsLikelyPlots) {
  // GIVEN a position-spread limit that track 1's update with two plots 60 m apart exceeds
  config::TrackingProfile profile = branch_profile();
  profile.point.track_life.delete_position_sigma = 14.5;
  Script s(profile);
  s.start();
  // WHEN both plots lie in its non-manoeuvre gate, each likelier than a miss
  s.scan(4, {{400.0, 30.0}, {400.0, -30.0}});
  // THEN its update suspends it, and the plots its IMM-JPDA weighed above its miss start
  // its sons with those weights (not the manoeuvre gate's): one son per plot; it stays
  // reported in this look, whose plots it took
  ASSERT_EQ(s.events(TrackEventType::kSuspended).size(), 1u);
  EXPECT_EQ(s.reported(), (std::vector<std::int64_t>{1}));
  EXPECT_EQ(s.events(TrackEventType::kBranchCreated),
            (std::vector<std::string>{"1: son 2 of track 1 from plot 401",
                                      "1: son 3 of track 1 from plot 402"}));
  for (const std::int64_t plot : {401, 402}) {
    double father = -1.0, son = -2.0;
    for (const Association& a : s.frame.associations) {
      if (a.plot != plot) continue;
      if (shown(a.track) == 1) father = a.probability;
      if (shown(a.track) == 2 || shown(a.track) == 3) son = a.probability;
    }
    EXPECT_DOUBLE_EQ(son, father) << "plot " << plot;
  }
  // AND the son that is followed replaces it under its number
  s.scan(5, {{500.0, 60.0}});
  EXPECT_EQ(s.events(TrackEventType::kBranchPromoted).size(), 1u);
  EXPECT_EQ(s.reported(), (std::vector<std::int64_t>{1}));
  EXPECT_NEAR(s.track(1)->position.y(), 60.0, 30.0);
}

TEST(BranchTracker, SuspendedFatherWithoutBranchesIsDeletedAfterItsMisses) {
  const config::TrackingProfile profile = suspending_profile();
  Script s(profile);
  s.suspend_father();  // suspended, no plot to branch from
  EXPECT_EQ(s.events(TrackEventType::kSuspended).size(), 1u);
  EXPECT_TRUE(s.reported().empty());
  // THEN its branching ends when its misses reach delete_confirmed_misses, and it is deleted
  // (and reported so, once) initiation.n scans later, the time a plot chain of its target
  // needs to form and confirm (§3.3), without a branch
  int deleted_at = 0;
  for (int t = 5; t <= 20 && deleted_at == 0; ++t) {
    s.scan(t, {});
    if (!s.events(TrackEventType::kDeleted).empty()) deleted_at = t;
  }
  EXPECT_EQ(deleted_at,
            3 + profile.point.track_life.delete_confirmed_misses + profile.point.initiation.n);
  ASSERT_EQ(s.reported(), (std::vector<std::int64_t>{1}));
  EXPECT_EQ(s.frame.tracks[0].status, TrackStatus::kDeleted);
}

TEST(BranchTracker, PlotChainInTheManoeuvreGateOfASuspendedFatherContinuesIt) {
  // GIVEN track 1 suspended by a miss at t = 4 (spread limit 12 m); its target comes back
  // towards its line at 300 m/s from 1000 m and 700 m off at t = 5 and 6, outside the
  // father's manoeuvre gate, so those plots start no son
  Script s(suspending_profile());
  s.suspend_father();
  ASSERT_EQ(s.events(TrackEventType::kSuspended).size(), 1u);
  s.scan(5, {{500.0, 1000.0}});
  s.scan(6, {{600.0, 700.0}});
  s.scan(7, {});
  ASSERT_TRUE(s.events(TrackEventType::kBranchCreated).empty());
  // WHEN the chain's third plot falls inside the manoeuvre gate (100 m off) in the scan whose
  // miss, its fifth, ends the father's own branching
  s.scan(8, {{800.0, 100.0}});
  // THEN the chain (plot-to-plot manoeuvre association, §3.3) starts son 2 of track 1 rather
  // than a new track, and the father waits for it, unreported
  EXPECT_EQ(
      s.events(TrackEventType::kBranchCreated),
      (std::vector<std::string>{
          "1: son 2 of track 1 from plots 501 601 801 (a plot chain in its manoeuvre gate)"}));
  EXPECT_TRUE(s.events(TrackEventType::kInitiated).empty());
  EXPECT_TRUE(s.events(TrackEventType::kDeleted).empty());
  EXPECT_TRUE(s.reported().empty());
  // WHEN the son takes its next plot, THEN it is confirmed and carries number 1 (rule 10)
  s.scan(9, {{900.0, -200.0}});
  EXPECT_EQ(s.events(TrackEventType::kBranchPromoted).size(), 1u);
  ASSERT_EQ(s.reported(), (std::vector<std::int64_t>{1}));
  EXPECT_NEAR(s.track(1)->position.y(), -200.0, 30.0);
  EXPECT_NEAR(s.track(1)->velocity.y(), -300.0, 30.0);
}

TEST(BranchTracker, ChainOutsideTheManoeuvreGateOfASuspendedFatherIsANewTrack) {
  // GIVEN the same script, the chain's third plot 1000 m off the father's prediction
  Script s(suspending_profile());
  s.suspend_father();
  s.scan(5, {{500.0, 1000.0}});
  s.scan(6, {{600.0, 1000.0}});
  s.scan(7, {});
  s.scan(8, {{800.0, 1000.0}});
  // THEN it is initiated as track 2, and the father, with no branch, waits unreported
  EXPECT_TRUE(s.events(TrackEventType::kBranchCreated).empty());
  EXPECT_EQ(s.events(TrackEventType::kInitiated),
            (std::vector<std::string>{"2: from plots 501 601 801"}));
  EXPECT_EQ(s.reported(), (std::vector<std::int64_t>{2}));
  // AND track 2, confirmed far from the father's manoeuvre gate, is numbered 2 (the next
  // number)
  s.scan(9, {{900.0, 1000.0}});
  EXPECT_EQ(s.events(TrackEventType::kConfirmed), (std::vector<std::string>{"2: tentative 2"}));
  EXPECT_TRUE(s.events(TrackEventType::kBranchPromoted).empty());
  EXPECT_EQ(s.reported(), (std::vector<std::int64_t>{2}));
}

TEST(BranchTracker, NewTrackConfirmedInTheManoeuvreGateOfASuspendedFatherTakesItsNumber) {
  // GIVEN track 1 suspended by a miss at t = 4 (spread limit 12 m), and its target coming
  // back towards its line at 300 m/s: the plot chain of t = 5, 6, 7 ends 400 m off the
  // father's prediction, outside its manoeuvre gate, so it starts track 2
  Script s(suspending_profile());
  s.suspend_father();
  s.scan(5, {{500.0, 1000.0}});
  s.scan(6, {{600.0, 700.0}});
  s.scan(7, {{700.0, 400.0}});
  ASSERT_EQ(s.events(TrackEventType::kInitiated),
            (std::vector<std::string>{"2: from plots 501 601 701"}));
  ASSERT_EQ(s.reported(), (std::vector<std::int64_t>{2}));
  ASSERT_EQ(s.frame.tracks[0].status, TrackStatus::kTentative);
  // WHEN track 2 is confirmed on a plot 100 m off the father's prediction, inside its
  // manoeuvre gate
  s.scan(8, {{800.0, 100.0}});
  // THEN it is the father's son, confirmed, and replaces it under number 1 (§3.3, rule 10):
  // number 2 is never reported as a firm track
  EXPECT_EQ(s.events(TrackEventType::kBranchPromoted),
            (std::vector<std::string>{"1: son 2 of track 1 replaces track 1: track 2 confirmed "
                                      "in its manoeuvre gate (§3.3)"}));
  EXPECT_TRUE(s.events(TrackEventType::kConfirmed).empty());
  ASSERT_EQ(s.reported(), (std::vector<std::int64_t>{1}));
  EXPECT_EQ(s.frame.tracks[0].status, TrackStatus::kConfirmed);
  EXPECT_NEAR(s.track(1)->position.y(), 100.0, 30.0);
  EXPECT_NEAR(s.track(1)->velocity.y(), -300.0, 30.0);
  // AND it goes on as track 1
  s.scan(9, {{900.0, -200.0}});
  EXPECT_EQ(s.reported(), (std::vector<std::int64_t>{1}));
  EXPECT_TRUE(s.associated(1, 901));
}

TEST(BranchTracker, TwoNewTracksConfirmedInOneSuspendedFathersGateNearestTakesItsNumber) {
  // GIVEN track 1 suspended by a miss at t = 4, and two plot chains closing on its line
  // from either side, outside its manoeuvre gate until t = 7: tentative tracks 2 and 3 (in
  // the order of their last plots: same time and x, south first)
  Script s(suspending_profile());
  s.suspend_father();
  s.scan(5, {{500.0, 1000.0}, {500.0, -1000.0}});
  s.scan(6, {{600.0, 700.0}, {600.0, -700.0}});
  s.scan(7, {{700.0, 400.0}, {700.0, -400.0}});
  ASSERT_EQ(s.events(TrackEventType::kInitiated),
            (std::vector<std::string>{"2: from plots 502 602 702", "3: from plots 501 601 701"}));
  // WHEN both are confirmed in the same scan inside the father's manoeuvre gate, track 2's
  // plot nearer the father's prediction (800, 0)
  s.scan(8, {{800.0, 120.0}, {800.0, -60.0}});
  // THEN only track 2 replaces the father, under number 1; track 3 is confirmed as itself,
  // numbered 2 (the next number)
  EXPECT_EQ(s.events(TrackEventType::kBranchPromoted),
            (std::vector<std::string>{"1: son 2 of track 1 replaces track 1: track 2 confirmed "
                                      "in its manoeuvre gate (§3.3)"}));
  EXPECT_EQ(s.events(TrackEventType::kConfirmed), (std::vector<std::string>{"2: tentative 3"}));
  std::vector<std::int64_t> reported = s.reported();
  std::sort(reported.begin(), reported.end());
  ASSERT_EQ(reported, (std::vector<std::int64_t>{1, 2}));
  EXPECT_NEAR(s.track(1)->position.y(), -60.0, 30.0);
  EXPECT_NEAR(s.track(2)->position.y(), 120.0, 30.0);
  // AND both go on under their numbers
  s.scan(9, {{900.0, 280.0}, {900.0, -180.0}});
  EXPECT_TRUE(s.associated(1, 901));
  EXPECT_TRUE(s.associated(2, 902));
  EXPECT_TRUE(s.events(TrackEventType::kBranchPromoted).empty());
}

}  // namespace
}  // namespace skytrack
