// ClutterRejector on clutter scenes: clusters kept, protected plots kept, point targets lost.
#include "skytrack/clutter/clutter_rejector.hpp"

#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "clutter_rejector_test_support.hpp"

namespace skytrack::clutter {
namespace {

using test::add_blob;
using test::add_uniform;
using test::clutter_and_clusters;
using test::ClutterScene;
using test::enabled_spec;
using test::kNoProtection;
using test::Points;

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

}  // namespace
}  // namespace skytrack::clutter
