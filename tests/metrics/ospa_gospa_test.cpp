#include "skytrack/metrics/ospa_gospa.hpp"

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace skytrack::metrics {
namespace {

using Points = std::vector<Eigen::VectorXd>;

Eigen::VectorXd p2(double x, double y) {
  return Eigen::Vector2d(x, y);
}
Eigen::VectorXd p3(double x, double y, double z) {
  return Eigen::Vector3d(x, y, z);
}

TEST(Ospa, EmptyVersusEmptyIsZero) {
  const OspaGospaResult r = ospa_gospa(Points{}, Points{});
  EXPECT_EQ(r.ospa, 0.0);
  EXPECT_EQ(r.gospa, 0.0);
  EXPECT_EQ(r.missed, 0);
  EXPECT_EQ(r.false_tracks, 0);
  EXPECT_TRUE(r.pairs.empty());
}

TEST(Gospa, EmptyEstimatesCountEveryTruthAsMissed) {
  // GIVEN n = 3 truths, no estimates, c = 50, p = 2
  const OspaGospaConfig config{50.0, 2.0};
  const Points truths{p2(0, 0), p2(100, 0), p2(0, 100)};
  const OspaGospaResult r = ospa_gospa(truths, Points{}, config);
  // THEN GOSPA = (c^p / 2 * n)^(1/p) and OSPA = c
  EXPECT_NEAR(r.gospa, std::sqrt(50.0 * 50.0 / 2.0 * 3.0), 1e-12);
  EXPECT_NEAR(r.ospa, 50.0, 1e-12);
  EXPECT_EQ(r.missed, 3);
  EXPECT_EQ(r.false_tracks, 0);
  EXPECT_EQ(r.localisation, 0.0);
}

TEST(Gospa, EmptyTruthCountsEveryEstimateAsFalse) {
  const OspaGospaConfig config{10.0, 1.0};
  const OspaGospaResult r = ospa_gospa(Points{}, Points{p2(0, 0), p2(5, 5)}, config);
  EXPECT_NEAR(r.gospa, 10.0 / 2.0 * 2.0, 1e-12);
  EXPECT_NEAR(r.ospa, 10.0, 1e-12);
  EXPECT_EQ(r.false_tracks, 2);
  EXPECT_EQ(r.missed, 0);
}

TEST(Gospa, PairBeyondCutoffIsOneMissedAndOneFalse) {
  // GIVEN one truth and one estimate 150 m apart, c = 100
  const OspaGospaResult r = ospa_gospa(Points{p2(0, 0)}, Points{p2(150, 0)}, {100.0, 2.0});
  // THEN GOSPA^2 = c^2/2 + c^2/2, OSPA = min(d, c) = c, and no pair is reported
  EXPECT_NEAR(r.gospa, 100.0, 1e-12);
  EXPECT_NEAR(r.ospa, 100.0, 1e-12);
  EXPECT_EQ(r.missed, 1);
  EXPECT_EQ(r.false_tracks, 1);
  EXPECT_TRUE(r.pairs.empty());
}

TEST(Gospa, MixedCaseMatchesHandComputation) {
  // GIVEN truths (0,0), (1000,0) and one estimate at (3,4): d = 5 to the first
  const OspaGospaResult r = ospa_gospa(Points{p2(0, 0), p2(1000, 0)}, Points{p2(3, 4)});
  // THEN GOSPA^2 = 5^2 + 100^2/2, OSPA^2 = (5^2 + 100^2) / 2
  EXPECT_NEAR(r.gospa, std::sqrt(25.0 + 5000.0), 1e-12);
  EXPECT_NEAR(r.ospa, std::sqrt((25.0 + 10000.0) / 2.0), 1e-12);
  EXPECT_NEAR(r.localisation, 25.0, 1e-12);
  ASSERT_EQ(r.pairs.size(), 1u);
  EXPECT_EQ(r.pairs[0].truth, 0);
  EXPECT_EQ(r.pairs[0].estimate, 0);
  EXPECT_NEAR(r.pairs[0].distance, 5.0, 1e-12);
}

TEST(Gospa, TwoByTwoOptimumIsNotTheDiagonal) {
  // GIVEN the diagonal costs 101 + 104, the swap 4 + 1
  const Points truths{p2(0, 0), p2(10, 0)};
  const Points estimates{p2(10, 1), p2(0, 2)};
  const OspaGospaResult r = ospa_gospa(truths, estimates, {100.0, 2.0});
  EXPECT_NEAR(r.gospa, std::sqrt(5.0), 1e-12);
  EXPECT_NEAR(r.ospa, std::sqrt(5.0 / 2.0), 1e-12);
  ASSERT_EQ(r.pairs.size(), 2u);
  EXPECT_EQ(r.pairs[0].truth, 0);
  EXPECT_EQ(r.pairs[0].estimate, 1);
  EXPECT_EQ(r.pairs[1].truth, 1);
  EXPECT_EQ(r.pairs[1].estimate, 0);
}

TEST(Gospa, ComparesCommonDimensionsOfTwoAndThreeDimensionalPoints) {
  const OspaGospaResult r = ospa_gospa(Points{p2(0, 0)}, Points{p3(3, 4, 9000)});
  EXPECT_NEAR(r.gospa, 5.0, 1e-12);
}

TEST(Gospa, IsSymmetricAndSwapsMissedWithFalse) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(0.0, 300.0);
  for (int trial = 0; trial < 50; ++trial) {
    Points a(trial % 5), b((trial * 7) % 6);
    // Each draw is its own step, last argument first: the order GCC used when the scenes were
    // measured (C++ leaves the evaluation order of arguments unspecified).
    for (auto& x : a) {
      const double py = u(rng), px = u(rng);
      x = p2(px, py);
    }
    for (auto& x : b) {
      const double py = u(rng), px = u(rng);
      x = p2(px, py);
    }
    const OspaGospaConfig config{60.0, 1.0 + (trial % 3)};
    const OspaGospaResult ab = ospa_gospa(a, b, config);
    const OspaGospaResult ba = ospa_gospa(b, a, config);
    EXPECT_NEAR(ab.gospa, ba.gospa, 1e-9);
    EXPECT_NEAR(ab.ospa, ba.ospa, 1e-9);
    EXPECT_EQ(ab.missed, ba.false_tracks);
    // GOSPA^p = localisation + c^p/2 (missed + false)
    const double c_p = std::pow(config.cutoff, config.order);
    EXPECT_NEAR(std::pow(ab.gospa, config.order),
                ab.localisation + c_p / 2.0 * (ab.missed + ab.false_tracks), 1e-6);
    EXPECT_LE(ab.ospa, config.cutoff + 1e-9);
  }
}

TEST(Ospa, RejectsInvalidConfig) {
  EXPECT_TRUE(is_valid(OspaGospaConfig{100.0, 2.0}));
  EXPECT_FALSE(is_valid(OspaGospaConfig{0.0, 2.0}));
  EXPECT_FALSE(is_valid(OspaGospaConfig{100.0, 0.5}));
}

}  // namespace
}  // namespace skytrack::metrics
