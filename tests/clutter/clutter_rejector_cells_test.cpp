// ClutterRejector mean-shift cells (eq. 9-10) and their measurement boxes (eq. 11).
#include "skytrack/clutter/clutter_rejector.hpp"

#include <cstddef>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "clutter_rejector_test_support.hpp"

namespace skytrack::clutter {
namespace {

using test::add_blob;
using test::clutter_and_clusters;
using test::ClutterScene;
using test::enabled_spec;
using test::kNoProtection;
using test::Points;

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

}  // namespace
}  // namespace skytrack::clutter
