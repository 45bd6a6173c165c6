// Two process-noise levels (motion.accel_noise and motion.manoeuvre_accel). SMF-EOT: each
// scan the tracker predicts with the quiet level and again with the manoeuvre level, and
// keeps the one its plots are likelier under (with Page's CUSUM of that log ratio at zero).
// The random matrix and MEM-EKF*: both levels are kept and mixed each scan by the plots'
// likelihood (noise_levels.hpp). An object going straight keeps the tight covariance of the
// quiet level; a ship in paper 002's turns is followed closer than with the quiet level
// alone.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "skytrack/extended/extended_tracker.hpp"

namespace skytrack::extended {
namespace {

constexpr double kScan = 10.0;   // [s]
constexpr double kR = 25.0;      // [m^2] plot noise variance per axis
constexpr double kSpeed = 13.9;  // [m/s]
// Paper 002's ship: 4.5 deg/s (1.1 m/s^2 at 13.9 m/s, beyond a 0.5 m/s^2 level) for 40 s
// from t = 30 s and back from t = 90 s; 340 m x 80 m, 5 plots a scan.
constexpr double kTurnRate = 4.5 * std::numbers::pi / 180.0;  // [rad/s]
constexpr int kScans = 17;

struct Truth {
  Eigen::Vector2d centre;
  double heading;  // [rad] from x to y
};

// Integrated in 0.1 s steps: straight, left turn [30, 70) s, straight, right turn [90, 130).
Truth truth_at(double t, bool turning) {
  Truth truth{{0.0, 0.0}, 0.0};
  for (double s = 0.0; s < t - 1e-9; s += 0.1) {
    double rate = 0.0;
    if (turning && s >= 30.0 && s < 70.0) rate = kTurnRate;
    if (turning && s >= 90.0 && s < 130.0) rate = -kTurnRate;
    truth.heading += rate * 0.05;
    truth.centre +=
        0.1 * kSpeed * Eigen::Vector2d(std::cos(truth.heading), std::sin(truth.heading));
    truth.heading += rate * 0.05;
  }
  return truth;
}

// 5 scatterers uniform over a 170 m x 40 m (semi-axes) ellipse along the heading, plus noise.
std::vector<Eigen::Vector2d> plots_at(const Truth& truth, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, std::sqrt(kR));
  const Eigen::Rotation2Dd turn(truth.heading);
  std::vector<Eigen::Vector2d> plots;
  for (int i = 0; i < 5; ++i) {
    const double r = std::sqrt(u(rng)), phi = 2.0 * std::numbers::pi * u(rng);
    // Each draw is its own step, last argument first: the order GCC used when the scenes were
    // measured (C++ leaves the evaluation order of arguments unspecified).
    const double noise_y = noise(rng), noise_x = noise(rng);
    plots.push_back(truth.centre +
                    turn * Eigen::Vector2d(170.0 * r * std::cos(phi), 40.0 * r * std::sin(phi)) +
                    Eigen::Vector2d(noise_x, noise_y));
  }
  return plots;
}

// SMF-EOT's CUSUM stands above zero; mixed levels: the manoeuvre level is the likelier.
bool manoeuvring(const ExtendedTrack& track, EstimatorKind kind) {
  return kind == EstimatorKind::kSmf ? track.manoeuvre_evidence > 0.0
                                     : track.levels.probability[1] > 0.5;
}

struct Outcome {
  double error = 0.0;        // [m] RMS centre error from the first turn on, over the runs
  double speed_sigma = 0.0;  // [m/s] mean sqrt of the velocity variance per axis, last scan
  int manoeuvre_scans = 0;   // scans at the manoeuvre level (manoeuvring below)
  int renumbered_runs = 0;   // runs whose ship was confirmed under more than one number
};

Outcome run(EstimatorKind kind, double quiet, double manoeuvre, bool turning) {
  ExtendedSpec spec;
  spec.kind = kind;
  spec.motion.accel_noise = quiet;
  spec.motion.manoeuvre_accel = manoeuvre;
  constexpr int kRuns = 20;
  Outcome out;
  double squared = 0.0;
  int scored = 0;
  for (int seed = 1; seed <= kRuns; ++seed) {
    ExtendedTracker tracker(spec);
    std::mt19937_64 rng(seed);
    std::vector<std::uint64_t> numbers;
    for (int k = 0; k < kScans; ++k) {
      const double t = kScan * k;
      const Truth truth = truth_at(t, turning);
      const std::vector<Eigen::Vector2d> plots = plots_at(truth, rng);
      const std::vector<Eigen::Matrix2d> noises(plots.size(), kR * Eigen::Matrix2d::Identity());
      tracker.process(t, plots, noises);
      const auto confirmed = std::find_if(
          tracker.tracks().begin(), tracker.tracks().end(),
          [](const ExtendedTrack& x) { return x.status == ExtendedTrackStatus::kConfirmed; });
      if (confirmed == tracker.tracks().end()) continue;
      const ExtendedTrack& track = *confirmed;
      if (std::find(numbers.begin(), numbers.end(), track.id) == numbers.end()) {
        numbers.push_back(track.id);
      }
      out.manoeuvre_scans += manoeuvring(track, kind);
      if (t >= 30.0) squared += (track.position() - truth.centre).squaredNorm(), ++scored;
      if (k == kScans - 1) {
        out.speed_sigma += std::sqrt(0.5 * (track.object.P(1, 1) + track.object.P(3, 3))) / kRuns;
      }
    }
    out.renumbered_runs += numbers.size() > 1;
  }
  out.error = std::sqrt(squared / std::max(scored, 1));
  return out;
}

class ManoeuvreLevel : public ::testing::TestWithParam<EstimatorKind> {};

TEST_P(ManoeuvreLevel, AStraightObjectKeepsTheQuietCovariance) {
  const Outcome quiet = run(GetParam(), 0.5, 0.0, false);
  const Outcome both = run(GetParam(), 0.5, 2.0, false);
  const Outcome hard = run(GetParam(), 2.0, 0.0, false);
  // Measured, velocity sigma [m/s] quiet / both / manoeuvre level alone: SMF-EOT 6.2 / 6.5 /
  // 11.9, random matrix 4.3 / 4.7 / 7.7, MEM-EKF* 4.5 / 4.8 / 8.1.
  EXPECT_LT(both.speed_sigma, 1.25 * quiet.speed_sigma);
  EXPECT_GT(hard.speed_sigma, 1.4 * both.speed_sigma);
}

TEST_P(ManoeuvreLevel, TheManoeuvreLevelIsChosenInTheTurns) {
  const Outcome straight = run(GetParam(), 0.5, 2.0, false);
  const Outcome turning = run(GetParam(), 0.5, 2.0, true);
  // Measured, scans at the manoeuvre level of 20 x 17: 31 / 112 (SMF-EOT), 3 / 20 (random
  // matrix), 4 / 10 (MEM-EKF*). Mixed, the manoeuvre level helps while still the less likely.
  EXPECT_GT(turning.manoeuvre_scans, 2 * straight.manoeuvre_scans);
}

// MEM-EKF* gains less (its own test below): its plot-by-plot update follows a turn closer on
// the quiet level alone.
class ManoeuvreLevelInTurns : public ManoeuvreLevel {};

TEST_P(ManoeuvreLevelInTurns, TheShipIsFollowedCloserThanByTheQuietLevelAlone) {
  const Outcome quiet = run(GetParam(), 0.5, 0.0, true);
  const Outcome both = run(GetParam(), 0.5, 2.0, true);
  // Measured, RMS centre error [m] quiet / both / manoeuvre level alone: SMF-EOT 100 / 61 /
  // 38, random matrix 150 / 53 / 49 (103 with the CUSUM's choice).
  EXPECT_LT(both.error, 0.8 * quiet.error)
      << "quiet alone " << quiet.error << " m, both levels " << both.error << " m";
}

TEST(ManoeuvreLevelMemEkf, MixedLevelsFollowTheShipCloserThanTheQuietLevelAlone) {
  const Outcome quiet = run(EstimatorKind::kMemEkf, 0.5, 0.0, true);
  const Outcome both = run(EstimatorKind::kMemEkf, 0.5, 2.0, true);
  // Measured 45.3 / 39.7 m (38.5 m with the manoeuvre level alone; 65 m with the CUSUM's
  // choice of one level a scan, which moved the centre with each plot of the long hull).
  EXPECT_LT(both.error, 0.95 * quiet.error)
      << "quiet alone " << quiet.error << " m, both levels " << both.error << " m";
}

// An object going straight at the quiet level of a real ship (0.1 m/s^2): the turn's first
// scan lies outside the quiet level's gates. SMF-EOT chooses its level from the plots its
// gates took, so it gates on the manoeuvre level's set; the mixed levels' prediction holds
// the manoeuvre already.
TEST_P(ManoeuvreLevel, AQuietStraightLevelKeepsTheTurningShipsNumber) {
  const Outcome out = run(GetParam(), 0.1, 2.0, true);
  // Measured: no run renumbered, RMS centre error 39 / 51 / 43 m (SMF-EOT / random matrix /
  // MEM-EKF*); SMF-EOT gating on the quiet level's set renumbered the ship in 2 of 20 runs,
  // 84 m. A pin on these runs' noise, not a bound: over seeds 1-100 the ship is renumbered
  // in 2 / 1 / 1 runs, and in 1 / 1 / 2 with each plot's two noise draws swapped (where the
  // turn's first scan splits the plots between the track and a new one, and the new one
  // takes the next scan's, the number is handed over: extended_handover_test.cpp).
  EXPECT_EQ(out.renumbered_runs, 0);
  EXPECT_LT(out.error, 70.0);
}

INSTANTIATE_TEST_SUITE_P(Estimators, ManoeuvreLevel,
                         ::testing::Values(EstimatorKind::kSmf, EstimatorKind::kRandomMatrix,
                                           EstimatorKind::kMemEkf),
                         [](const auto& info) { return std::string(to_string(info.param)); });
INSTANTIATE_TEST_SUITE_P(Estimators, ManoeuvreLevelInTurns,
                         ::testing::Values(EstimatorKind::kSmf, EstimatorKind::kRandomMatrix),
                         [](const auto& info) { return std::string(to_string(info.param)); });

}  // namespace
}  // namespace skytrack::extended
