// SMF-EOT leaves out plots inconsistent with one object (SmfSpec::outlier_margin,
// smf_eot.cpp): a stray plot does not grow the hull.
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "skytrack/extended/ellipse_geometry.hpp"
#include "skytrack/extended/smf_eot.hpp"

namespace skytrack::extended {
namespace {

// n plots uniform over a 100 m x 25 m ellipse at the origin, noise uniform in a 5 m disc.
std::vector<Eigen::Vector2d> object_plots(int n, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Eigen::Vector2d> plots;
  for (int i = 0; i < n; ++i) {
    const double r = std::sqrt(u(rng)), phi = 2.0 * std::numbers::pi * u(rng);
    const double rn = 5.0 * std::sqrt(u(rng)), pn = 2.0 * std::numbers::pi * u(rng);
    plots.push_back({100.0 * r * std::cos(phi) + rn * std::cos(pn),
                     25.0 * r * std::sin(phi) + rn * std::sin(pn)});
  }
  return plots;
}

// A track on the object (prior extent its own ellipse) after one scan of its 10 plots and,
// when `stray`, a clutter plot 600 m beside it.
ExtendedObject updated(double outlier_margin, bool stray) {
  SmfSpec spec;
  spec.outlier_margin = outlier_margin;
  ExtendedObject object;
  object.P = KinVec(400.0, 25.0, 400.0, 25.0, 0.25, 0.25).asDiagonal();
  object.S = object.P;
  object.extent = shape_from_axes(100.0, 25.0, 0.0);
  std::mt19937_64 rng(3);
  std::vector<Eigen::Vector2d> plots = object_plots(10, rng);
  if (stray) plots.push_back({0.0, 600.0});
  SmfWorkspace workspace;
  EXPECT_EQ(smf_update(spec, object, plots, Eigen::Matrix2d::Identity() * 25.0, workspace),
            UpdateStatus::kUpdated);
  return object;
}

TEST(SmfOutlier, StrayPlotDoesNotEnterTheHull) {
  // GIVEN the track and a stray plot 600 m off, beyond 2 x 2 x 100 m + 2 x 5 m of every
  // object plot; WHEN one scan updates it without and with the outlier rule
  const ExtendedObject free = updated(0.0, true);
  const ExtendedObject robust = updated(2.0, true);
  // THEN without it the hull reaches the stray plot: a semi-axis over 250 m
  EXPECT_GT(ellipse_axes(free.extent).major, 250.0);
  // and with it the extent is the object's alone (the inner estimate of 10 plots: the major
  // semi-axis 60-105 % of 100 m, the minor under 40 m) and the centre is not dragged
  const EllipseAxes axes = ellipse_axes(robust.extent);
  EXPECT_GT(axes.major, 60.0);
  EXPECT_LT(axes.major, 105.0);
  EXPECT_LT(axes.minor, 40.0);
  EXPECT_LT(std::hypot(robust.x[0], robust.x[2]), 20.0);
  EXPECT_GT(std::abs(free.x[2]), 20.0);
}

TEST(SmfOutlier, ObjectAloneIsUnchanged) {
  // GIVEN only the object's plots WHEN the rule is on THEN no plot leaves: same update
  const ExtendedObject free = updated(0.0, false);
  const ExtendedObject robust = updated(2.0, false);
  EXPECT_EQ(robust.extent, free.extent);
  EXPECT_EQ(robust.x, free.x);
}

TEST(SmfOutlier, TwoPlotsAreKept) {
  // GIVEN two plots 1 km apart (no majority to tell the stray) WHEN the rule is on THEN both
  // enter: the same update as without it
  SmfSpec robust_spec, free_spec;
  free_spec.outlier_margin = 0.0;
  ExtendedObject a;
  a.P = KinMat::Identity() * 100.0;
  a.S = a.P;
  a.extent = shape_from_axes(100.0, 25.0, 0.0);
  ExtendedObject b = a;
  const std::vector<Eigen::Vector2d> plots = {{0.0, 0.0}, {1000.0, 0.0}};
  SmfWorkspace workspace;
  const Eigen::Matrix2d U = Eigen::Matrix2d::Identity() * 25.0;
  smf_update(robust_spec, a, plots, U, workspace);
  smf_update(free_spec, b, plots, U, workspace);
  EXPECT_EQ(a.extent, b.extent);
  EXPECT_EQ(a.x, b.x);
}

}  // namespace
}  // namespace skytrack::extended
