// Paper 004 eq. 9-12 for one pair of tracks, against hand-computed values.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "skytrack/fusion/track_distance.hpp"

namespace skytrack::fusion {
namespace {

PositionEstimate at(double x, double y, double variance) {
  PositionEstimate p;
  p.mean = {x, y, 0.0};
  p.cov = Eigen::Matrix3d::Identity() * variance;
  p.cov(2, 2) = 0.0;
  return p;
}

FusionSpec euclidean() {
  FusionSpec s;
  s.metric = Metric::kEuclidean;
  s.cutoff = 10.0;
  s.label_penalty = 2.0;
  s.order = 2.0;
  return s;
}

TEST(TrackDistance, EuclideanExpectationAddsTheTraceOfBothCovariances) {
  // GIVEN tracks 5 m apart with variances 1 and 0.8 m^2 per axis
  const double sq = expected_squared_distance(at(0, 0, 1.0), at(3, 4, 0.8), Metric::kEuclidean);
  EXPECT_NEAR(sq, 25.0 + 2.0 * 1.8, 1e-12);  // |dm|^2 + tr(Pa + Pb)
}

TEST(TrackDistance, NormalisedExpectationIsMahalanobisPlusDimension) {
  // S = 2 I: (3, 0) S^-1 (3, 0)' = 4.5, plus n = 2
  const double sq = expected_squared_distance(at(0, 0, 1.0), at(3, 0, 1.0), Metric::kNormalised);
  EXPECT_NEAR(sq, 6.5, 1e-5);
}

TEST(TrackDistance, BaseDistanceAddsTheLabelTermAndCuts) {
  const FusionSpec s = euclidean();
  EXPECT_NEAR(base_distance(28.6, false, s), std::sqrt(28.6), 1e-12);
  EXPECT_NEAR(base_distance(28.6, true, s), std::sqrt(28.6 + 4.0), 1e-12);  // + alpha^2
  EXPECT_DOUBLE_EQ(base_distance(200.0, false, s), 10.0);                   // cut at c
  FusionSpec p1 = s;
  p1.order = 1.0;  // (d + alpha) for p = 1
  EXPECT_NEAR(base_distance(9.0, true, p1), 5.0, 1e-12);
}

TEST(TrackDistance, AdaptiveBetaFollowsEquation11) {
  EXPECT_NEAR(adaptive_beta(1.0, 3.0, 0.4), 0.4 * 3.0 / 4.0, 1e-15);
  EXPECT_NEAR(adaptive_beta(3.0, 1.0, 0.4), 0.3, 1e-15);
  EXPECT_NEAR(adaptive_beta(2.0, 2.0, 0.4), 0.2, 1e-15);  // agreement: epsilon / 2
  EXPECT_NEAR(adaptive_beta(5.0, 0.0, 0.4), 0.4, 1e-15);  // one zero: epsilon
  EXPECT_NEAR(adaptive_beta(0.0, 0.0, 0.4), 0.2, 1e-15);  // 0 / 0 read as agreement
}

TEST(TrackDistance, BlendIsAdaptiveOrFixed) {
  FusionSpec s = euclidean();
  s.blend = Blend::kAdaptive;
  s.epsilon = 0.4;
  EXPECT_NEAR(blend(1.0, 3.0, s), 0.3 * 1.0 + 0.7 * 3.0, 1e-12);
  s.blend = Blend::kFixed;
  s.history_weight = 0.2;
  EXPECT_NEAR(blend(1.0, 3.0, s), 0.2 * 1.0 + 0.8 * 3.0, 1e-12);
}

TEST(TrackDistance, HistoryIsTheMeanOverCommonScansInTheWindow) {
  // GIVEN a at x = 0 and b at x = k (cycles 1..6, zero variance) and b missing cycle 4
  const FusionSpec s = euclidean();
  std::vector<HistoryPoint> a, b;
  for (std::uint64_t k = 1; k <= 6; ++k) {
    a.push_back({k, at(0, 0, 0.0)});
    if (k != 4) b.push_back({k, at(static_cast<double>(k), 0, 0.0)});
  }
  // WHEN the window holds 4 cycles at cycle 7: cycles 4, 5, 6 before it; 4 is not common
  const double dw = history_distance(a, b, 7, 4, false, s, -1.0);
  EXPECT_NEAR(dw, (5.0 + 6.0) / 2.0, 1e-12);
  // ... with the label term on each scan
  const double dw_label = history_distance(a, b, 7, 4, true, s, -1.0);
  EXPECT_NEAR(dw_label, (std::sqrt(29.0) + std::sqrt(40.0)) / 2.0, 1e-12);
  // no common scan: the fallback
  EXPECT_DOUBLE_EQ(history_distance(a, b, 100, 4, false, s, -1.0), -1.0);
}

TEST(TrackDistance, PairMospaBlendsCurrentAndHistory) {
  FusionSpec s = euclidean();
  s.blend = Blend::kAdaptive;
  s.epsilon = 0.4;
  const std::vector<HistoryPoint> a{{1, at(0, 0, 0.0)}};
  const std::vector<HistoryPoint> b{{1, at(1, 0, 0.0)}};
  // current 3 m, history 1 m: beta = 0.4 * 3 / 4 = 0.3
  const double m = pair_mospa(at(0, 0, 0.0), at(3, 0, 0.0), a, b, 2, 10, false, s);
  EXPECT_NEAR(m, 0.3 * 1.0 + 0.7 * 3.0, 1e-12);
}

}  // namespace
}  // namespace skytrack::fusion
