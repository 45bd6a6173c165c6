// Mean-shift partitions and measurement boxes (paper 000 §3.1 steps 2-3, eq. 9-11).
#include "skytrack/clutter/mean_shift_partition.hpp"

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "skytrack/group/group_spec.hpp"

namespace skytrack::clutter {
namespace {

TEST(IntervalHull, ComponentwiseMinMax) {
  const std::vector<Eigen::Vector3d> p = {{1, 5, 9}, {3, -2, 7}, {std::nan(""), 0, 0}, {2, 0, 1}};
  const std::vector<int> idx = {0, 1, 2, 3, 17, -1};  // NaN and out-of-range skipped
  const MeasurementBox b = interval_hull(p, idx, 2);
  EXPECT_EQ(b.lower, Eigen::Vector3d(1, -2, 0));
  EXPECT_EQ(b.upper, Eigen::Vector3d(3, 5, 0));
  const MeasurementBox b3 = interval_hull(p, idx, 3);
  EXPECT_EQ(b3.lower.z(), 1.0);
  EXPECT_EQ(b3.upper.z(), 9.0);
  const MeasurementBox empty = interval_hull(p, std::vector<int>{}, 2);
  EXPECT_EQ(empty.lower, Eigen::Vector3d::Zero());
}

// Two groups of 15 plots (uniform +-10 m) 300 m apart and 10 clutter plots over 2 km x 2 km:
// with the group defaults, the clutter is rejected and each group is one partition whose box
// is the hull of exactly its plots.
TEST(MeanShiftPartitioner, TwoGroupsInClutter) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> spread(-10.0, 10.0);
  std::uniform_real_distribution<double> area(-1000.0, 1000.0);
  std::vector<Eigen::Vector3d> p;
  for (const Eigen::Vector2d& c : {Eigen::Vector2d(0, 0), Eigen::Vector2d(300, 0)}) {
    for (int i = 0; i < 15; ++i) {
      // Each draw is its own step, last argument first: the order GCC used when the scenes were
      // measured (C++ leaves the evaluation order of arguments unspecified).
      const double dy = spread(rng), dx = spread(rng);
      p.emplace_back(c.x() + dx, c.y() + dy, 0.0);
    }
  }
  for (int i = 0; i < 10; ++i) {
    const double x = area(rng);
    p.emplace_back(x, 500.0 + 0.5 * area(rng), 0.0);  // y in [0, 1000]: none near the groups
  }
  MeanShiftPartitioner partitioner(group::GroupSpec::default_preprocessing());
  const auto& parts = partitioner.partition(p, 2);
  ASSERT_EQ(parts.size(), 2U);
  for (int g = 0; g < 2; ++g) {
    std::vector<int> expected;
    for (int i = 0; i < 15; ++i) {
      expected.push_back(15 * g + i);
    }
    EXPECT_EQ(parts[static_cast<std::size_t>(g)].plots, expected);
    const MeasurementBox hull = interval_hull(p, expected, 2);
    EXPECT_EQ(parts[static_cast<std::size_t>(g)].box.lower, hull.lower);
    EXPECT_EQ(parts[static_cast<std::size_t>(g)].box.upper, hull.upper);
  }
  EXPECT_EQ(partitioner.rejection().rejected, 10);
}

TEST(MeanShiftPartitioner, EmptyAndNonFiniteScans) {
  MeanShiftPartitioner partitioner(group::GroupSpec::default_preprocessing());
  EXPECT_TRUE(partitioner.partition(std::vector<Eigen::Vector3d>{}, 2).empty());
  const std::vector<Eigen::Vector3d> bad = {{std::nan(""), 0, 0}, {0, INFINITY, 0}};
  EXPECT_TRUE(partitioner.partition(bad, 2).empty());
}

TEST(PartitionsFromCells, ReusesOutput) {
  ClutterRejectionResult r;
  r.cell = {1, -1, 0, 1};
  r.cells = 2;
  r.boxes.resize(2);
  r.boxes[1].upper = Eigen::Vector3d(1, 2, 0);
  std::vector<PlotPartition> out(5);
  partitions_from_cells(r, out);
  ASSERT_EQ(out.size(), 2U);
  EXPECT_EQ(out[0].plots, std::vector<int>{2});
  EXPECT_EQ(out[1].plots, (std::vector<int>{0, 3}));
  EXPECT_EQ(out[1].box.upper, Eigen::Vector3d(1, 2, 0));
}

}  // namespace
}  // namespace skytrack::clutter
