// ClutterRejector density and threshold, paper 000 §3.1 eq. 6-8, and the k-d tree truncation.
#include "skytrack/clutter/clutter_rejector.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "clutter_rejector_test_support.hpp"

namespace skytrack::clutter {
namespace {

using test::enabled_spec;
using test::kNoProtection;
using test::Points;

// Eq. 6-7 without truncation: the O(N^2) reference.
std::vector<double> brute_force_density(const Points& points, double h, int dims) {
  std::vector<double> density(points.size(), 0.0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (const Eigen::Vector3d& q : points) {
      density[i] += gaussian_kernel((points[i] - q).squaredNorm(), h, dims);
    }
    density[i] /= static_cast<double>(points.size());
  }
  return density;
}

TEST(ClutterRejector, DensityOfThreePlotsEqualsHandComputedKernelSum) {
  // GIVEN three plots at mutual distances 300, 400 and 500 m, h = 500 m, radius 3h = 1500 m
  const Points points = {{0.0, 0.0, 0.0}, {300.0, 0.0, 0.0}, {0.0, 400.0, 0.0}};
  ClutterRejector rejector(enabled_spec(500.0));
  // WHEN the densities are computed in 2-D and in 3-D
  const std::vector<double> d2 = rejector.apply(points, 2, kNoProtection).density;
  const std::vector<double> d3 = rejector.apply(points, 3, kNoProtection).density;
  // THEN each is (1/N) sum_i G(z, z_i), the plot itself included (eq. 6-7)
  const double two_h2 = 2.0 * 500.0 * 500.0;
  const double e300 = std::exp(-300.0 * 300.0 / two_h2);
  const double e400 = std::exp(-400.0 * 400.0 / two_h2);
  const double e500 = std::exp(-500.0 * 500.0 / two_h2);
  const double sums[3] = {1.0 + e300 + e400, 1.0 + e300 + e500, 1.0 + e400 + e500};
  const double g0_2d = 1.0 / (2.0 * std::numbers::pi * 500.0 * 500.0);
  const double g0_3d = std::pow(2.0 * std::numbers::pi * 500.0 * 500.0, -1.5);
  for (int i = 0; i < 3; ++i) {
    const double expected_2d = g0_2d * sums[i] / 3.0;
    const double expected_3d = g0_3d * sums[i] / 3.0;
    EXPECT_NEAR(d2[static_cast<std::size_t>(i)], expected_2d, 1e-12 * expected_2d);
    EXPECT_NEAR(d3[static_cast<std::size_t>(i)], expected_3d, 1e-12 * expected_3d);
  }
}

TEST(ClutterRejector, ThresholdFollowsEquation8) {
  // GIVEN the formula alone
  EXPECT_DOUBLE_EQ(clutter_threshold(1.0, 11.0, 1, 10), 2.0);
  EXPECT_DOUBLE_EQ(clutter_threshold(1.0, 11.0, 3, 10), 4.0);
  EXPECT_DOUBLE_EQ(clutter_threshold(2.0, 2.0, 1, 10), 2.0);
  // GIVEN three plots 100 m apart and one plot 10 km away, h = 500 m, beta = 1, n_f = 10
  const Points points = {{0, 0, 0}, {100, 0, 0}, {0, 100, 0}, {10000, 0, 0}};
  ClutterRejector rejector(enabled_spec(500.0));
  // WHEN the scan is processed
  const ClutterRejectionResult& r = rejector.apply(points, 2, kNoProtection);
  // THEN f_min is the lone plot's G(0)/N, f_max the corner plot's, and tau sits 1/10 up
  const double g0 = 1.0 / (2.0 * std::numbers::pi * 500.0 * 500.0);
  const double f_min = g0 / 4.0;
  const double f_max = g0 / 4.0 * (1.0 + 2.0 * std::exp(-100.0 * 100.0 / 500000.0));
  const double tau = f_min + 0.1 * (f_max - f_min);
  EXPECT_NEAR(r.threshold, tau, 1e-12 * tau);
  EXPECT_EQ(r.keep, (std::vector<std::uint8_t>{1, 1, 1, 0}));
  EXPECT_EQ(r.rejected, 1);
  EXPECT_EQ(r.cell, (std::vector<int>{0, 0, 0, -1}));
}

TEST(ClutterRejector, KdTreeDensityMatchesBruteForceWithinTruncationBound) {
  // GIVEN a random 3-D scan: 1500 uniform plots in a 20 km cube plus 5 blobs of 40
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0.0, 20e3);
  std::normal_distribution<double> n(0.0, 300.0);
  Points points;
  for (int i = 0; i < 1500; ++i) {
    const double x = u(rng);
    const double y = u(rng);
    points.emplace_back(x, y, u(rng));
  }
  for (int b = 0; b < 5; ++b) {
    const Eigen::Vector3d centre(4e3 * (b + 1), 10e3, 10e3);
    for (int i = 0; i < 40; ++i) {
      const double x = n(rng);
      const double y = n(rng);
      points.push_back(centre + Eigen::Vector3d(x, y, n(rng)));
    }
  }
  const double h = 1000.0;
  const double c = ClutterRejector::kDefaultTruncationSigmas;
  ClutterRejector rejector(enabled_spec(h));
  // WHEN the truncated k-d tree density is compared with the O(N^2) sum
  const ClutterRejectionResult& r = rejector.apply(points, 3, kNoProtection);
  const std::vector<double> exact = brute_force_density(points, h, 3);
  // THEN the truncation only drops mass, at most G(0) e^{-c^2/2} per plot beyond c h
  const double per_plot = truncation_error_bound(h, 3, c) / static_cast<double>(points.size());
  int outside_total = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    int outside = 0;
    for (const Eigen::Vector3d& q : points) {
      outside += (points[i] - q).norm() >= c * h ? 1 : 0;
    }
    outside_total += outside;
    EXPECT_LE(r.density[i], exact[i] * (1.0 + 1e-12));
    EXPECT_LE(exact[i] - r.density[i], outside * per_plot + 1e-12 * exact[i]);
  }
  EXPECT_GT(outside_total, 0);
  // AND with the radius far beyond every distance it equals the full sum to 1e-12
  ClutterRejector wide(enabled_spec(h), 40.0);
  const ClutterRejectionResult& w = wide.apply(points, 3, kNoProtection);
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_NEAR(w.density[i], exact[i], 1e-12 * exact[i]);
  }
}

}  // namespace
}  // namespace skytrack::clutter
