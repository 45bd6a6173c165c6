#pragma once
// Scripted scans through the point tracker with branching on, for the branch tracker tests.
//
// Every script starts the same way: a target at 100 m/s along +x gives plots at x = 0, 100,
// 200, 300 m (t = 0..3 s), so track 1 is initiated at t = 2 and confirmed at t = 3. The
// non-manoeuvre gate (CV, 1 m/s^2, P_G 0.999) is a few tens of metres wide; the manoeuvre
// gate (CV, 100 m/s^2, P_G 0.9999) about 250 m, so a plot 150 m off the prediction lies
// in the manoeuvre gate only.
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "skytrack/tracking/point_tracker.hpp"

namespace skytrack::test {

inline config::TrackingProfile branch_profile() {
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

/// The tests name branches and tentative tracks by the order they were made in (1, 2, ...),
/// as the tracker's provisional numbers (kProvisionalNumber, + 1, ...) are: a provisional
/// number n reads as n - kProvisionalNumber + 1. Confirmed tracks keep their numbers.
inline std::int64_t shown(std::int64_t number) {
  return number >= kProvisionalNumber ? number - kProvisionalNumber + 1 : number;
}

/// `text` with every provisional number in it shown as above.
inline std::string shown(const std::string& text) {
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

}  // namespace skytrack::test
