// Branch tracking in clutter areas: coast sons, and sons confirmed against clutter and father.
#include <algorithm>
#include <cmath>
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

TEST(BranchTracker, SonConfirmedOnExistenceWeighsItsPlotsAgainstTheClutter) {
  // GIVEN son 2 of track 1 (FatherManoeuvrePairStartsAHiddenSonFromTheFathersLastPlot) and
  // its next plot in its non-manoeuvre gate, with branching.confirmation existence, in
  // sparse clutter and in a clutter area of 10 false plots per km^2
  for (const double clutter : {1e-8, 1e-5}) {
    SCOPED_TRACE(clutter);
    config::TrackingProfile profile = branch_profile();
    profile.point.track_life.confirmation = config::ConfirmationMethod::kMOfN;  // the father's
    profile.point.branching.confirmation = config::ConfirmationMethod::kExistence;
    profile.association.clutter_density = clutter;
    Script s(profile);
    s.start();
    s.scan(4, {{400.0, 150.0}});
    ASSERT_EQ(s.events(TrackEventType::kBranchCreated).size(), 1u);
    s.scan(5, {{500.0, 300.0}});
    if (clutter < 1e-6) {
      // THEN in sparse clutter one plot where it predicts confirms it, as M-of-N would
      EXPECT_EQ(s.events(TrackEventType::kBranchPromoted).size(), 1u);
      EXPECT_NEAR(s.track(1)->position.y(), 300.0, 30.0);
      continue;
    }
    // THEN in the clutter area it is not confirmed yet (M-of-N would, on this one plot)
    EXPECT_TRUE(s.events(TrackEventType::kBranchPromoted).empty());
    EXPECT_TRUE(s.associated(2, 501));
    EXPECT_EQ(s.live_branches(), 1);
    EXPECT_EQ(s.reported(), (std::vector<std::int64_t>{1}));
  }
}

// A clutter area of 100 false plots per km^2, fathers on their last motion, sons confirmed
// on existence and up to 3 coast sons per father.
config::TrackingProfile coast_son_profile() {
  config::TrackingProfile p = branch_profile();
  p.point.track_life.confirmation = config::ConfirmationMethod::kMOfN;
  p.association.clutter_density = 1e-4;
  p.point.branching.coast_on_last_motion = true;
  p.point.branching.confirmation = config::ConfirmationMethod::kExistence;
  p.point.branching.coast_sons = 3;
  return p;
}

TEST(BranchTracker, CoastSonKeepsTheLastMotionWhileFalseAlarmsPullTheFather) {
  // GIVEN confirmed track 1 flying straight east in a clutter area of 100 false plots per
  // km^2, with branching.coast_sons: its target is missed at t = 4 and 5, and at t = 6 a
  // false plot 60 m left of its line lies in its gate, widened by the misses
  const config::TrackingProfile profile = coast_son_profile();
  Script s(profile);
  s.split_coast_son();
  // THEN the father takes it (rule 5), and as the plot may be a false alarm (its clutter
  // density is close to its density under the track) its last motion stays as coast son 2
  ASSERT_TRUE(s.associated(1, 601));
  const std::vector<std::string> created = s.events(TrackEventType::kBranchCreated);
  ASSERT_EQ(created.size(), 1u);
  EXPECT_EQ(created[0].rfind("1: son 2 of track 1: its last motion before plot 601 (coast son", 0),
            0u);
  // WHEN the target returns on its straight line, with a false plot further left each time
  std::vector<std::string> promoted;
  for (const int t : {7, 8}) {
    s.scan(t, {{100.0 * t, 0.0}, {100.0 * t, 60.0 + 15.0 * (t - 6)}});
    if (t == 7) {  // THEN the father weighs the false plot too, the coast son the target's
      EXPECT_TRUE(s.associated(1, 702));
      EXPECT_TRUE(s.associated(2, 701));
    }
    const std::vector<std::string> now = s.events(TrackEventType::kBranchPromoted);
    promoted.insert(promoted.end(), now.begin(), now.end());
  }
  // THEN the coast son, better supported than the father since the split, replaces it
  // under number 1 (rule 10), back on the target
  ASSERT_EQ(promoted.size(), 1u);
  EXPECT_EQ(promoted[0].rfind("1: son 2 of track 1 replaces track 1", 0), 0u);
  ASSERT_NE(s.track(1), nullptr);
  EXPECT_NEAR(s.track(1)->position.x(), 800.0, 20.0);
  EXPECT_NEAR(s.track(1)->position.y(), 0.0, 20.0);
}

