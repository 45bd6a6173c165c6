// Fast covariance intersection and the CV alignment, against hand-computed cases.
#include <vector>

#include <gtest/gtest.h>

#include "skytrack/fusion/covariance_intersection.hpp"

namespace skytrack::fusion {
namespace {

StateEstimate track(double x, double variance, int dims = 2) {
  StateEstimate s;
  s.dims = dims;
  s.x.setZero();
  s.x(0) = x;
  s.P = StateEstimate::Mat::Identity() * variance;
  return s;
}

TEST(CovarianceIntersection, FastWeightsByInverseTrace) {
  // GIVEN P1 = I, P2 = 4 I (4-D): w1 = (1/4) / (1/4 + 1/16) = 0.8, w2 = 0.2
  const std::vector<StateEstimate> in{track(0.0, 1.0), track(17.0, 4.0)};
  const FusedEstimate f = covariance_intersection(in);
  ASSERT_TRUE(f.ok);
  // P^-1 = 0.8 I + 0.2 / 4 I = 0.85 I; x = P (0.8 * 0 + 0.05 * 17) = 1
  EXPECT_NEAR(f.estimate.P(0, 0), 1.0 / 0.85, 1e-12);
  EXPECT_NEAR(f.estimate.P(3, 3), 1.0 / 0.85, 1e-12);
  EXPECT_NEAR(f.estimate.x(0), 1.0, 1e-12);
  EXPECT_EQ(f.estimate.dims, 2);
}

TEST(CovarianceIntersection, IsNeverMoreConfidentThanTwiceTheBestTrack) {
  // Two identical tracks (fully correlated): CI must not halve the covariance.
  const std::vector<StateEstimate> in{track(5.0, 2.0, 3), track(5.0, 2.0, 3)};
  const FusedEstimate f = covariance_intersection(in);
  ASSERT_TRUE(f.ok);
  EXPECT_NEAR(f.estimate.P(4, 4), 2.0, 1e-12);
  EXPECT_NEAR(f.estimate.x(0), 5.0, 1e-12);
  EXPECT_EQ(f.estimate.dims, 3);
}

TEST(CovarianceIntersection, MixedDimensionsTakeHeightFromThreeDTracks) {
  StateEstimate three = track(0.0, 1.0, 3);
  three.x(4) = 1000.0;
  const std::vector<StateEstimate> in{track(0.0, 1.0, 2), three};
  const FusedEstimate f = covariance_intersection(in);
  ASSERT_TRUE(f.ok);
  EXPECT_EQ(f.estimate.dims, 3);
  EXPECT_NEAR(f.estimate.x(4), 1000.0, 1e-9);
}

TEST(CovarianceIntersection, NotPositiveDefiniteIsReported) {
  StateEstimate bad = track(0.0, 1.0);
  bad.P(1, 1) = -1.0;
  const std::vector<StateEstimate> in{track(0.0, 1.0), bad};
  EXPECT_FALSE(covariance_intersection(in).ok);
}

TEST(PredictCv, MovesByVelocityAndGrowsCovariance) {
  StateEstimate s = track(100.0, 1.0);
  s.x(1) = 10.0;
  const StateEstimate p = predict_cv(s, 2.0, 3.0);
  EXPECT_NEAR(p.x(0), 120.0, 1e-12);
  // P = F P F' + q [dt^3/3 dt^2/2; dt^2/2 dt]: P00 = 1 + 4 + 3 * 8 / 3
  EXPECT_NEAR(p.P(0, 0), 1.0 + 4.0 + 8.0, 1e-12);
  EXPECT_NEAR(p.P(0, 1), 2.0 + 6.0, 1e-12);
  EXPECT_NEAR(p.P(1, 1), 1.0 + 6.0, 1e-12);
}

}  // namespace
}  // namespace skytrack::fusion
