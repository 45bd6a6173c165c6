// The test of a scan's plots as the object's or clutter (object_plots_log_ratio,
// ExtendedSpec::clutter_scan_test): by hand, and in the tracker a pair of stray plots at the
// edge of a track's gate in a scan that missed its object leaves the track coasting, while
// two of the object's own plots still update it.
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include "skytrack/extended/extended_existence.hpp"
#include "skytrack/extended/extended_tracker.hpp"

namespace skytrack::extended {
namespace {

constexpr double kScan = 10.0;  // [s]
constexpr double kR = 25.0;     // [m^2] plot noise variance per axis

TEST(ObjectPlotsLogRatio, OnePlotByHand) {
  // GIVEN one plot at the predicted centre, C = 100 I, S = 400 I, the default model
  const ExistenceSpec spec;  // P_D 0.95, gamma 8, lambda 1e-6
  const std::vector<Eigen::Vector2d> plots{{3.0, -2.0}};
  const double got = object_plots_log_ratio(plots, {3.0, -2.0}, 100.0 * Eigen::Matrix2d::Identity(),
                                            400.0 * Eigen::Matrix2d::Identity(), spec);
  // THEN ln 19 - 8 + ln 8 - ln 1e-6 + ln N(0; 0, 500 I), to 1e-9
  const double want = std::log(19.0) - 8.0 + std::log(8.0) - std::log(1e-6) -
                      std::log(2.0 * std::numbers::pi) - std::log(500.0);
  EXPECT_NEAR(got, want, 1e-9);
}

TEST(ObjectPlotsLogRatio, TwoPlotsByHand) {
  // GIVEN two plots a = 30 m either side of a mean 40 m east of the centre, C = 100 I,
  // S = 400 I: the spread taken is S plus the plots' sample covariance diag(a^2, 0)
  const ExistenceSpec spec;
  const double a = 30.0, s = 400.0, c = 100.0;
  const std::vector<Eigen::Vector2d> plots{{40.0 + a, 0.0}, {40.0 - a, 0.0}};
  const double got =
      object_plots_log_ratio(plots, Eigen::Vector2d::Zero(), c * Eigen::Matrix2d::Identity(),
                             s * Eigen::Matrix2d::Identity(), spec);
  // THEN the mean's N(40 e_x; 0, C + S/2) and the deviations' density under S + sample
  const double log_2pi = std::log(2.0 * std::numbers::pi);
  const double about = c + s / 2.0;
  const double mean_term = -log_2pi - std::log(about) - 0.5 * 1600.0 / about;
  const double deviation_term =
      -log_2pi - 0.5 * std::log((s + a * a) * s) - std::log(2.0) - 0.5 * 2.0 * a * a / (s + a * a);
  const double want =
      std::log(19.0) - 8.0 + 2.0 * (std::log(8.0) - std::log(1e-6)) + mean_term + deviation_term;
  EXPECT_NEAR(got, want, 1e-9);
  // AND no plots or a singular spread are no evidence of the object
  EXPECT_EQ(object_plots_log_ratio({}, Eigen::Vector2d::Zero(), Eigen::Matrix2d::Identity(),
                                   Eigen::Matrix2d::Identity(), spec),
            -std::numeric_limits<double>::infinity());
}

// A 100 m x 25 m object east at 15 m/s, 8 plots a scan uniform over it plus N(0, 25 m^2),
// tracked for 10 scans (deterministic: the same track each time).
ExtendedSpec spec_of(EstimatorKind kind, bool test) {
  ExtendedSpec spec;
  spec.kind = kind;
  spec.clutter_scan_test = test;
  return spec;
}

void see_ten_scans(ExtendedTracker& tracker) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 5.0);
  for (int k = 0; k < 10; ++k) {
    const double t = kScan * k;
    const Eigen::Vector2d centre(15.0 * t, 0.0);
    std::vector<Eigen::Vector2d> plots;
    for (int i = 0; i < 8; ++i) {
      const double r = std::sqrt(u(rng)), phi = 2.0 * std::numbers::pi * u(rng);
      // Each draw is its own step, last argument first: the order GCC used when the scenes were
      // measured (C++ leaves the evaluation order of arguments unspecified).
      const double noise_y = noise(rng), noise_x = noise(rng);
      plots.push_back(centre + Eigen::Vector2d(100.0 * r * std::cos(phi) + noise_x,
                                               25.0 * r * std::sin(phi) + noise_y));
    }
    const std::vector<Eigen::Matrix2d> noises(plots.size(), kR * Eigen::Matrix2d::Identity());
    tracker.process(t, plots, noises);
  }
}

