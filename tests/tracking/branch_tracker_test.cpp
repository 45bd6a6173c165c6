// Branch tracking in the point tracker, scan by scan: paper 003 §1 rules (5)-(10) and §2.3
// (1)-(5) on small scripted plot sequences (2-D Cartesian plots, no noise, no clutter).
//
// Every script starts the same way: a target at 100 m/s along +x gives plots at x = 0, 100,
// 200, 300 m (t = 0..3 s), so track 1 is initiated at t = 2 and confirmed at t = 3. The
// non-manoeuvre gate (CV, 1 m/s^2, P_G 0.999) is a few tens of metres wide; the manoeuvre
// gate (CV, 100 m/s^2, P_G 0.9999) about 250 m, so a plot 150 m off the prediction lies
// in the manoeuvre gate only.
#include <algorithm>
#include <cctype>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "skytrack/tracking/point_tracker.hpp"

namespace skytrack {
namespace {

config::TrackingProfile branch_profile() {
  config::TrackingProfile p;
  p.identity = {"branch-test", "1", ""};
  p.dimension = 2;
  p.motion_models = {
      {.name = "cv", .type = config::MotionModelType::kConstantVelocity, .accel_sigma = 1.0}};
  p.mode_transition = {{1.0}};
  p.initial_mode_probabilities = {1.0};
  p.association.clutter_density = 1e-8;  // [1/m^2]
  p.point.branching.manoeuvre_models = {"cv"};
  p.point.branching.manoeuvre_accel_sigma = 100.0;
  // Paper 003's rules alone: the default's clutter-area options off (tests of each turn
  // them on).
  p.point.branching.coast_on_last_motion = false;
  p.point.branching.non_manoeuvre_gate = config::NonManoeuvreGate::kUnion;
  p.point.branching.last_motion_false_plots = 0.0;
  p.point.branching.last_motion_accel_sigma = 0.0;
  p.point.branching.confirmation = config::ConfirmationMethod::kMOfN;
  p.point.branching.coast_sons = 0;
  p.point.branching.coast_son_looks = 0;
  p.point.branching.detectability.hide = 0.0;  // independent misses
  return p;
}

/// branch_profile() with a position-spread limit (12 m) that one missed scan exceeds.
config::TrackingProfile suspending_profile() {
  config::TrackingProfile p = branch_profile();
  p.point.track_life.delete_position_sigma = 12.0;
  return p;
}

/// The tests name branches and tentative tracks by the order they were made in (1, 2, ...),
/// as the tracker's provisional numbers (kProvisionalNumber, + 1, ...) are: a provisional
/// number n reads as n - kProvisionalNumber + 1. Confirmed tracks keep their numbers.
std::int64_t shown(std::int64_t number) {
  return number >= kProvisionalNumber ? number - kProvisionalNumber + 1 : number;
}

/// The provisional number shown as n.
std::int64_t provisional(std::int64_t n) {
  return kProvisionalNumber + n - 1;
}

/// `text` with every provisional number in it shown as above.
std::string shown(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    if (!std::isdigit(static_cast<unsigned char>(text[i]))) {
      out += text[i++];
      continue;
    }
    std::size_t j = i;
    while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j]))) ++j;
    const std::string digits = text.substr(i, j - i);
    out += digits.size() >= 13 ? std::to_string(shown(std::stoll(digits))) : digits;
    i = j;
  }
  return out;
}

struct Script {
  explicit Script(const config::TrackingProfile& profile)
      : pre(profile, 2), tracker(*PointTracker::create(profile, 2)) {}

  /// One scan at time t with plots (x, y); plot ids are 100 t + 1, 100 t + 2, ...
  const TrackFrame& scan(double t, std::vector<Eigen::Vector2d> points) {
    PlotScan s;
    s.sensor = 1;
    s.scan = static_cast<std::uint64_t>(t);
    s.time = t;
    s.sigma.x = 10.0;
    s.sigma.y = 10.0;
    for (std::size_t k = 0; k < points.size(); ++k) {
      Plot plot;
      plot.id = static_cast<std::int64_t>(100 * t) + static_cast<std::int64_t>(k) + 1;
      plot.form = PlotForm::kCartesian;
      plot.x = points[k].x();
      plot.y = points[k].y();
      s.plots.push_back(plot);
    }
    report = ScanReport{};
    pre.prepare(s, nullptr, report);
    tracker.process(s, pre, frame, report);
    return frame;
  }

