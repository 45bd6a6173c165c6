// Branch tracking with fathers held on their last motion: coasting, gating and updating on it.
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

/// branch_profile() with a left-turn mode (0.5 rad/s) beside CV in the IMM.
config::TrackingProfile turning_profile(bool coast_on_last_motion) {
  config::TrackingProfile p = branch_profile();
  p.motion_models.push_back({.name = "ct_left",
                             .type = config::MotionModelType::kCoordinatedTurn,
                             .accel_sigma = 1.0,
                             .turn_rate = 0.5});
  p.mode_transition = {{0.9, 0.1}, {0.1, 0.9}};
  p.initial_mode_probabilities = {0.9, 0.1};
  p.point.branching.coast_on_last_motion = coast_on_last_motion;
  return p;
}

TEST(BranchTracker, FatherThatMissedTakesPlotsOnlyOnItsLastMotion) {
  // GIVEN confirmed track 1 flying straight east, which misses its plot at t = 4, and at
  // t = 5 a plot 30 m short of and 90 m left of its straight line: where a left turn from
  // its last plot would be (200 m radius, 1 rad in 2 s: 468, 92), in its turn mode's gate,
  // about 95 m outside its CV prediction (a CV gate of a few tens of metres)
  for (const bool on : {true, false}) {
    SCOPED_TRACE(on ? "coast_on_last_motion" : "union of the modes' gates");
    Script s(turning_profile(on));
    s.start();
    s.scan(4, {});
    s.scan(5, {{470.0, 90.0}});
    if (!on) {  // THEN without the rule the father takes it and is pulled off its line
      EXPECT_TRUE(s.associated(1, 501));
      EXPECT_TRUE(s.events(TrackEventType::kBranchCreated).empty());
      EXPECT_GT(s.track(1)->position.y(), 20.0);
      continue;
    }
    // THEN with it the father coasts on, and the plot, in its manoeuvre gate, starts son 2
    EXPECT_FALSE(s.associated(1, 501));
    EXPECT_EQ(s.events(TrackEventType::kBranchCreated),
              (std::vector<std::string>{"1: son 2 of track 1 from plot 501"}));
    EXPECT_EQ(s.track(1)->status, TrackStatus::kCoasting);
    EXPECT_NEAR(s.father_position(1).y(), 0.0, 20.0);
    // AND number 1 is reported at its son's estimate, the son's plot being likelier the
    // target's than the turn's prior (its IMM's turn mode share) is unlikely, with a
    // covariance (y variance) that reaches the father's own line
    EXPECT_NEAR(s.track(1)->position.y(), 90.0, 20.0);
    EXPECT_GT(s.track(1)->covariance[2 * 4 + 2], 80.0 * 80.0);
    // WHEN the target's plot returns on the straight line (the other was a false alarm)
    s.scan(6, {{600.0, 0.0}});
    // THEN the father takes it and its son is pruned (rule 5): number 1 holds the target
    EXPECT_TRUE(s.associated(1, 601));
    EXPECT_EQ(s.events(TrackEventType::kBranchPruned),
              (std::vector<std::string>{"1: son 2 of track 1: track 1 took plot 601 (rule 5)"}));
    EXPECT_EQ(s.reported(), (std::vector<std::int64_t>{1}));
    EXPECT_EQ(s.track(1)->status, TrackStatus::kConfirmed);
    EXPECT_NEAR(s.track(1)->position.y(), 0.0, 20.0);
  }
}

/// turning_profile(true) with M-of-N confirmation, last_motion_false_plots 0.3 and a
/// uniform clutter density [1/m^2].
config::TrackingProfile last_motion_where_clutter(double clutter) {
  config::TrackingProfile p = turning_profile(true);
  p.point.track_life.confirmation = config::ConfirmationMethod::kMOfN;
  p.association.clutter_density = clutter;
  p.point.branching.last_motion_false_plots = 0.3;
  return p;
}