struct Scan {
  ExtendedTrack coasted;  // the track after a scan without plots
  ExtendedTrack after;    // the track after the scan with `plots`
  double log_ratio;       // the test's figure for those plots
};

// Scan 10 with two plots `offsets` from the track's prediction, along its minor axis (north)
// scaled to d^2 = `d2` under the plot gate's G = HPH' + X/4 + R (X floored at 50 m).
Scan scan_with_pair(EstimatorKind kind, bool test, double d2, double along) {
  ExtendedTracker empty(spec_of(kind, test)), paired(spec_of(kind, test));
  see_ten_scans(empty);
  see_ten_scans(paired);
  const double t = kScan * 10.0;
  empty.process(t, std::vector<Eigen::Vector2d>{}, std::vector<Eigen::Matrix2d>{});
  Scan scan{empty.tracks().front(), {}, 0.0};
  const ExtendedTrack& predicted = scan.coasted;  // coasted: the prediction, covariance kept
  const PosMat H = position_matrix();
  const Eigen::Matrix2d C = H * predicted.object.P * H.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(predicted.object.extent);
  const Eigen::Matrix2d X = eig.eigenvectors() * eig.eigenvalues().cwiseMax(2500.0).asDiagonal() *
                            eig.eigenvectors().transpose();
  const Eigen::Matrix2d S = X / 4.0 + kR * Eigen::Matrix2d::Identity();
  const double north = std::sqrt(d2 * (C + S)(1, 1));
  const std::vector<Eigen::Vector2d> plots{predicted.position() + Eigen::Vector2d(along, north),
                                           predicted.position() + Eigen::Vector2d(-along, north)};
  scan.log_ratio = object_plots_log_ratio(plots, predicted.position(), C, S, ExistenceSpec{});
  const std::vector<Eigen::Matrix2d> noises(2, kR * Eigen::Matrix2d::Identity());
  paired.process(t, plots, noises);
  scan.after = paired.tracks().front();
  return scan;
}

class ExtendedClutterScan : public ::testing::TestWithParam<EstimatorKind> {};

TEST_P(ExtendedClutterScan, StrayPairAtTheGateEdgeLeavesTheTrackCoasting) {
  // GIVEN a track on its object for 10 scans; WHEN the object is missed and two stray plots
  // 10 m apart lie beside its prediction at d^2 = 13 (inside the plot gate, 13.8)
  const Scan on = scan_with_pair(GetParam(), true, 13.0, 5.0);
  const Scan off = scan_with_pair(GetParam(), false, 13.0, 5.0);
  ASSERT_LT(on.log_ratio, 0.0) << "the pair should be likelier clutter";
  // THEN with the test the scan is a miss: the track's state is the coast's (1e-9 m)
  EXPECT_EQ(on.after.plots, 0);
  EXPECT_LT((on.after.object.x - on.coasted.object.x).norm(), 1e-9);
  // AND without it the pair updates the track and pulls its centre north by over 20 m
  EXPECT_EQ(off.after.plots, 2);
  EXPECT_GT(off.after.position().y() - off.coasted.position().y(), 20.0);
}

TEST_P(ExtendedClutterScan, TwoOfTheObjectsOwnPlotsStillUpdate) {
  // GIVEN the same track; WHEN its object gives only two plots, 40 m either side of the
  // predicted centre along it and 10 m north (d^2 well inside the gate)
  const Scan scan = scan_with_pair(GetParam(), true, 0.1, 40.0);
  // THEN they are taken as the object's and update the track
  EXPECT_GT(scan.log_ratio, 0.0);
  EXPECT_EQ(scan.after.plots, 2);
  EXPECT_GT((scan.after.object.x - scan.coasted.object.x).norm(), 1e-6);
}

INSTANTIATE_TEST_SUITE_P(AllEstimators, ExtendedClutterScan,
                         ::testing::Values(EstimatorKind::kSmf, EstimatorKind::kRandomMatrix,
                                           EstimatorKind::kMemEkf));

}  // namespace
}  // namespace skytrack::extended
