// ClutterRejector on degenerate input, determinism, buffer reuse and invalid specs.
#include "skytrack/clutter/clutter_rejector.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
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

TEST(ClutterRejector, RejectsAnInvalidSpecAtConstruction) {
  config::ClutterRejectionSpec spec = enabled_spec();
  spec.kernel_bandwidth = 0.0;
  EXPECT_THROW(ClutterRejector{spec}, std::invalid_argument);
  EXPECT_THROW(ClutterRejector(enabled_spec(), -1.0), std::invalid_argument);
}

}  // namespace
}  // namespace skytrack::clutter
