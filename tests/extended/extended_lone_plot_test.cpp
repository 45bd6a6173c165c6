// Lone plots (a partition of fewer than min_partition_plots) in a track's gate: after two
// missed scans a coasting track's gate holds clutter plots hundreds of metres from its
// prediction. They update it only beside a cluster of its object's plots and within the
// object's reach of that cluster; a scan that gives a track lone plots alone is a miss.
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "skytrack/extended/extended_existence.hpp"
#include "skytrack/extended/extended_tracker.hpp"

namespace skytrack::extended {
namespace {

constexpr double kScan = 10.0;   // [s]
constexpr double kR = 25.0;      // [m^2] plot noise variance per axis
constexpr double kSpeed = 15.0;  // [m/s] east

using Plots = std::vector<Eigen::Vector2d>;

// The object's plots at time t: a 100 m x 25 m ellipse moving east, `count` scatterers
// uniform over it plus N(0, kR) noise (deterministic for a given rng state).
Plots object_plots(double t, int count, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, std::sqrt(kR));
  const Eigen::Vector2d centre(kSpeed * t, 0.0);
  Plots plots;
  for (int i = 0; i < count; ++i) {
    const double r = std::sqrt(u(rng)), phi = 2.0 * std::numbers::pi * u(rng);
    // Each draw is its own step, last argument first: the order GCC used when the scenes were
    // measured (C++ leaves the evaluation order of arguments unspecified).
    const double noise_y = noise(rng), noise_x = noise(rng);
    plots.push_back(centre + Eigen::Vector2d(100.0 * r * std::cos(phi) + noise_x,
                                             25.0 * r * std::sin(phi) + noise_y));
  }
  return plots;
}

void scan(ExtendedTracker& tracker, double t, const Plots& plots) {
  const std::vector<Eigen::Matrix2d> noises(plots.size(), kR * Eigen::Matrix2d::Identity());
  tracker.process(t, plots, noises);
}

// Ten scans of the object (t = 0..90 s), then two scans that miss it (100, 110 s).
ExtendedTracker coasting_track(EstimatorKind kind) {
  ExtendedSpec spec;
  spec.kind = kind;
  ExtendedTracker tracker(spec);
  std::mt19937_64 rng(7);
  for (int k = 0; k < 10; ++k) scan(tracker, kScan * k, object_plots(kScan * k, 8, rng));
  scan(tracker, 100.0, {});
  scan(tracker, 110.0, {});
  return tracker;
}

constexpr double kT = 120.0;  // [s] the scan under test

// The track's predicted centre and covariances at kT: a tracker given an empty scan coasts
// on its prediction (coast_constant_velocity), covariance the prediction's.
struct Prediction {
  ExtendedTrack track;
  Eigen::Matrix2d C;  // HPH'
  Eigen::Matrix2d X;  // extent, semi-axes floored at 50 m as association floors them
};

Prediction predicted(EstimatorKind kind) {
  ExtendedTracker tracker = coasting_track(kind);
  scan(tracker, kT, {});
  Prediction p{tracker.tracks().front(), {}, {}};
  const PosMat H = position_matrix();
  p.C = H * p.track.object.P * H.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(p.track.object.extent);
  p.X = eig.eigenvectors() * eig.eigenvalues().cwiseMax(2500.0).asDiagonal() *
        eig.eigenvectors().transpose();
  return p;
}

double d2(const Eigen::Vector2d& nu, const Eigen::Matrix2d& G) {
  return nu.dot(G.llt().solve(nu));
}

class ExtendedLonePlots : public ::testing::TestWithParam<EstimatorKind> {};

TEST_P(ExtendedLonePlots, LonePlotsAloneAreAMiss) {
  // GIVEN a track on its object for ten scans, then two scans that missed it; WHEN the
  // object is missed again and two clutter plots 140 m apart (two partitions of one plot)
  // lie 60 m north of its prediction, either side of it
  const Prediction p = predicted(GetParam());
  ASSERT_EQ(p.track.status, ExtendedTrackStatus::kConfirmed);
  const Eigen::Vector2d c = p.track.position();
  const Plots pair{c + Eigen::Vector2d(70.0, 60.0), c + Eigen::Vector2d(-70.0, 60.0)};
  const Eigen::Matrix2d R = kR * Eigen::Matrix2d::Identity();
  for (const Eigen::Vector2d& z : pair) ASSERT_LE(d2(z - c, p.C + p.X / 4.0 + R), 13.8);
  // the test of a scan's plots as clutter alone would take them as the object's
  ASSERT_GT(object_plots_log_ratio(pair, c, p.C, p.X / 4.0 + R, ExistenceSpec{}), 0.0);
  ExtendedTracker tracker = coasting_track(GetParam());
  scan(tracker, kT, pair);
  // THEN the scan is a miss: no plots taken, the state and existence the coast's (1e-9)
  const ExtendedTrack& after = tracker.tracks().front();
  EXPECT_EQ(after.plots, 0);
  EXPECT_LT((after.object.x - p.track.object.x).norm(), 1e-9);
  EXPECT_NEAR(after.existence_log_odds, p.track.existence_log_odds, 1e-9);
}

TEST_P(ExtendedLonePlots, LonePlotAwayFromTheClusterStaysOut) {
  // GIVEN the same coasting track; WHEN its object returns (eight plots, one partition)
  // with a clutter plot north of them, inside the track's widened gate but beyond the
  // object's reach of the cluster (d^2 > 13.8 under (1 + 1/8)(X + R) about their mean)
  const Prediction p = predicted(GetParam());
  std::mt19937_64 rng(3);
  const Plots cluster = object_plots(kT, 8, rng);
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& z : cluster) mean += z;
  mean /= 8.0;
  const Eigen::Matrix2d R = kR * Eigen::Matrix2d::Identity();
  const Eigen::Matrix2d reach = 9.0 / 8.0 * (p.X + R);
  const Eigen::Vector2d lone = mean + Eigen::Vector2d(0.0, 1.3 * std::sqrt(13.8 * reach(1, 1)));
  const Eigen::Vector2d c = p.track.position();
  ASSERT_GT(d2(lone - mean, reach), 13.8);
  ASSERT_LE(d2(lone - c, p.C + p.X + R), 4.0);         // its partition gates the track
  ASSERT_LE(d2(lone - c, p.C + p.X / 4.0 + R), 13.8);  // and it is inside the plot gate
  Plots with_lone = cluster;
  with_lone.push_back(lone);
  ExtendedTracker tracker = coasting_track(GetParam());
  ExtendedTracker reference = coasting_track(GetParam());
  scan(tracker, kT, with_lone);
  scan(reference, kT, cluster);
  // THEN the track takes the cluster alone: the same update as without the lone plot (1e-9)
  const ExtendedTrack& after = tracker.tracks().front();
  EXPECT_EQ(after.plots, 8);
  EXPECT_LT((after.object.x - reference.tracks().front().object.x).norm(), 1e-9);
  EXPECT_LT((after.extent() - reference.tracks().front().extent()).norm(), 1e-9);
  EXPECT_NEAR(after.existence_log_odds, reference.tracks().front().existence_log_odds, 1e-9);
}