TEST(BranchTracker, CoastSonReplacesTheFatherOnceItsSupportSinceTheSplitIsHigher) {
  // GIVEN coast son 2 of CoastSonKeepsTheLastMotionWhileFalseAlarmsPullTheFather (t = 6):
  // the father's support has the false plot of t = 6, the son's a miss instead
  const config::TrackingProfile profile = coast_son_profile();
  Script s(profile);
  s.split_coast_son();
  ASSERT_EQ(s.events(TrackEventType::kBranchCreated).size(), 1u);
  const double father = s.support(1), son = s.support(2);
  EXPECT_LT(son, father);
  // WHEN at t = 7 the target's plot returns on the straight line and a false plot lies
  // further left, on the father's pulled track
  s.scan(7, {{700.0, 0.0}, {700.0, 75.0}});
  // THEN the son takes the target's plot and, its support now above the father's (the
  // father, undecided between the two plots, takes neither), replaces it in this very look:
  // one plot decides, not the several an existence threshold would need after two misses
  EXPECT_TRUE(s.associated(2, 701));
  EXPECT_EQ(s.events(TrackEventType::kBranchPromoted),
            (std::vector<std::string>{
                "1: son 2 of track 1 replaces track 1: confirmed with plot 701 (rule 10)"}));
  EXPECT_GT(s.support(1), father);
  EXPECT_NEAR(s.track(1)->position.y(), 0.0, 20.0);
}

TEST(BranchTracker, DetectabilityChainCountsMaskedMissesOnlyInAClutterArea) {
  // GIVEN coast son 2 of CoastSonKeepsTheLastMotionWhileFalseAlarmsPullTheFather (split at
  // t = 6), the clutter area told by branching.last_motion_false_plots, and
  // branching.detectability on (hide 0.05, reveal 0.3) or off
  struct Run {
    double detectable = 0.0;  // the son's, after the split
    double miss = 0.0;        // what its next miss adds to its support
    double father = 0.0;
    std::vector<std::string> events;
  };
  const auto run = [](double false_plots, double hide) {
    config::TrackingProfile profile = coast_son_profile();
    profile.point.branching.last_motion_false_plots = false_plots;
    profile.point.branching.detectability.hide = hide;
    Script s(profile);
    s.split_coast_son();
    Run r;
    for (const PointTrack& t : s.tracker.tracks()) {
      if (shown(t.id) == 2) r.detectable = t.life.detectable;
    }
    const double before = s.support(2);
    // WHEN at t = 7 the father takes another false plot, left of its line, and the son misses
    s.scan(7, {{700.0, 90.0}});
    EXPECT_TRUE(s.associated(1, 701));
    EXPECT_FALSE(s.associated(2, 701));
    r.miss = s.support(2) - before;
    r.father = s.support(1);
    r.events = s.events(TrackEventType::kBranchCreated);
    return r;
  };
  const double miss = std::log(1.0 - 0.9 * 0.999);  // P_D 0.9, P_G 0.999
  // THEN in a clutter area (the last motion's gate expects 0.3 false plots or more) the
  // son's miss at the split made "hidden" likelier, and its next miss costs less
  const Run plain = run(0.3, 0.0), masked = run(0.3, 0.05);
  EXPECT_DOUBLE_EQ(plain.detectable, 1.0);
  EXPECT_NEAR(plain.miss, miss, 1e-9);
  EXPECT_LT(masked.detectable, 0.7);
  const double predicted = 0.95 * masked.detectable + 0.3 * (1.0 - masked.detectable);
  EXPECT_NEAR(masked.miss, std::log(1.0 - 0.9 * predicted * 0.999), 1e-9);
  EXPECT_GT(masked.miss, miss + 0.8);
  // AND where no gate expects that many (clear sky), the chain changes nothing
  const Run clear = run(1e9, 0.0), clear_masked = run(1e9, 0.05);
  EXPECT_NEAR(clear_masked.miss, miss, 1e-9);
  EXPECT_DOUBLE_EQ(clear_masked.father, clear.father);
  EXPECT_EQ(clear_masked.events, clear.events);
}