TEST(BranchTracker, LastMotionOnlyWhereItsGateExpectsFalsePlots) {
  // GIVEN FatherThatMissedTakesPlotsOnlyOnItsLastMotion's script with coast_on_last_motion
  // and last_motion_false_plots 0.3, in clear sky (1 false plot per 100 km^2) and in a
  // clutter area (100 per km^2, about 1 in the last motion's gate)
  for (const double clutter : {1e-8, 1e-4}) {
    SCOPED_TRACE(clutter);
    Script s(last_motion_where_clutter(clutter));
    s.start();
    s.scan(4, {});
    s.scan(5, {{470.0, 90.0}});
    if (clutter < 1e-6) {
      // THEN in clear sky the father gates on its modes' union as without the option, and
      // takes the turn's plot
      EXPECT_TRUE(s.associated(1, 501));
      EXPECT_GT(s.track(1)->position.y(), 20.0);
      continue;
    }
    // THEN in the clutter area its last motion's gate leaves the plot out: it coasts on
    EXPECT_FALSE(s.associated(1, 501));
    EXPECT_NEAR(s.father_position(1).y(), 0.0, 20.0);
  }
}

TEST(BranchTracker, FatherInAClutterAreaIsUpdatedOnItsLastMotion) {
  // GIVEN confirmed track 1 flying straight east at 100 m/s with a left-turn mode, gating on
  // its last motion (non_manoeuvre_gate last_motion, last_motion_false_plots 0.3), and at
  // t = 4 a plot 35 m left of its straight line, 11 m from where its turn mode predicts
  // (396, 24): inside its last motion's gate too
  for (const double clutter : {1e-8, 1e-4}) {
    SCOPED_TRACE(clutter);
    config::TrackingProfile profile = last_motion_where_clutter(clutter);
    profile.point.branching.non_manoeuvre_gate = config::NonManoeuvreGate::kLastMotion;
    Script s(profile);
    s.start();
    s.scan(4, {{396.0, 35.0}});
    ASSERT_GT(s.probability(1, 401), 0.8);
    if (clutter < 1e-6) {
      // THEN in clear sky its IMM update follows the turn mode: the velocity swings north
      // (about 16 m/s)
      EXPECT_GT(s.track(1)->velocity.y(), 12.0);
      continue;
    }
    // THEN in the clutter area the plot is taken as the motion unchanged (§2.1): it moves
    // the father without turning it as much (about 6 m/s; 13 with the IMM update)
    EXPECT_LT(s.track(1)->velocity.y(), 9.0);
    EXPECT_GT(s.track(1)->position.y(), 10.0);
  }
}

TEST(BranchTracker, FatherMissedInAClutterAreaKeepsItsExistenceOnTheDetectabilityChain) {
  // GIVEN confirmed track 1 holding its last motion, confirmed and deleted on its IPDA
  // existence, whose target is missed 4 scans in a row (t = 4..7)
  for (const double hide : {0.0, 0.05}) {
    SCOPED_TRACE(hide);
    config::TrackingProfile profile = branch_profile();
    profile.association.clutter_density = 1e-6;
    profile.point.track_life.confirmation = config::ConfirmationMethod::kExistence;
    profile.point.track_life.delete_confirmed_misses = 6;
    profile.point.branching.coast_on_last_motion = true;
    profile.point.branching.detectability = {.hide = hide, .reveal = 0.3};
    Script s(profile);
    s.start();
    for (int t = 4; t <= 7; ++t) s.scan(t, {});
    if (hide == 0.0) {
      // THEN with independent misses (P_D 0.9 each scan) its existence falls below
      // delete_existence (0.02) on the fourth: the track is gone
      EXPECT_TRUE(s.reported().empty());
      continue;
    }
    // THEN on the chain (a target can be masked for scans in a clutter area) the misses say
    // less each time: it coasts on under number 1 and takes its target's returning plot
    EXPECT_GT(s.existence(1), 0.2);
    ASSERT_EQ(s.reported(), (std::vector<std::int64_t>{1}));
    s.scan(8, {{800.0, 0.0}});
    EXPECT_TRUE(s.associated(1, 801));
    EXPECT_EQ(s.track(1)->status, TrackStatus::kConfirmed);
  }
}