TEST_P(ExtendedLonePlots, ObjectsOwnOutlyingPlotStillUpdates) {
  // GIVEN the same coasting track; WHEN its object returns as a cluster of seven plots and
  // an eighth 110 m east of their mean (its own partition, within the object's reach)
  const Prediction p = predicted(GetParam());
  std::mt19937_64 rng(3);
  Plots plots = object_plots(kT, 7, rng);
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& z : plots) mean += z;
  mean /= 7.0;
  double east = mean.x();
  for (const Eigen::Vector2d& z : plots) east = std::max(east, z.x());
  const Eigen::Vector2d outlying(std::max(east + 101.0, mean.x() + 110.0), mean.y());
  ASSERT_LE(d2(outlying - mean, 8.0 / 7.0 * (p.X + kR * Eigen::Matrix2d::Identity())), 13.8);
  plots.push_back(outlying);
  ExtendedTracker tracker = coasting_track(GetParam());
  scan(tracker, kT, plots);
  // THEN all eight update the track
  EXPECT_EQ(tracker.tracks().front().plots, 8);
}

INSTANTIATE_TEST_SUITE_P(AllEstimators, ExtendedLonePlots,
                         ::testing::Values(EstimatorKind::kSmf, EstimatorKind::kRandomMatrix,
                                           EstimatorKind::kMemEkf));

}  // namespace
}  // namespace skytrack::extended