TEST(BranchTracker, ConfirmedSonWaitsUntilItsSupportPassesItsFathers) {
  // GIVEN son 2 of track 1 (FatherManoeuvrePairStartsAHiddenSonFromTheFathersLastPlot) in
  // a clutter density of 15 false plots per km^2, and M-of-N confirmation
  config::TrackingProfile profile = branch_profile();
  profile.association.clutter_density = 1.5e-5;
  profile.point.track_life.confirmation = config::ConfirmationMethod::kMOfN;
  Script s(profile);
  s.start();
  s.scan(4, {{400.0, 150.0}});
  ASSERT_EQ(s.events(TrackEventType::kBranchCreated),
            (std::vector<std::string>{"1: son 2 of track 1 from plot 401"}));
  // WHEN its next plot lies in its gate but 150 m off where the turn it started points
  s.scan(5, {{500.0, 450.0}});
  // THEN it takes the plot and is confirmed (its third plot), but a plot that likely as
  // clutter (plus the prior of a manoeuvre, 0.1) does not beat its father's miss: it stays
  // hidden and the father keeps the number
  EXPECT_TRUE(s.associated(2, 501));
  const auto& tracks = s.tracker.tracks();
  const auto son = std::find_if(tracks.begin(), tracks.end(),
                                [](const PointTrack& t) { return shown(t.id) == 2; });
  ASSERT_NE(son, tracks.end());
  EXPECT_EQ(son->life.status, TrackStatus::kConfirmed);
  EXPECT_LT(s.support(2), s.support(1));
  EXPECT_TRUE(s.events(TrackEventType::kBranchPromoted).empty());
  EXPECT_EQ(s.live_branches(), 1);
  // WHEN its next plot lies where it predicts
  const Gaussian g = ImmFilter::from_profile(profile, 2)->combine(son->estimate);
  const Eigen::Vector2d next(g.mean[StateLayout::position(0)] + g.mean[StateLayout::velocity(0)],
                             g.mean[StateLayout::position(1)] + g.mean[StateLayout::velocity(1)]);
  const double father = s.support(1);
  s.scan(6, {next});
  // THEN its support passes the father's (which missed again) and it replaces the father
  EXPECT_EQ(s.events(TrackEventType::kBranchPromoted).size(), 1u);
  EXPECT_GT(s.support(1), father);
  EXPECT_NEAR(s.track(1)->position.x(), next.x(), 30.0);
  EXPECT_NEAR(s.track(1)->position.y(), next.y(), 30.0);
}

TEST(BranchTracker, CoastSonNotConfirmedWithinItsWindowIsPruned) {
  // GIVEN coast son 2 of CoastSonKeepsTheLastMotionWhileFalseAlarmsPullTheFather (t = 6),
  // with branching.coast_son_looks 2 and misses that would not delete it before 10 looks
  config::TrackingProfile profile = coast_son_profile();
  profile.point.track_life.delete_confirmed_misses = 10;
  profile.point.branching.coast_son_looks = 2;
  Script s(profile);
  s.split_coast_son();
  ASSERT_EQ(s.events(TrackEventType::kBranchCreated).size(), 1u);
  // WHEN the target stays away (t = 7: the son's second look)
  s.scan(7, {});
  // THEN it lives through its window
  EXPECT_EQ(s.live_branches(), 1);
  EXPECT_TRUE(s.events(TrackEventType::kBranchPruned).empty());
  // WHEN a third look passes without a plot for it
  s.scan(8, {});
  // THEN the decision falls to the father's plots: the coast son is pruned
  EXPECT_EQ(
      s.events(TrackEventType::kBranchPruned),
      (std::vector<std::string>{"1: son 2 of track 1: not confirmed within coast_son_looks (2)"}));
  EXPECT_EQ(s.live_branches(), 0);
  EXPECT_EQ(s.reported(), (std::vector<std::int64_t>{1}));
}

}  // namespace
}  // namespace skytrack
