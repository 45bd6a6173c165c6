#include "skytrack/association/plot_index.hpp"

#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "spatial_index_test_support.hpp"

namespace skytrack {
namespace {

std::vector<Eigen::Vector3d> random_points(int n, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> xy(-5000.0, 5000.0), z(0.0, 2000.0);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < n; ++i) {
    // Each draw is its own step, last argument first: the order GCC used when the scenes were
    // measured (C++ leaves the evaluation order of arguments unspecified).
    const double height = z(rng), y = xy(rng), x = xy(rng);
    points.emplace_back(x, y, height);
  }
  return points;
}

TEST(PlotIndex, WithinMatchesBruteForceIn2dAnd3dAcrossRebuilds) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> xy(-5500.0, 5500.0), z(-200.0, 2200.0),
      radius(0.0, 1500.0);
  PlotIndex index;  // one index, rebuilt per scan with different sizes and dimensions
  std::vector<int> found;
  for (const int n : {500, 3, 1200, 0, 40}) {
    for (const int dims : {3, 2}) {
      const std::vector<Eigen::Vector3d> points = random_points(n, rng);
      index.build(points, dims);
      ASSERT_EQ(index.size(), n);
      ASSERT_EQ(index.dims(), dims);
      for (int q = 0; q < 200; ++q) {
        const double height = z(rng), y = xy(rng), x = xy(rng);
        const Eigen::Vector3d centre(x, y, height);
        const double r = radius(rng);
        index.within(centre, r, found);
        EXPECT_EQ(found, test::brute_force_within(points, dims, centre, r))
            << n << " plots, " << dims;
      }
    }
  }
}

TEST(PlotIndex, RadiusIsInclusiveAndTwoDimsIgnoresHeight) {
  const std::vector<Eigen::Vector3d> points = {{3.0, 4.0, 0.0}, {0.0, 0.0, 100.0}, {6.0, 0.0, 0.0}};
  PlotIndex index;
  std::vector<int> found;
  index.build(points, 3);
  index.within(Eigen::Vector3d::Zero(), 5.0, found);  // (3, 4, 0) is exactly 5 away
  EXPECT_EQ(found, (std::vector<int>{0}));
  index.build(points, 2);
  index.within(Eigen::Vector3d::Zero(), 5.0, found);  // height no longer counts
  EXPECT_EQ(found, (std::vector<int>{0, 1}));
}

TEST(PlotIndex, EmptyIndexAndInvalidQueriesGiveNothing) {
  PlotIndex index;
  std::vector<int> found = {7};
  index.within(Eigen::Vector3d::Zero(), 10.0, found);  // never built
  EXPECT_TRUE(found.empty());
  const std::vector<Eigen::Vector3d> points = {{0.0, 0.0, 0.0}};
  index.build(points, 3);
  index.within(Eigen::Vector3d::Zero(), -1.0, found);
  EXPECT_TRUE(found.empty());
  index.within(Eigen::Vector3d::Zero(), std::numeric_limits<double>::quiet_NaN(), found);
  EXPECT_TRUE(found.empty());
  index.within(Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), 1.0, found);
  EXPECT_TRUE(found.empty());
  index.within(Eigen::Vector3d::Zero(), 0.0, found);  // radius 0 still finds a plot on top
  EXPECT_EQ(found, (std::vector<int>{0}));
}

}  // namespace
}  // namespace skytrack
