// ExtendedTracker at a crossing: two confirmed tracks whose plots fall in one partition keep
// their objects (the split of a shared partition, extended_tracker.hpp), and an object seen
// off its prediction is not started again as a new track.
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "skytrack/extended/ellipse_geometry.hpp"
#include "skytrack/extended/extended_tracker.hpp"

namespace skytrack::extended {
namespace {

struct Mover {
  Eigen::Vector2d start, velocity;
  double major, minor;  // [m] semi-axes, the major along the velocity
};

Eigen::Vector2d centre(const Mover& m, double t) {
  return m.start + t * m.velocity;
}

// Eight plots spread over the object's ellipse on two rings (radius 0.4 and 0.8), the
// pattern turned by 20 degrees a scan: hand-made and deterministic, no noise.
void ring_plots(const Mover& m, double t, int scan, std::vector<Eigen::Vector2d>& out) {
  const double heading = std::atan2(m.velocity.y(), m.velocity.x());
  const double c = std::cos(heading), s = std::sin(heading);
  for (int j = 0; j < 8; ++j) {
    const double r = j % 2 == 0 ? 0.4 : 0.8;
    const double phi = (45.0 * j + 20.0 * scan) * std::numbers::pi / 180.0;
    const double a = m.major * r * std::cos(phi), b = m.minor * r * std::sin(phi);
    out.push_back(centre(m, t) + Eigen::Vector2d(c * a - s * b, s * a + c * b));
  }
}

// A (east) and B (north) at 15 m/s cross at the origin at t = 100 s. A fades for the two
// scans before the crossing (80 and 90 s), so its track arrives with a centre variance
// several times B's: split from the predictions alone, the shared partition went to B's
// track plot by plot, A's track starved through the crossing and B's left with A's plots.
struct CrossingResult {
  std::uint64_t before[2] = {0, 0};  // the confirmed track on each object at 70 s
  std::uint64_t after[2] = {0, 0};   // and at 160 s
  double after_error[2] = {0.0, 0.0};
  int tracks_after = 0;
};

CrossingResult run_faded_crossing(EstimatorKind kind) {
  const Mover movers[2] = {{{-1500.0, 0.0}, {15.0, 0.0}, 100.0, 25.0},
                           {{0.0, -1500.0}, {0.0, 15.0}, 100.0, 25.0}};
  ExtendedSpec spec;
  spec.kind = kind;
  ExtendedTracker tracker(spec);
  CrossingResult result;
  std::vector<Eigen::Vector2d> plots;
  for (int k = 0; k <= 16; ++k) {
    const double t = 10.0 * k;
    plots.clear();
    if (t != 80.0 && t != 90.0) ring_plots(movers[0], t, k, plots);
    ring_plots(movers[1], t, k, plots);
    const std::vector<Eigen::Matrix2d> noises(plots.size(), Eigen::Matrix2d::Identity() * 25.0);
    EXPECT_FALSE(tracker.process(t, plots, noises).skipped);
    if (t != 70.0 && t != 160.0) continue;
    for (int o = 0; o < 2; ++o) {
      double best = 200.0;  // [m] a track farther than this is on neither object
      for (const ExtendedTrack& track : tracker.tracks()) {
        const double d = (track.position() - centre(movers[o], t)).norm();
        if (track.status != ExtendedTrackStatus::kConfirmed || d >= best) continue;
        best = d;
        (t == 70.0 ? result.before : result.after)[o] = track.id;
        if (t == 160.0) result.after_error[o] = d;
      }
    }
    if (t == 160.0) result.tracks_after = static_cast<int>(tracker.tracks().size());
  }
  return result;
}

TEST(ExtendedCrossing, FadedTrackKeepsItsObjectThroughASharedPartition) {
  for (EstimatorKind kind :
       {EstimatorKind::kSmf, EstimatorKind::kRandomMatrix, EstimatorKind::kMemEkf}) {
    SCOPED_TRACE(std::string(to_string(kind)));
    const CrossingResult r = run_faded_crossing(kind);
    ASSERT_NE(r.before[0], 0u);
    ASSERT_NE(r.before[1], 0u);
    EXPECT_NE(r.before[0], r.before[1]);
    // Six scans after the crossing each object carries the number it had before, its
    // centre within 60 m (objects 200 m long, plots without noise), and no third track.
    EXPECT_EQ(r.after[0], r.before[0]);
    EXPECT_EQ(r.after[1], r.before[1]);
    EXPECT_LT(r.after_error[0], 60.0);
    EXPECT_LT(r.after_error[1], 60.0);
    EXPECT_EQ(r.tracks_after, 2);
  }
}

// Two small objects (10 m, below the 50 m extent floor: their tracks have no shape to split
// by) cross at the origin at 100 s with coinciding centres; the tracks coast through that
// scan on their velocities and pick their own objects up again after it.
TEST(ExtendedCrossing, ShapelessTracksCoastThroughTheCrossingAndKeepTheirObjects) {
  const Mover movers[2] = {{{-1500.0, 0.0}, {15.0, 0.0}, 10.0, 5.0},
                           {{0.0, -1500.0}, {0.0, 15.0}, 10.0, 5.0}};
  for (EstimatorKind kind :
       {EstimatorKind::kSmf, EstimatorKind::kRandomMatrix, EstimatorKind::kMemEkf}) {
    SCOPED_TRACE(std::string(to_string(kind)));
    ExtendedSpec spec;
    spec.kind = kind;
    ExtendedTracker tracker(spec);
    std::vector<Eigen::Vector2d> plots;
    std::uint64_t before[2] = {0, 0}, after[2] = {0, 0};
    int coasted = 0;
    for (int k = 0; k <= 16; ++k) {  // GIVEN the two objects, 8 plots each a scan
      const double t = 10.0 * k;
      plots.clear();
      for (const Mover& m : movers) ring_plots(m, t, k, plots);
      const std::vector<Eigen::Matrix2d> noises(plots.size(), Eigen::Matrix2d::Identity() * 25.0);
      tracker.process(t, plots, noises);  // WHEN every scan is processed
      for (const ExtendedTrack& track : tracker.tracks()) {
        EXPECT_EQ(track.misses, 0);
        if (t == 100.0 && track.unresolved) ++coasted;
      }
      if (t != 70.0 && t != 160.0) continue;
      for (int o = 0; o < 2; ++o) {
        for (const ExtendedTrack& track : tracker.tracks()) {
          if (track.status == ExtendedTrackStatus::kConfirmed &&
              (track.position() - centre(movers[o], t)).norm() < 30.0) {
            (t == 70.0 ? before : after)[o] = track.id;
          }
        }
      }
    }
    // THEN both coasted through the crossing, neither counted a miss, numbers kept
    EXPECT_EQ(coasted, 2);
    ASSERT_NE(before[0], 0u);
    ASSERT_NE(before[1], 0u);
    EXPECT_EQ(after[0], before[0]);
    EXPECT_EQ(after[1], before[1]);
    EXPECT_EQ(tracker.tracks().size(), 2u);
  }
}

}  // namespace
}  // namespace skytrack::extended
