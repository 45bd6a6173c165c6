// The filter's per-scan path (LabeledBoxPhd::step on ready cells) must not touch the heap
// once its workspaces have grown to the scene: a counting malloc (tests/counting_malloc.hpp)
// counts every malloc in the process while the
// window is open. The preprocessing is not in the window: ClutterRejector rebuilds its k-d
// tree node pools every scan (docs/clutter_rejection.md).
#include <atomic>
#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "skytrack/group/labeled_box_phd.hpp"

#include "../counting_malloc.hpp"

namespace skytrack::group {
namespace {

// Three groups moving CV; each cell a 20 m box round the centroid with 15 plots.
std::vector<GroupCell> cells_at(double t) {
  std::vector<GroupCell> cells;
  const Eigen::Vector2d start[3] = {{0, 0}, {400, 0}, {0, 400}};
  const Eigen::Vector2d velocity[3] = {{20, 5}, {-10, 15}, {5, -20}};
  for (int g = 0; g < 3; ++g) {
    GroupCell c;
    c.mean = start[g] + t * velocity[g];
    c.box.lower = c.mean - Eigen::Vector2d(12.5, 12.5);
    c.box.upper = c.mean + Eigen::Vector2d(12.5, 12.5);
    c.scatter = Eigen::Matrix2d::Identity() * 33.0;
    c.plots = 15;
    cells.push_back(c);
  }
  return cells;
}

TEST(GroupAllocation, FilterStepAllocatesNothingInSteadyState) {
#if !SKYTRACK_COUNTING_MALLOC
  GTEST_SKIP() << "the counting malloc needs glibc and no sanitizer";
#else
  GroupSpec spec;
  spec.motion = GroupMotion::kConstantVelocity;
  LabeledBoxPhd filter(spec);
  std::vector<std::vector<GroupCell> > scans;
  for (int k = 0; k < 60; ++k) {
    scans.push_back(cells_at(k));
  }
  for (int k = 0; k < 40; ++k) {  // warm-up: the workspaces grow to the scene
    filter.step(k, scans[static_cast<std::size_t>(k)]);
  }
  ASSERT_EQ(filter.estimates().size(), 3U);
  g_allocations = 0;
  g_counting = true;
  for (int k = 40; k < 60; ++k) {
    filter.step(k, scans[static_cast<std::size_t>(k)]);
  }
  g_counting = false;
  EXPECT_EQ(g_allocations.load(), 0);
  EXPECT_EQ(filter.estimates().size(), 3U);
  // The counter does count: a heap vector is seen.
  g_counting = true;
  const auto* probe = new std::vector<double>(100);
  g_counting = false;
  EXPECT_GE(g_allocations.load(), 1);
  delete probe;
#endif
}

}  // namespace
}  // namespace skytrack::group