  /// Track 1, confirmed at t = 3 (x = 300, y = 0, 100 m/s east).
  void start() {
    for (int t = 0; t <= 3; ++t) scan(t, {{100.0 * t, 0.0}});
    ASSERT_EQ(reported(), (std::vector<std::int64_t>{1}));
    ASSERT_EQ(frame.tracks[0].status, TrackStatus::kConfirmed);
  }

  std::vector<std::int64_t> reported() const {
    std::vector<std::int64_t> ids;
    for (const TrackReport& t : frame.tracks) ids.push_back(shown(t.id));
    return ids;
  }
  const TrackReport* track(std::int64_t id) const {
    for (const TrackReport& t : frame.tracks) {
      if (shown(t.id) == id) return &t;
    }
    return nullptr;
  }
  /// Events of one type, as "track: detail".
  std::vector<std::string> events(TrackEventType type) const {
    std::vector<std::string> out;
    for (const TrackEvent& e : frame.events) {
      if (e.type == type) out.push_back(std::to_string(shown(e.track)) + ": " + shown(e.detail));
    }
    return out;
  }
  bool associated(std::int64_t track, std::int64_t plot) const {
    return std::any_of(
        frame.associations.begin(), frame.associations.end(),
        [&](const Association& a) { return shown(a.track) == track && a.plot == plot; });
  }
  /// The probability of the association (track, plot) in the latest frame (0 if none).
  double probability(std::int64_t track, std::int64_t plot) const {
    for (const Association& a : frame.associations) {
      if (shown(a.track) == track && a.plot == plot) return a.probability;
    }
    return 0.0;
  }
  /// Track 1 (start()) misses at t = 4 and is suspended (with suspending_profile()).
  void suspend_father() {
    start();
    scan(4, {});
  }
  /// Track 1 (start()) in a clutter area misses at t = 4 and 5, and at t = 6 takes a false
  /// plot 60 m left of its line, which splits coast son 2 (with coast_son_profile()).
  void split_coast_son() {
    start();
    scan(4, {});
    scan(5, {});
    scan(6, {{600.0, 60.0}});
  }

  /// The own estimate's position (its IMM's combined mean) of father `id`, which the report
  /// replaces by a branch's while the father took no plot and the branch did (NaN if none).
  Eigen::Vector2d father_position(std::int64_t id) const {
    for (const PointTrack& t : tracker.tracks()) {
      if (t.branch != BranchType::kFather || shown(t.id) != id || t.replaced) continue;
      Eigen::Vector2d p = Eigen::Vector2d::Zero();
      for (std::size_t m = 0; m < t.estimate.modes.size(); ++m) {
        for (int a = 0; a < 2; ++a) {
          p[a] += t.estimate.probabilities[static_cast<Eigen::Index>(m)] *
                  t.estimate.modes[m].mean[StateLayout::position(a)];
        }
      }
      return p;
    }
    return Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());
  }
  /// TrackLife::support of the live track or branch numbered `id` (NaN if none).
  double support(std::int64_t id) const {
    for (const PointTrack& t : tracker.tracks()) {
      if (shown(t.id) == id && t.life.status != TrackStatus::kDeleted) return t.life.support;
    }
    return std::numeric_limits<double>::quiet_NaN();
  }
  /// TrackLife::existence of the live track or branch numbered `id` (NaN if none).
  double existence(std::int64_t id) const {
    for (const PointTrack& t : tracker.tracks()) {
      if (shown(t.id) == id && t.life.status != TrackStatus::kDeleted) return t.life.existence;
    }
    return std::numeric_limits<double>::quiet_NaN();
  }
  int live_branches() const {
    return static_cast<int>(
        std::count_if(tracker.tracks().begin(), tracker.tracks().end(), [](const PointTrack& t) {
          return t.branch != BranchType::kFather && t.life.status != TrackStatus::kDeleted;
        }));
  }

  Preprocessing pre;
  PointTracker tracker;
  TrackFrame frame;
  ScanReport report;
};

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
