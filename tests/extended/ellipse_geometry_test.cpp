// Hand-computed steps of paper 002's ellipse geometry: the Minkowski sum bound (Theorems
// 3-4), the Graham scan, the enclosing ellipse of a known hull and the Minkowski difference.
#include "skytrack/extended/ellipse_geometry.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/LU>

namespace skytrack::extended {
namespace {

TEST(MinkowskiSumBound, MinimumTraceParameterAndShapeByHand) {
  // GIVEN S1 = diag(4, 0) + ... tr S1 = 8, tr S2 = 2, so p = sqrt(8 / 2) = 2 (eq. 19)
  const Eigen::Matrix2d S1 = Eigen::Vector2d(4.0, 4.0).asDiagonal();
  const Eigen::Matrix2d S2 = Eigen::Vector2d(1.0, 1.0).asDiagonal();
  const SumBound<Eigen::Matrix2d> bound = minkowski_sum_bound(S1, S2);
  EXPECT_DOUBLE_EQ(bound.p, 2.0);
  // THEN S = 1.5 S1 + 3 S2 = diag(9, 9): the circle of radius 3 = 2 + 1, exact for circles.
  EXPECT_NEAR(bound.shape(0, 0), 9.0, 1e-12);
  EXPECT_NEAR(bound.shape(1, 1), 9.0, 1e-12);
  EXPECT_NEAR(bound.shape(0, 1), 0.0, 1e-12);
}

TEST(MinkowskiSumBound, ContainsEverySumOfBoundaryPoints) {
  // GIVEN two rotated ellipses, THEN every a + b (a in E1, b in E2) lies in E(0, S(p)).
  const Eigen::Matrix2d S1 = shape_from_axes(5.0, 1.0, 0.3);
  const Eigen::Matrix2d S2 = shape_from_axes(3.0, 2.0, -1.0);
  const Eigen::Matrix2d S = minkowski_sum_bound(S1, S2).shape;
  std::vector<Eigen::Vector2d> a, b;
  append_ellipse_boundary(Eigen::Vector2d::Zero(), S1, 72, a);
  append_ellipse_boundary(Eigen::Vector2d::Zero(), S2, 72, b);
  const Eigen::Matrix2d inv = S.inverse();
  for (const auto& p : a) {
    for (const auto& q : b) EXPECT_LE((p + q).dot(inv * (p + q)), 1.0 + 1e-9);
  }
  // AND its trace is no larger than with p = 1 (Theorem 4 minimises it).
  EXPECT_LE(S.trace(), (2.0 * S1 + 2.0 * S2).trace() + 1e-12);
}

TEST(ConvexHull, GrahamScanKeepsTheCornersCounterClockwise) {
  // GIVEN a square's corners, its centre, and points on its edges
  const std::vector<Eigen::Vector2d> points = {{0, 0}, {2, 0}, {1, 0}, {2, 2}, {1, 1},
                                               {0, 2}, {0, 1}, {2, 1}, {1, 2}, {1.5, 0.5}};
  std::vector<Eigen::Vector2d> hull;
  convex_hull(points, hull);
  // THEN only the four corners, from the lowest-leftmost, counter-clockwise.
  ASSERT_EQ(hull.size(), 4u);
  EXPECT_EQ(hull[0], Eigen::Vector2d(0, 0));
  EXPECT_EQ(hull[1], Eigen::Vector2d(2, 0));
  EXPECT_EQ(hull[2], Eigen::Vector2d(2, 2));
  EXPECT_EQ(hull[3], Eigen::Vector2d(0, 2));
}

TEST(EnclosingEllipse, OfARectangleIsTheEllipseThroughItsCorners) {
  // GIVEN the hull of a rectangle with half-sides 3 and 1 centred at (10, -5): by symmetry
  // the minimum-area ellipse through its corners has semi-axes 3 sqrt 2 and sqrt 2.
  const std::vector<Eigen::Vector2d> hull = {{7, -6}, {13, -6}, {13, -4}, {7, -4}};
  const Ellipse e = minimum_enclosing_ellipse(hull, 1e-10);
  EXPECT_NEAR(e.centre.x(), 10.0, 1e-6);
  EXPECT_NEAR(e.centre.y(), -5.0, 1e-6);
  EXPECT_NEAR(e.shape(0, 0), 18.0, 1e-5);
  EXPECT_NEAR(e.shape(1, 1), 2.0, 1e-5);
  EXPECT_NEAR(e.shape(0, 1), 0.0, 1e-5);
}

TEST(EnclosingEllipse, ContainsEveryPointOfARandomishCloud) {
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i < 40; ++i) {
    points.emplace_back(std::sin(1.3 * i) * 50.0 + 0.1 * i, std::cos(2.7 * i) * 10.0);
  }
  const Ellipse e = minimum_enclosing_ellipse(points, 1e-9);
  const Eigen::Matrix2d inv = e.shape.inverse();
  for (const auto& p : points) {
    EXPECT_LE((p - e.centre).dot(inv * (p - e.centre)), 1.0 + 1e-6);
  }
}

TEST(MinkowskiDifference, OfConcentricCirclesSubtractsTheRadii) {
  const DifferenceResult d =
      minkowski_difference(Eigen::Matrix2d::Identity() * 25.0, Eigen::Matrix2d::Identity() * 4.0);
  ASSERT_FALSE(d.empty);
  EXPECT_NEAR(d.shape(0, 0), 9.0, 1e-9);  // (5 - 2)^2
  EXPECT_NEAR(d.shape(1, 1), 9.0, 1e-9);
}

TEST(MinkowskiDifference, OfHomotheticEllipsesIsTheScaledEllipse) {
  // GIVEN E1 with semi-axes 10, 5 and E2 with 4, 2, both rotated by 30 degrees. The affine
  // map turns E2 into a circle of radius 2 and E1 into one of radius 5 (eq. 43-44), the
  // offset curve is the circle of radius 3 (eq. 45), mapped back: semi-axes 6, 3 (eq. 46).
  const double angle = std::numbers::pi / 6.0;
  const DifferenceResult d =
      minkowski_difference(shape_from_axes(10.0, 5.0, angle), shape_from_axes(4.0, 2.0, angle));
  ASSERT_FALSE(d.empty);
  const EllipseAxes axes = ellipse_axes(d.shape);
  EXPECT_NEAR(axes.major, 6.0, 1e-3);
  EXPECT_NEAR(axes.minor, 3.0, 1e-3);
  EXPECT_NEAR(std::remainder(axes.orientation - angle, std::numbers::pi), 0.0, 0.03);
}

TEST(MinkowskiDifference, OfAnEllipseByACircleShrinksEachAxisByTheRadius) {
  // GIVEN E1 axis-aligned with semi-axes 20, 10 and a circle of radius 3 (3 < 10^2 / 20 =
  // the smallest radius of curvature, so the offset curve has no cusp): THEN the vertices
  // of the difference are at 17 and 7 on the axes.
  const DifferenceResult d = minkowski_difference(shape_from_axes(20.0, 10.0, 0.0),
                                                  Eigen::Matrix2d::Identity() * 9.0, 720);
  const EllipseAxes axes = ellipse_axes(d.shape);
  EXPECT_NEAR(axes.major, 17.0, 1e-6);
  EXPECT_NEAR(axes.minor, 7.0, 1e-6);
}

TEST(MinkowskiDifference, IsEmptyWhenTheSecondDoesNotFit) {
  EXPECT_TRUE(
      minkowski_difference(shape_from_axes(20.0, 2.0, 0.0), Eigen::Matrix2d::Identity() * 9.0)
          .empty);
  // AND subtracting a point changes nothing.
  const Eigen::Matrix2d E1 = shape_from_axes(4.0, 1.0, 0.5);
  EXPECT_TRUE(minkowski_difference(E1, Eigen::Matrix2d::Zero()).shape.isApprox(E1));
}

}  // namespace
}  // namespace skytrack::extended
