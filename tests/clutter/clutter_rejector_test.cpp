// Tests of ClutterRejector, paper 000 §3.1: density (eq. 6-7), threshold (eq. 8),
// protection rule, mean-shift cells (eq. 9-10) and measurement boxes (eq. 11).
#include "skytrack/clutter/clutter_rejector.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

namespace skytrack::clutter {
namespace {

using Points = std::vector<Eigen::Vector3d>;
constexpr std::span<const std::uint8_t> kNoProtection{};

config::ClutterRejectionSpec enabled_spec(double h = 500.0) {
  config::ClutterRejectionSpec spec;
  spec.enabled = true;
  spec.kernel_bandwidth = h;
  spec.beta = 1;
  spec.n_f = 10;
  spec.mean_shift.bandwidth = h;
  return spec;
}

// Uniform plots over [0, side]^2 (z = 0).
void add_uniform(Points& points, int count, double side, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, side);
  for (int i = 0; i < count; ++i) {
    const double x = u(rng);
    points.emplace_back(x, u(rng), 0.0);
  }
}

// Gaussian blob of `count` plots with standard deviation sigma per axis (z = 0).
void add_blob(Points& points, const Eigen::Vector2d& centre, int count, double sigma,
              std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, sigma);
  for (int i = 0; i < count; ++i) {
    const double x = centre.x() + n(rng);
    points.emplace_back(x, centre.y() + n(rng), 0.0);
  }
}

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

// 100 km x 100 km, 2000 uniform clutter plots (2e-7 per m^2, about 0.3 neighbours within
// h = 500 m of a plot), plus 10 clusters of 20 plots with sigma = 100 m, 25 km apart.
struct ClutterScene {
  Points points;
  int clutter = 0;
};

ClutterScene clutter_and_clusters(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  ClutterScene scene;
  add_uniform(scene.points, 2000, 100e3, rng);
  scene.clutter = static_cast<int>(scene.points.size());
  for (int c = 0; c < 10; ++c) {
    const Eigen::Vector2d centre(12.5e3 + 25e3 * (c % 4), 12.5e3 + 25e3 * (c / 4));
    add_blob(scene.points, centre, 20, 100.0, rng);
  }
  return scene;
}

TEST(ClutterRejector, KeepsTightClustersAndRejectsMostUniformClutter) {
  // GIVEN the clutter-and-clusters scene with h = 500 m, beta = 1, n_f = 10
  const ClutterScene scene = clutter_and_clusters(7);
  ClutterRejector rejector(enabled_spec(500.0));
  // WHEN the scan is processed
  const ClutterRejectionResult& r = rejector.apply(scene.points, 2, kNoProtection);
  // THEN every cluster plot is kept and more than 95% of the clutter is rejected
  int clutter_rejected = 0;
  for (std::size_t i = 0; i < scene.points.size(); ++i) {
    if (static_cast<int>(i) < scene.clutter) {
      clutter_rejected += r.keep[i] == 0 ? 1 : 0;
    } else {
      EXPECT_EQ(r.keep[i], 1) << "cluster plot " << i;
    }
  }
  const double rejected_rate = static_cast<double>(clutter_rejected) / scene.clutter;
  RecordProperty("clutter_rejected_rate", std::to_string(rejected_rate));
  EXPECT_GT(rejected_rate, 0.95);
  // AND each cluster forms one cell of its own
  for (int c = 0; c < 10; ++c) {
    const auto first = static_cast<std::size_t>(scene.clutter + 20 * c);
    for (std::size_t i = first; i < first + 20; ++i) {
      EXPECT_EQ(r.cell[i], r.cell[first]);
    }
  }
}

TEST(ClutterRejector, NeverRejectsAProtectedPlot) {
  // GIVEN the clutter-and-clusters scene plus a lone plot 50 km from everything, and every
  // clutter plot and the lone plot marked as inside a confirmed track's gate
  ClutterScene scene = clutter_and_clusters(11);
  scene.points.emplace_back(150e3, 150e3, 0.0);
  std::vector<std::uint8_t> protection(scene.points.size(), 0);
  for (int i = 0; i < scene.clutter; ++i) {
    protection[static_cast<std::size_t>(i)] = 1;
  }
  protection.back() = 1;
  ClutterRejector rejector(enabled_spec(500.0));
  // WHEN the scan is processed
  const ClutterRejectionResult& r = rejector.apply(scene.points, 2, protection);
  // THEN nothing is rejected although the lone plot has the lowest density of the scan
  EXPECT_EQ(r.rejected, 0);
  EXPECT_LT(r.density.back(), r.threshold);
  EXPECT_EQ(r.keep.back(), 1);
  EXPECT_GE(r.cell.back(), 0);
  EXPECT_GT(r.protected_kept, scene.clutter / 2);
  // AND without protection the lone plot goes
  EXPECT_EQ(rejector.apply(scene.points, 2, kNoProtection).keep.back(), 0);
}

