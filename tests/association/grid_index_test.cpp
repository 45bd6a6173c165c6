#include "skytrack/association/grid_index.hpp"

#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "skytrack/association/plot_index.hpp"
#include "spatial_index_test_support.hpp"

namespace skytrack {
namespace {

// Uniform plots and a tight cluster: the cell side is only a hint of the query scale, so
// queries far larger or smaller than it, and crowded cells, must still answer exactly.
std::vector<Eigen::Vector3d> mixed_points(int n, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> xy(-5000.0, 5000.0), z(0.0, 2000.0), near(-20.0, 20.0);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < n; ++i) {
    if (i % 3 == 0) {
      // Each draw is its own step, last argument first: the order GCC used when the scenes were
      // measured (C++ leaves the evaluation order of arguments unspecified).
      const double height = z(rng), dy = near(rng), dx = near(rng);
      points.emplace_back(1000.0 + dx, -700.0 + dy, height);
    } else {
      const double height = z(rng), y = xy(rng), x = xy(rng);
      points.emplace_back(x, y, height);
    }
  }
  return points;
}

TEST(GridIndex, WithinMatchesBruteForceAndTheKdTreeAndMoreThanCountsItForAnyCellSide) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> xy(-6000.0, 6000.0), z(-200.0, 2200.0),
      radius(0.0, 3000.0);
  GridIndex grid;  // one grid, rebuilt with different sizes, dimensions and cell sides
  PlotIndex tree;
  std::vector<int> found, from_tree;
  for (const int n : {700, 3, 1500, 0, 1, 60}) {
    for (const int dims : {3, 2}) {
      for (const double cell : {1.0, 300.0, 2500.0, 1e6, 0.0}) {
        const std::vector<Eigen::Vector3d> points = mixed_points(n, rng);
        grid.build(points, dims, cell);
        tree.build(points, dims);
        for (int q = 0; q < 100; ++q) {
          const double height = z(rng), y = xy(rng), x = xy(rng);
          const Eigen::Vector3d centre(x, y, height);
          const double r = q % 10 == 0 ? 30.0 : radius(rng);  // some queries in the cluster
          const Eigen::Vector3d at = q % 10 == 0 ? points.empty() ? centre : points[0] : centre;
          grid.within(at, r, found);
          tree.within(at, r, from_tree);
          EXPECT_EQ(found, test::brute_force_within(points, dims, at, r))
              << n << " plots, " << dims << " dims, cell " << cell;
          EXPECT_EQ(found, from_tree);
          const int count = q % 7;  // at, below and above the number found
          EXPECT_EQ(grid.more_than(at, r, count), static_cast<int>(found.size()) > count);
        }
      }
    }
  }
}

TEST(GridIndex, RadiusIsInclusiveTwoDimsIgnoresHeightAndBadInputFindsNothing) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Eigen::Vector3d> points = {
      {3.0, 4.0, 0.0}, {0.0, 0.0, 100.0}, {6.0, 0.0, 0.0}, {nan, 0.0, 0.0}};
  GridIndex grid;
  std::vector<int> found{42};
  grid.within(Eigen::Vector3d::Zero(), 10.0, found);  // never built
  EXPECT_TRUE(found.empty());
  grid.build(points, 3, 2.0);
  grid.within(Eigen::Vector3d::Zero(), 5.0, found);  // (3, 4, 0) is exactly 5 away
  EXPECT_EQ(found, (std::vector<int>{0}));
  grid.build(points, 2, 2.0);
  grid.within(Eigen::Vector3d::Zero(), 5.0, found);  // height no longer counts
  EXPECT_EQ(found, (std::vector<int>{0, 1}));
  grid.within(Eigen::Vector3d(1e300, -1e300, 0.0), 1e200, found);  // far off: no overflow
  EXPECT_TRUE(found.empty());
  grid.within(Eigen::Vector3d::Zero(), -1.0, found);
  EXPECT_TRUE(found.empty());
  grid.within(Eigen::Vector3d::Zero(), nan, found);
  EXPECT_TRUE(found.empty());
  grid.within(Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), 1.0, found);
  EXPECT_TRUE(found.empty());
  grid.within(Eigen::Vector3d(6.0, 0.0, 0.0), 0.0, found);  // radius 0 finds a plot on top
  EXPECT_EQ(found, (std::vector<int>{2}));
  EXPECT_TRUE(grid.more_than(Eigen::Vector3d::Zero(), 5.0, 1));  // (3, 4) and (0, 0)
  EXPECT_FALSE(grid.more_than(Eigen::Vector3d::Zero(), 5.0, 2));
  EXPECT_FALSE(grid.more_than(Eigen::Vector3d::Zero(), nan, 0));
  EXPECT_FALSE(GridIndex{}.more_than(Eigen::Vector3d::Zero(), 10.0, 0));  // never built
}

}  // namespace
}  // namespace skytrack
