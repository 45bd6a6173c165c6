// The two noise levels mixed per scan (noise_levels.hpp): the levels' probabilities start at
// their long-run shares, plots off the quiet prediction (a turn) move weight to the
// manoeuvre level and plots on it move weight back, and the mixture is the levels' moment
// match.
#include <vector>

#include <gtest/gtest.h>

#include "skytrack/extended/noise_levels.hpp"

namespace skytrack::extended {
namespace {

ExtendedSpec spec_of(EstimatorKind kind) {
  ExtendedSpec spec;
  spec.kind = kind;
  spec.motion.accel_noise = 0.5;
  spec.motion.manoeuvre_accel = 2.0;
  spec.motion.straight_duration = 120.0;
  spec.motion.manoeuvre_duration = 30.0;
  return spec;
}

// An object at the origin going +x at 15 m/s, 200 m x 60 m (semi-axes 100 m, 30 m), with
// a settled track's covariance.
ExtendedObject moving_object(const ExtendedEstimator& estimator) {
  KinVec x = KinVec::Zero();
  x[1] = 15.0;
  const KinMat P = (KinVec() << 25.0, 0.25, 25.0, 0.25, 0.01, 0.01).finished().asDiagonal();
  Eigen::Matrix2d extent;
  extent << 100.0 * 100.0, 0.0, 0.0, 30.0 * 30.0;
  return estimator.initiate(x, P, extent);
}

// Plots round `centre` spread along x (the hull) and a little across.
std::vector<Eigen::Vector2d> plots_round(const Eigen::Vector2d& centre) {
  std::vector<Eigen::Vector2d> plots;
  for (const double dx : {-60.0, -20.0, 20.0, 60.0}) {
    for (const double dy : {-10.0, 10.0}) plots.push_back(centre + Eigen::Vector2d(dx, dy));
  }
  return plots;
}

class NoiseLevelsTest : public ::testing::TestWithParam<EstimatorKind> {};

TEST_P(NoiseLevelsTest, ANewObjectStartsAtTheLevelsLongRunShares) {
  const ExtendedSpec spec = spec_of(GetParam());
  const ExtendedEstimator estimator(spec);
  const NoiseLevels levels = start_levels(moving_object(estimator), spec.motion);
  EXPECT_NEAR(levels.probability[0], 0.8, 1e-12);  // 120 / (120 + 30)
  EXPECT_NEAR(levels.probability[1], 0.2, 1e-12);
}

TEST_P(NoiseLevelsTest, PlotsOffTheQuietPredictionMoveWeightToTheManoeuvreLevel) {
  const ExtendedSpec spec = spec_of(GetParam());
  ExtendedEstimator estimator(spec);
  const Eigen::Matrix2d R = 25.0 * Eigen::Matrix2d::Identity();
  const Eigen::Matrix2d spread = 0.25 * moving_object(estimator).extent + R;
  for (const bool turned : {false, true}) {
    NoiseLevels levels = start_levels(moving_object(estimator), spec.motion);
    ExtendedObject mixture;
    predict_levels(levels, estimator, spec.motion, 10.0, mixture);
    const double before = levels.probability[1];
    // Straight: the plots round the prediction (150, 0). A turn at 2 m/s^2 begun at the last
    // scan: 100 m off it across the track (the quiet level's sigma there is about 26 m).
    const Eigen::Vector2d centre(150.0, turned ? 100.0 : 0.0);
    update_levels(levels, estimator, plots_round(centre), R, spread, mixture);
    if (turned) {
      EXPECT_GT(levels.probability[1], before + 0.2) << "before " << before;
    } else {
      EXPECT_LT(levels.probability[1], before) << "before " << before;
    }
    EXPECT_NEAR(levels.probability[0] + levels.probability[1], 1.0, 1e-12);
  }
}

TEST_P(NoiseLevelsTest, TheMixtureIsTheLevelsMomentMatch) {
  const ExtendedSpec spec = spec_of(GetParam());
  const ExtendedEstimator estimator(spec);
  NoiseLevels levels = start_levels(moving_object(estimator), spec.motion);
  levels.object[1].x[2] = 40.0;  // the manoeuvre level 40 m across
  levels.object[1].extent *= 2.0;
  levels.probability = {0.75, 0.25};
  const ExtendedObject m = mix(levels);
  EXPECT_NEAR(m.x[2], 10.0, 1e-12);
  // Var y = sum p_i (P_i + (y_i - y)^2) = 25 + 0.75 * 100 + 0.25 * 900.
  EXPECT_NEAR(m.P(2, 2), 25.0 + 75.0 + 225.0, 1e-9);
  EXPECT_NEAR(m.P(0, 0), 25.0, 1e-9);
  EXPECT_TRUE(m.extent.isApprox(levels.object[0].extent));  // the likelier level's
}

TEST_P(NoiseLevelsTest, EachLevelPredictsWithItsOwnNoise) {
  const ExtendedSpec spec = spec_of(GetParam());
  const ExtendedEstimator estimator(spec);
  NoiseLevels levels = start_levels(moving_object(estimator), spec.motion);
  ExtendedObject mixture;
  predict_levels(levels, estimator, spec.motion, 10.0, mixture);
  const double quiet = levels.object[0].P(1, 1), manoeuvre = levels.object[1].P(1, 1);
  EXPECT_GT(manoeuvre, quiet + 100.0);  // (2^2 - 0.5^2) * 10^2 m^2/s^2 more, about
  EXPECT_GT(mixture.P(1, 1), quiet);
  EXPECT_LT(mixture.P(1, 1), manoeuvre);
  EXPECT_NEAR(mixture.x[0], 150.0, 1e-9);  // both levels predict the same mean
}

INSTANTIATE_TEST_SUITE_P(Estimators, NoiseLevelsTest,
                         ::testing::Values(EstimatorKind::kRandomMatrix, EstimatorKind::kMemEkf),
                         [](const auto& info) { return std::string(to_string(info.param)); });

}  // namespace
}  // namespace skytrack::extended
