#pragma once
// Ellipse geometry of SMF-EOT (paper 002, Liu et al. 2023, section 2): an ellipsoid
// E(c, S) = {y : (y - c)' S^-1 (y - c) <= 1} is a centre and a shape matrix S (its semi-axes
// are sqrt(eig S)); the extent X of an object is such a shape matrix [m^2].
//   - the minimum-trace bound of a Minkowski sum (Theorems 3-4, eq. 9, 19);
//   - the convex hull of a point set by Graham scan (eq. 40, Graham 1972);
//   - the minimum-area ellipse enclosing a point set (the hull's enclosing ellipse of eq. 41;
//     Khachiyan's algorithm, Todd & Yildirim 2007);
//   - the concentric Minkowski difference E1 (-) E2 in closed form: an affine map makes E2 a
//     circle, the offset curve of E1 by its radius is the boundary, mapped back (eq. 42-48,
//     Yan & Chirikjian 2014).
#include <cmath>
#include <span>
#include <vector>

#include <Eigen/Core>

namespace skytrack::extended {

/// Theorem 3-4: E(c1, S1) (+) E(c2, S2) is contained in E(c1 + c2, (1 + 1/p) S1 + (1 + p) S2)
/// for any p > 0; p = sqrt(tr S1 / tr S2) gives the bound of least trace.
template <class Matrix>
struct SumBound {
  Matrix shape;
  double p = 1.0;
};

template <class Matrix>
SumBound<Matrix> minkowski_sum_bound(const Matrix& S1, const Matrix& S2) noexcept {
  const double t1 = S1.trace();
  const double t2 = S2.trace();
  if (!(t1 > 0.0)) return {S2, 0.0};  // a point plus an ellipse is that ellipse
  if (!(t2 > 0.0)) return {S1, 0.0};
  const double p = std::sqrt(t1 / t2);
  return {Matrix((1.0 + 1.0 / p) * S1 + (1.0 + p) * S2), p};
}

struct Ellipse {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  Eigen::Matrix2d shape = Eigen::Matrix2d::Zero();  // [m^2]
};

/// `count` points on the boundary of E(centre, shape), appended to `out`.
void append_ellipse_boundary(const Eigen::Vector2d& centre, const Eigen::Matrix2d& shape, int count,
                             std::vector<Eigen::Vector2d>& out);

/// Graham scan: the hull's vertices counter-clockwise from the lowest point (lowest x on a
/// tie), collinear points dropped. Fewer than 3 distinct points: those points. `hull` is
/// overwritten; `points` is not changed.
void convex_hull(std::span<const Eigen::Vector2d> points, std::vector<Eigen::Vector2d>& hull);

/// The minimum-area ellipse containing the points (their hull's enclosing ellipse), to a
/// relative tolerance `tolerance` of Khachiyan's iteration. Fewer than 3 affinely
/// independent points give a degenerate (rank-deficient) shape through them.
Ellipse minimum_enclosing_ellipse(std::span<const Eigen::Vector2d> points, double tolerance = 1e-7,
                                  int max_iterations = 5000);

struct DifferenceResult {
  Eigen::Matrix2d shape = Eigen::Matrix2d::Zero();
  bool empty = false;  // E2 does not fit inside E1: no centre keeps it inside
};

/// E1 (-) E2 = the centres of all translates of E2 inside E1 (both centred at the origin),
/// eq. 42-48: T = R2 diag(b2/a2, 1) R2' turns E2 into a circle of radius b2; the boundary of
/// T E1 offset inwards by b2 along its normal (eq. 45), mapped back by T^-1 (eq. 46), is the
/// difference's boundary. Like the paper, we return the ellipse whose semi-axes are the
/// longest and shortest centre-to-boundary distances, along the longest one (exact when the
/// difference is an ellipse, e.g. homothetic E1, E2 or a circle from a circle). `samples`
/// boundary points.
DifferenceResult minkowski_difference(const Eigen::Matrix2d& E1, const Eigen::Matrix2d& E2,
                                      int samples = 256) noexcept;

/// Semi-axes (major first) [m] and orientation of the major axis [rad, from x towards y].
struct EllipseAxes {
  double major = 0.0;
  double minor = 0.0;
  double orientation = 0.0;
};
EllipseAxes ellipse_axes(const Eigen::Matrix2d& shape) noexcept;
Eigen::Matrix2d shape_from_axes(double major, double minor, double orientation) noexcept;

}  // namespace skytrack::extended