// The trade-off of docs/clutter_rejection.md: single-plot (point) targets in uniform clutter.
struct PointTargetCase {
  int clutter;       // uniform clutter plots over 100 km x 100 km
  bool with_groups;  // plus the 10 clusters of 20 plots of clutter_and_clusters()
  double min_target_rejection;
};

class PointTargets : public ::testing::TestWithParam<PointTargetCase> {};

TEST_P(PointTargets, AreRejectedAtTheClutterRate) {
  // GIVEN uniform clutter, optionally the 10 clusters, and 200 point targets (one plot
  // each) placed uniformly too; h = 500 m, beta = 1, n_f = 10
  const PointTargetCase& param = GetParam();
  std::mt19937_64 rng(53);
  Points points;
  add_uniform(points, param.clutter, 100e3, rng);
  const std::size_t first_target = points.size();
  add_uniform(points, 200, 100e3, rng);
  if (param.with_groups) {
    for (int c = 0; c < 10; ++c) {
      add_blob(points, {12.5e3 + 25e3 * (c % 4), 12.5e3 + 25e3 * (c / 4)}, 20, 100.0, rng);
    }
  }
  ClutterRejector rejector(enabled_spec(500.0));
  // WHEN the scan is processed
  const ClutterRejectionResult& r = rejector.apply(points, 2, kNoProtection);
  // THEN a target plot is rejected as often as a clutter plot: density cannot tell them apart
  int clutter_rejected = 0;
  int targets_rejected = 0;
  for (std::size_t i = 0; i < first_target + 200; ++i) {
    (i < first_target ? clutter_rejected : targets_rejected) += r.keep[i] == 0 ? 1 : 0;
  }
  const double clutter_rate = static_cast<double>(clutter_rejected) / param.clutter;
  const double target_rate = targets_rejected / 200.0;
  RecordProperty("clutter_rejected_rate", std::to_string(clutter_rate));
  RecordProperty("point_target_rejected_rate", std::to_string(target_rate));
  EXPECT_NEAR(target_rate, clutter_rate, 0.1);
  EXPECT_GE(target_rate, param.min_target_rejection);
}

// Lambda = clutter / 1e10 per m^2: 5e-8, 2e-7 and 1e-6.
INSTANTIATE_TEST_SUITE_P(
    ClutterRejector, PointTargets,
    ::testing::Values(PointTargetCase{500, true, 0.95}, PointTargetCase{2000, true, 0.95},
                      PointTargetCase{10000, true, 0.6}, PointTargetCase{500, false, 0.7},
                      PointTargetCase{2000, false, 0.45}, PointTargetCase{10000, false, 0.05}));

TEST(ClutterRejector, MeanShiftSeparatesTwoBlobsAndMergesEachIntoOneCell) {
  // GIVEN two blobs of 30 plots (sigma 80 m) 5 km apart, mean-shift bandwidth 500 m, and
  // the density threshold off so that mean-shift sees every plot (eq. 8 would drop the
  // outermost plots of each blob)
  std::mt19937_64 rng(3);
  Points points;
  add_blob(points, {0.0, 0.0}, 30, 80.0, rng);
  add_blob(points, {5000.0, 0.0}, 30, 80.0, rng);
  config::ClutterRejectionSpec spec = enabled_spec(500.0);
  spec.enabled = false;
  ClutterRejector rejector(spec);
  // WHEN the scan is processed
  const ClutterRejectionResult& r = rejector.apply(points, 2, kNoProtection);
  // THEN there are exactly two cells, labelled in order of first plot index
  ASSERT_EQ(r.cells, 2);
  ASSERT_EQ(r.boxes.size(), 2U);
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(r.cell[i], i < 30 ? 0 : 1);
  }
  // AND each box is the interval hull of its blob (eq. 11)
  for (int c = 0; c < 2; ++c) {
    Eigen::Vector3d lower = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector3d upper = -lower;
    for (std::size_t i = 30 * static_cast<std::size_t>(c); i < 30 * (c + 1U); ++i) {
      lower = lower.cwiseMin(points[i]);
      upper = upper.cwiseMax(points[i]);
    }
    EXPECT_EQ(r.boxes[static_cast<std::size_t>(c)].lower, lower);
    EXPECT_EQ(r.boxes[static_cast<std::size_t>(c)].upper, upper);
  }
}