TEST(BranchTracker, MissingFatherCoastsOnItsLastMotionWhileItsSonFollowsTheTurn) {
  // GIVEN confirmed track 1 flying straight east at 100 m/s, whose target turns left at
  // 0.5 rad/s from x = 300 m (t = 3) and is missed at t = 4; a manoeuvre gate of 10 m/s^2
  // (about 80 m wide after 2 s) from a straight coast would not reach the turn's plots
  for (const bool on : {true, false}) {
    SCOPED_TRACE(on ? "coast_on_last_motion" : "IMM-JPDA coast");
    config::TrackingProfile profile = turning_profile(on);
    profile.point.branching.manoeuvre_accel_sigma = 10.0;
    Script s(profile);
    s.start();
    s.scan(4, {});
    // THEN the missing father is reported on its straight line only with the rule (without
    // it, its IMM blends in the turn mode's prediction)
    if (on) {
      EXPECT_NEAR(s.track(1)->position.x(), 400.0, 0.5);
      EXPECT_NEAR(s.track(1)->position.y(), 0.0, 0.3);
    } else {
      EXPECT_GT(s.track(1)->position.y(), 0.8);
    }
    // WHEN the turn's plots come at t = 5, 6 (200 m radius about (300, 200))
    s.scan(5, {{468.3, 91.9}});
    s.scan(6, {{499.5, 185.9}});
    // THEN number 1 follows the target: with the rule, a son from the plot of t = 5 (its
    // manoeuvre gate starts from the IMM's own coast, whose turn mode reaches the turn)
    // takes the plot of t = 6, confirms and replaces the father (rule 10)
    EXPECT_EQ(s.reported(), (std::vector<std::int64_t>{1}));
    EXPECT_NEAR(s.track(1)->position.x(), 499.5, 30.0);
    EXPECT_NEAR(s.track(1)->position.y(), 185.9, 30.0);
    if (on) {
      EXPECT_EQ(s.events(TrackEventType::kBranchPromoted).size(), 1u);
      EXPECT_TRUE(s.associated(2, 601));
    }
  }
}

TEST(BranchTracker, LastMotionGateLeavesATurnModesPlotToASon) {
  // GIVEN confirmed track 1 flying straight east, and at t = 4 (not after a miss) a plot
  // 60 m left of its straight line, 37 m from where its left-turn mode predicts (396, 25):
  // outside its CV gate, inside the turn mode's
  for (const bool last_motion : {true, false}) {
    SCOPED_TRACE(last_motion ? "non_manoeuvre_gate last_motion" : "union");
    config::TrackingProfile profile = turning_profile(true);
    if (last_motion)
      profile.point.branching.non_manoeuvre_gate = config::NonManoeuvreGate::kLastMotion;
    Script s(profile);
    s.start();
    s.scan(4, {{385.0, 60.0}});
    if (!last_motion) {  // THEN the union gate lets the father take it
      EXPECT_TRUE(s.associated(1, 401));
      EXPECT_TRUE(s.events(TrackEventType::kBranchCreated).empty());
      continue;
    }
    // THEN the last motion's gate does not: the plot starts son 2, the father coasts on
    EXPECT_FALSE(s.associated(1, 401));
    EXPECT_EQ(s.events(TrackEventType::kBranchCreated),
              (std::vector<std::string>{"1: son 2 of track 1 from plot 401"}));
    EXPECT_NEAR(s.father_position(1).y(), 0.0, 1.0);
  }
}

TEST(BranchTracker, FatherOnItsLastMotionWeighsItsPlotsOnIt) {
  // GIVEN confirmed track 1 flying straight east with a noisy IMM (50 m/s^2) and a quiet last
  // motion (0.5 m/s^2), and at t = 4 two plots in both its gates: one on its straight line,
  // one 80 m off it
  double off_line[2] = {};
  for (const bool last_motion : {true, false}) {
    SCOPED_TRACE(last_motion ? "non_manoeuvre_gate last_motion" : "union");
    config::TrackingProfile profile = branch_profile();
    profile.motion_models[0].accel_sigma = 50.0;
    profile.point.branching.coast_on_last_motion = true;
    profile.point.branching.last_motion_accel_sigma = 0.5;
    if (last_motion)
      profile.point.branching.non_manoeuvre_gate = config::NonManoeuvreGate::kLastMotion;
    Script s(profile);
    s.start();
    s.scan(4, {{400.0, 0.0}, {400.0, 80.0}});
    ASSERT_TRUE(s.associated(1, 401));
    ASSERT_TRUE(s.associated(1, 402));
    off_line[last_motion ? 0 : 1] = s.probability(1, 402);
  }
  // THEN gated on its last motion it also weighs them on it: the plot off the line gets
  // about half the weight the IMM's wider prediction gives it (0.10 against 0.20)
  EXPECT_LT(off_line[0], 0.12);
  EXPECT_GT(off_line[1], 0.15);
  EXPECT_LT(off_line[0], 0.6 * off_line[1]);
}

}  // namespace
}  // namespace skytrack
