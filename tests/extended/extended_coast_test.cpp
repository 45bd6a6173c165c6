// ExtendedTracker's coast of an unseen track (ExtendedSpec::coast_constant_velocity): the
// prediction over a scan without plots is the constant-velocity one of the last state, the
// acceleration estimated before the miss is not extrapolated, the covariance is kept.
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "skytrack/extended/extended_tracker.hpp"

namespace skytrack::extended {
namespace {

constexpr double kScan = 10.0;  // [s]

struct Coast {
  ExtendedObject last_seen;             // the track after its last scan with plots
  std::vector<ExtendedObject> coasted;  // the track after each scan without
};

// A 50 m x 20 m object from the origin east at 5 m/s, accelerating at 0.3 m/s^2, 8 plots a
// scan uniform over it plus N(0, 25 m^2), seen `seen` scans then unseen `unseen` scans.
Coast run_coast(EstimatorKind kind, bool constant_velocity, int seen, int unseen) {
  ExtendedSpec spec;
  spec.kind = kind;
  spec.motion.accel_noise = 2.0;  // the profile's: the track follows the acceleration
  spec.coast_constant_velocity = constant_velocity;
  ExtendedTracker tracker(spec);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 5.0);
  std::vector<Eigen::Vector2d> plots;
  Coast coast;
  for (int k = 0; k < seen + unseen; ++k) {
    const double t = kScan * k;
    const Eigen::Vector2d centre(5.0 * t + 0.15 * t * t, 0.0);
    plots.clear();
    for (int i = 0; i < 8 && k < seen; ++i) {
      const double r = std::sqrt(u(rng)), phi = 2.0 * std::numbers::pi * u(rng);
      // Each draw is its own step, last argument first: the order GCC used when the scenes were
      // measured (C++ leaves the evaluation order of arguments unspecified).
      const double noise_y = noise(rng), noise_x = noise(rng);
      plots.push_back(centre + Eigen::Vector2d(50.0 * r * std::cos(phi) + noise_x,
                                               20.0 * r * std::sin(phi) + noise_y));
    }
    const std::vector<Eigen::Matrix2d> noises(plots.size(), Eigen::Matrix2d::Identity() * 25.0);
    EXPECT_FALSE(tracker.process(t, plots, noises).skipped);
    EXPECT_EQ(tracker.tracks().size(), 1u) << "scan " << k;
    if (tracker.tracks().empty()) continue;
    (k < seen ? coast.last_seen : coast.coasted.emplace_back()) = tracker.tracks().front().object;
  }
  return coast;
}

class ExtendedCoast : public ::testing::TestWithParam<EstimatorKind> {};

TEST_P(ExtendedCoast, UnseenTrackCoastsAtConstantVelocity) {
  // GIVEN a track that followed an accelerating object for 10 scans
  // WHEN the object is unseen for 3 scans
  const Coast coast = run_coast(GetParam(), true, 10, 3);
  const ExtendedObject& last = coast.last_seen;
  ASSERT_EQ(coast.coasted.size(), 3u);
  ASSERT_GT(std::abs(last.x[4]), 0.05) << "the track estimated no acceleration to drop";
  // THEN each coasted centre is the last one moved on at its velocity (to 1e-6 m), the
  // velocity is kept (1e-9 m/s) and the acceleration's mean is zero
  for (int j = 0; j < 3; ++j) {
    const ExtendedObject& c = coast.coasted[j];
    const double t = kScan * (j + 1);
    EXPECT_NEAR(c.x[0], last.x[0] + t * last.x[1], 1e-6) << "scan " << j;
    EXPECT_NEAR(c.x[2], last.x[2] + t * last.x[3], 1e-6) << "scan " << j;
    EXPECT_NEAR(c.x[1], last.x[1], 1e-9);
    EXPECT_NEAR(c.x[3], last.x[3], 1e-9);
    EXPECT_EQ(c.x[4], 0.0);
    EXPECT_EQ(c.x[5], 0.0);
  }
}

TEST_P(ExtendedCoast, CoastKeepsTheSingerCovarianceAndDropsOnlyTheExtrapolation) {
  // GIVEN the same track with and without the constant-velocity coast
  const Coast cv = run_coast(GetParam(), true, 10, 3);
  const Coast singer = run_coast(GetParam(), false, 10, 3);
  ASSERT_EQ(cv.coasted.size(), 3u);
  ASSERT_EQ(singer.coasted.size(), 3u);
  // THEN the seen scans are the same (to 1e-9 m), and through the coast the covariance is the
  // Singer prediction's (relative 1e-9) while the Singer centre runs ahead of the
  // constant-velocity one by at least dt^2 a / 2 of the first coasted scan's acceleration
  EXPECT_LT((cv.last_seen.x - singer.last_seen.x).norm(), 1e-9);
  const double a = singer.last_seen.x[4];
  for (int j = 0; j < 3; ++j) {
    const KinMat& P = singer.coasted[j].P;
    EXPECT_LT((cv.coasted[j].P - P).norm(), 1e-9 * P.norm()) << "scan " << j;
    const double lead = singer.coasted[j].x[0] - cv.coasted[j].x[0];
    EXPECT_GT(std::copysign(1.0, a) * lead, 0.5 * kScan * kScan * std::abs(a) * 0.99)
        << "scan " << j;
  }
}

INSTANTIATE_TEST_SUITE_P(AllEstimators, ExtendedCoast,
                         ::testing::Values(EstimatorKind::kSmf, EstimatorKind::kRandomMatrix,
                                           EstimatorKind::kMemEkf));

}  // namespace
}  // namespace skytrack::extended
