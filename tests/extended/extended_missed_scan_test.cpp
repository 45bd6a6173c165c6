// A scan's plots weighed again once the next scan shows where the object is
// (ExtendedTracker::reconsider_missed_scans): a track whose object was unseen takes a clutter
// cluster beside its prediction, and when the object's plots return where the track would
// stand had that scan been a miss, the track returns to them under its number.
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "skytrack/extended/extended_tracker.hpp"

namespace skytrack::extended {
namespace {

constexpr double kScan = 10.0;  // [s]
constexpr double kR = 25.0;     // [m^2] plot noise variance per axis

// The shipped extended profile's model (config/profiles/extended.yaml).
ExtendedSpec profile_spec(EstimatorKind kind) {
  ExtendedSpec spec;
  spec.kind = kind;
  spec.motion.manoeuvre_accel = 2.0;
  spec.existence.expected_plots = 5.0;
  return spec;
}

// An object northbound at 15 m/s, 25 m x 100 m along its course (the crossing scenario's
// B), 8 plots a scan uniform over it plus N(0, 25 m^2).
Eigen::Vector2d centre_at(double t) {
  return {0.0, -2000.0 + 15.0 * t};
}

std::vector<Eigen::Vector2d> object_plots(double t, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 5.0);
  std::vector<Eigen::Vector2d> plots;
  for (int i = 0; i < 8; ++i) {
    const double r = std::sqrt(u(rng)), phi = 2.0 * std::numbers::pi * u(rng);
    // Each draw is its own step, last argument first: the order GCC used when the scenes were
    // measured (C++ leaves the evaluation order of arguments unspecified).
    const double noise_y = noise(rng), noise_x = noise(rng);
    plots.push_back(centre_at(t) + Eigen::Vector2d(25.0 * r * std::cos(phi) + noise_x,
                                                   100.0 * r * std::sin(phi) + noise_y));
  }
  return plots;
}

void scan(ExtendedTracker& tracker, double t, const std::vector<Eigen::Vector2d>& plots) {
  const std::vector<Eigen::Matrix2d> noises(plots.size(), kR * Eigen::Matrix2d::Identity());
  tracker.process(t, plots, noises);
}

const ExtendedTrack* track_numbered(const ExtendedTracker& tracker, std::uint64_t id) {
  for (const ExtendedTrack& track : tracker.tracks()) {
    if (track.id == id) return &track;
  }
  return nullptr;
}

class ExtendedMissedScan : public ::testing::TestWithParam<EstimatorKind> {};

TEST_P(ExtendedMissedScan, TrackReturnsToItsObjectAfterTakingAClutterCluster) {
  // GIVEN a confirmed track on the object for 20 scans, then a scan that misses it
  ExtendedTracker tracker(profile_spec(GetParam()));
  std::mt19937_64 rng(6);
  for (int k = 0; k < 20; ++k) scan(tracker, kScan * k, object_plots(kScan * k, rng));
  ASSERT_EQ(tracker.tracks().size(), 1u);
  const std::uint64_t id = tracker.tracks().front().id;
  scan(tracker, kScan * 20, {});
  // WHEN the object is unseen again and three clutter plots lie 250 m east of it, inside the
  // coasting track's widened gate; the track takes them and turns east
  const double t_cluster = kScan * 21;
  const Eigen::Vector2d cluster = centre_at(t_cluster) + Eigen::Vector2d(250.0, 0.0);
  scan(tracker, t_cluster,
       {cluster, cluster + Eigen::Vector2d(15.0, 10.0), cluster + Eigen::Vector2d(-10.0, 15.0)});
  const ExtendedTrack* taken = track_numbered(tracker, id);
  ASSERT_NE(taken, nullptr);
  ASSERT_EQ(taken->plots, 3) << "the cluster should pass the clutter test";
  // AND the object's plots return where it is
  scan(tracker, kScan * 22, object_plots(kScan * 22, rng));
  // THEN the track of that number takes them, and no new track starts on them
  const ExtendedTrack* back = track_numbered(tracker, id);
  ASSERT_NE(back, nullptr) << "the object's track was deleted";
  EXPECT_EQ(back->plots, 8);
  EXPECT_EQ(tracker.tracks().size(), 1u);
  // AND two scans on it follows the object, at its speed and course
  for (int k = 23; k < 25; ++k) scan(tracker, kScan * k, object_plots(kScan * k, rng));
  const ExtendedTrack* kept = track_numbered(tracker, id);
  ASSERT_NE(kept, nullptr);
  EXPECT_LT((kept->position() - centre_at(kScan * 24)).norm(), 60.0);
  EXPECT_LT((kept->velocity() - Eigen::Vector2d(0.0, 15.0)).norm(), 6.0);
}

INSTANTIATE_TEST_SUITE_P(AllEstimators, ExtendedMissedScan,
                         ::testing::Values(EstimatorKind::kSmf, EstimatorKind::kRandomMatrix,
                                           EstimatorKind::kMemEkf));

}  // namespace
}  // namespace skytrack::extended