TEST(ClutterRejector, MergeDistanceJoinsConvergedPoints) {
  // GIVEN the same two blobs but a merge distance larger than their separation
  std::mt19937_64 rng(3);
  Points points;
  add_blob(points, {0.0, 0.0}, 30, 80.0, rng);
  add_blob(points, {5000.0, 0.0}, 30, 80.0, rng);
  config::ClutterRejectionSpec spec = enabled_spec(500.0);
  spec.mean_shift.merge_distance = 6000.0;
  ClutterRejector rejector(spec);
  // WHEN the scan is processed
  const ClutterRejectionResult& r = rejector.apply(points, 2, kNoProtection);
  // THEN both blobs share one cell whose box spans both
  EXPECT_EQ(r.cells, 1);
  EXPECT_LT(r.boxes.at(0).lower.x(), 0.0);
  EXPECT_GT(r.boxes.at(0).upper.x(), 5000.0);
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

TEST(ClutterRejector, HandlesEmptyAndSinglePlotScans) {
  ClutterRejector rejector(enabled_spec());
  // GIVEN no plots WHEN processed THEN the result is empty
  const ClutterRejectionResult& empty = rejector.apply({}, 2, kNoProtection);
  EXPECT_TRUE(empty.keep.empty());
  EXPECT_TRUE(empty.density.empty());
  EXPECT_TRUE(empty.boxes.empty());
  EXPECT_EQ(empty.cells, 0);
  EXPECT_EQ(empty.rejected, 0);
  EXPECT_EQ(empty.threshold, 0.0);
  // GIVEN one plot WHEN processed THEN it is kept as a cell with a point box
  const Points one = {{10.0, 20.0, 30.0}};
  const ClutterRejectionResult& r = rejector.apply(one, 3, kNoProtection);
  EXPECT_EQ(r.keep, std::vector<std::uint8_t>{1});
  EXPECT_EQ(r.cells, 1);
  EXPECT_EQ(r.boxes.at(0).lower, one[0]);
  EXPECT_EQ(r.boxes.at(0).upper, one[0]);
  EXPECT_DOUBLE_EQ(r.threshold, r.density[0]);
}

TEST(ClutterRejector, KeepsEveryPlotWhenAllDensitiesAreEqual) {
  // GIVEN a 10 x 10 grid of plots 10 km apart: no neighbour within 3h, equal densities
  Points points;
  for (int i = 0; i < 100; ++i) {
    points.emplace_back(10e3 * (i % 10), 10e3 * (i / 10), 0.0);
  }
  ClutterRejector rejector(enabled_spec(500.0));
  // WHEN the scan is processed
  const ClutterRejectionResult& r = rejector.apply(points, 2, kNoProtection);
  // THEN nothing is rejected and every plot is its own cell
  EXPECT_EQ(r.rejected, 0);
  EXPECT_EQ(r.cells, 100);
  EXPECT_TRUE(std::isfinite(r.threshold));
}

TEST(ClutterRejector, RejectsNonFinitePlotsWithoutSpreadingNan) {
  // GIVEN a blob with one NaN plot and one plot with an infinite z used in 3-D
  std::mt19937_64 rng(5);
  Points points;
  add_blob(points, {0.0, 0.0}, 10, 50.0, rng);
  points.emplace_back(std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0);
  points.emplace_back(0.0, 0.0, std::numeric_limits<double>::infinity());
  ClutterRejector rejector(enabled_spec());
  // WHEN the scan is processed in 3-D
  const ClutterRejectionResult& r = rejector.apply(points, 3, kNoProtection);
  // THEN both are rejected, counted as invalid, and every number is finite
  EXPECT_EQ(r.invalid, 2);
  int below_tau = 0;
  for (std::size_t i = 0; i < 10; ++i) {
    below_tau += r.density[i] < r.threshold ? 1 : 0;
  }
  EXPECT_EQ(r.rejected, 2 + below_tau);
  EXPECT_EQ(r.keep[10], 0);
  EXPECT_EQ(r.keep[11], 0);
  EXPECT_EQ(r.cells, 1);
  for (const double d : r.density) {
    EXPECT_TRUE(std::isfinite(d));
  }
  EXPECT_TRUE(std::isfinite(r.threshold));
  // AND in 2-D the infinite z is ignored
  EXPECT_EQ(rejector.apply(points, 2, kNoProtection).invalid, 1);
}

TEST(ClutterRejector, TwoDimensionsIgnoresZ) {
  // GIVEN a scene, and the same scene with random heights
  const ClutterScene flat = clutter_and_clusters(19);
  Points lifted = flat.points;
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> z(-5e3, 5e3);
  for (Eigen::Vector3d& p : lifted) {
    p.z() = z(rng);
  }
  ClutterRejector a(enabled_spec());
  ClutterRejector b(enabled_spec());
  // WHEN both are processed in 2-D THEN the outcomes are identical and boxes are flat
  const ClutterRejectionResult& ra = a.apply(flat.points, 2, kNoProtection);
  const ClutterRejectionResult& rb = b.apply(lifted, 2, kNoProtection);
  EXPECT_EQ(ra.keep, rb.keep);
  EXPECT_EQ(ra.cell, rb.cell);
  EXPECT_EQ(ra.density, rb.density);
  for (const MeasurementBox& box : rb.boxes) {
    EXPECT_EQ(box.lower.z(), 0.0);
    EXPECT_EQ(box.upper.z(), 0.0);
  }
}

TEST(ClutterRejector, IsDeterministic) {
  // GIVEN one scene, two rejectors, and one of them used for an unrelated scan first
  const ClutterScene scene = clutter_and_clusters(29);
  const ClutterScene other = clutter_and_clusters(31);
  ClutterRejector first(enabled_spec());
  ClutterRejector second(enabled_spec());
  second.apply(other.points, 2, kNoProtection);
  // WHEN both process the scene
  const ClutterRejectionResult a = first.apply(scene.points, 2, kNoProtection);
  const ClutterRejectionResult& b = second.apply(scene.points, 2, kNoProtection);
  // THEN the outcomes are bit-identical
  EXPECT_EQ(a.keep, b.keep);
  EXPECT_EQ(a.cell, b.cell);
  EXPECT_EQ(a.density, b.density);
  EXPECT_EQ(a.threshold, b.threshold);
  ASSERT_EQ(a.boxes.size(), b.boxes.size());
  for (std::size_t c = 0; c < a.boxes.size(); ++c) {
    EXPECT_EQ(a.boxes[c].lower, b.boxes[c].lower);
    EXPECT_EQ(a.boxes[c].upper, b.boxes[c].upper);
  }
}

TEST(ClutterRejector, ReusesResultBuffersAcrossScans) {
  // GIVEN a rejector warmed up on one scan
  const ClutterScene scene = clutter_and_clusters(37);
  const ClutterScene next = clutter_and_clusters(41);
  ClutterRejector rejector(enabled_spec());
  const ClutterRejectionResult& r = rejector.apply(scene.points, 2, kNoProtection);
  const void* keep = r.keep.data();
  const void* cell = r.cell.data();
  const void* density = r.density.data();
  // WHEN a scan of the same size is processed
  rejector.apply(next.points, 2, kNoProtection);
  // THEN the per-plot buffers are the same allocations
  EXPECT_EQ(r.keep.data(), keep);
  EXPECT_EQ(r.cell.data(), cell);
  EXPECT_EQ(r.density.data(), density);
}

TEST(ClutterRejector, DisabledKeepsEveryPlotButStillPartitions) {
  // GIVEN clutter rejection switched off
  const ClutterScene scene = clutter_and_clusters(43);
  config::ClutterRejectionSpec spec = enabled_spec();
  spec.enabled = false;
  ClutterRejector rejector(spec);
  // WHEN the scan is processed THEN no plot is rejected and every plot has a cell
  const ClutterRejectionResult& r = rejector.apply(scene.points, 2, kNoProtection);
  EXPECT_EQ(r.rejected, 0);
  for (std::size_t i = 0; i < scene.points.size(); ++i) {
    EXPECT_GE(r.cell[i], 0);
  }
  EXPECT_GT(r.cells, 10);
}

TEST(ClutterRejector, RejectsAnInvalidSpecAtConstruction) {
  config::ClutterRejectionSpec spec = enabled_spec();
  spec.kernel_bandwidth = 0.0;
  EXPECT_THROW(ClutterRejector{spec}, std::invalid_argument);
  EXPECT_THROW(ClutterRejector(enabled_spec(), -1.0), std::invalid_argument);
}

}  // namespace
}  // namespace skytrack::clutter
