// Ellipse geometry of SMF-EOT (see ellipse_geometry.hpp; paper 002 eq. 9, 19, 40-48).
#include "skytrack/extended/ellipse_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>

namespace skytrack::extended {
namespace {

double cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// A symmetric square root S^{1/2} of a PSD 2x2 matrix (negative eigenvalues clamped).
Eigen::Matrix2d sqrt_psd(const Eigen::Matrix2d& S) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(S);
  const Eigen::Vector2d roots = eig.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  return eig.eigenvectors() * roots.asDiagonal() * eig.eigenvectors().transpose();
}

}  // namespace

EllipseAxes ellipse_axes(const Eigen::Matrix2d& shape) noexcept {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(0.5 * (shape + shape.transpose()));
  const Eigen::Vector2d l = eig.eigenvalues().cwiseMax(0.0);  // ascending
  const Eigen::Vector2d v = eig.eigenvectors().col(1);
  return {std::sqrt(l[1]), std::sqrt(l[0]), std::atan2(v.y(), v.x())};
}

Eigen::Matrix2d shape_from_axes(double major, double minor, double orientation) noexcept {
  const double c = std::cos(orientation), s = std::sin(orientation);
  Eigen::Matrix2d R;
  R << c, -s, s, c;
  return R * Eigen::Vector2d(major * major, minor * minor).asDiagonal() * R.transpose();
}

void append_ellipse_boundary(const Eigen::Vector2d& centre, const Eigen::Matrix2d& shape, int count,
                             std::vector<Eigen::Vector2d>& out) {
  const Eigen::Matrix2d root = sqrt_psd(shape);
  for (int i = 0; i < count; ++i) {
    const double phi = 2.0 * std::numbers::pi * i / count;
    out.emplace_back(centre + root * Eigen::Vector2d(std::cos(phi), std::sin(phi)));
  }
}

void convex_hull(std::span<const Eigen::Vector2d> points, std::vector<Eigen::Vector2d>& hull) {
  hull.clear();
  if (points.empty()) return;
  // Pivot a0: the lowest point; every other point sorted by its polar angle about a0 (eq. 40,
  // compared by cross products rather than arccos), nearer first on equal angles.
  std::vector<Eigen::Vector2d> sorted(points.begin(), points.end());
  const auto pivot_it = std::min_element(sorted.begin(), sorted.end(), [](auto& a, auto& b) {
    return a.y() < b.y() || (a.y() == b.y() && a.x() < b.x());
  });
  std::iter_swap(sorted.begin(), pivot_it);
  const Eigen::Vector2d a0 = sorted.front();
  std::sort(sorted.begin() + 1, sorted.end(), [&a0](const auto& a, const auto& b) {
    const double c = cross(a0, a, b);
    if (c != 0.0) return c > 0.0;
    return (a - a0).squaredNorm() < (b - a0).squaredNorm();
  });
  // The scan keeps a point while the turn through it is counter-clockwise (sigma > 0).
  for (const Eigen::Vector2d& p : sorted) {
    while (hull.size() >= 2 && cross(hull[hull.size() - 2], hull.back(), p) <= 0.0) {
      hull.pop_back();
    }
    if (hull.empty() || p != hull.back()) hull.push_back(p);
  }
}

Ellipse minimum_enclosing_ellipse(std::span<const Eigen::Vector2d> points, double tolerance,
                                  int max_iterations) {
  const int n = static_cast<int>(points.size());
  if (n == 0) return {};
  if (n < 3) {  // a point or a segment: the degenerate ellipse through them
    Ellipse e;
    e.centre = 0.5 * (points.front() + points.back());
    const Eigen::Vector2d half = 0.5 * (points.back() - points.front());
    e.shape = half * half.transpose();
    return e;
  }
  // Khachiyan's algorithm with Wolfe-Atwood away steps (Todd & Yildirim 2007): weights u on
  // the points lifted to q = (p, 1); the optimum's ellipse is E(c, d (sum u p p' - c c')),
  // c = sum u p, d = 2. An away step lowers the weight of the point deepest inside, which
  // makes the convergence linear instead of O(1 / tolerance).
  constexpr double kLifted = 3.0;  // d + 1
  // Work about the points' mean and in units of their spread: the lifted (p, 1) are then
  // well conditioned wherever the object is.
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& p : points) origin += p;
  origin /= n;
  double scale = 0.0;
  for (const Eigen::Vector2d& p : points)
    scale = std::max(scale, (p - origin).cwiseAbs().maxCoeff());
  if (!(scale > 0.0) || !std::isfinite(scale)) scale = 1.0;
  std::vector<Eigen::Vector3d> q(n);
  for (int i = 0; i < n; ++i) q[i] << (points[i] - origin) / scale, 1.0;

  std::vector<double> u(n, 1.0 / n), m(n, 0.0);
  Eigen::Matrix3d X = Eigen::Matrix3d::Zero();
  for (int i = 0; i < n; ++i) X.noalias() += u[i] * q[i] * q[i].transpose();
  Eigen::Matrix3d X_inv;
  for (int it = 0; it < max_iterations; ++it) {
    if (it % 64 == 0) {  // m_i = q_i' X^-1 q_i afresh now and then; updated in between
      bool invertible = false;
      X.computeInverseWithCheck(X_inv, invertible);
      if (!invertible) break;
      for (int i = 0; i < n; ++i) m[i] = q[i].dot(X_inv * q[i]);
    }
    int j = 0, i_min = -1;
    double m_max = -1.0, m_min = std::numeric_limits<double>::infinity();
    for (int i = 0; i < n; ++i) {
      if (m[i] > m_max) m_max = m[i], j = i;
      if (u[i] > 0.0 && m[i] < m_min) m_min = m[i], i_min = i;
    }
    const double gap_up = m_max / kLifted - 1.0;
    const double gap_down = i_min >= 0 ? 1.0 - m_min / kLifted : 0.0;
    if (!(std::max(gap_up, gap_down) > tolerance)) break;
    int k = j;
    double step = 0.0;
    if (gap_up >= gap_down) {
      step = (m_max - kLifted) / (kLifted * (m_max - 1.0));
    } else {
      k = i_min;
      const double w = u[k];
      step = -std::min((kLifted - m_min) / (kLifted * (m_min - 1.0)), w / (1.0 - w));
    }
    for (double& w : u) w *= 1.0 - step;
    u[k] += step;
    if (u[k] < 0.0) u[k] = 0.0;
    // X' = (1 - s) X + s q_k q_k'; Sherman-Morrison with a = s / (1 - s):
    // m_i' = (m_i - a (q_i' X^-1 q_k)^2 / (1 + a m_k)) / (1 - s).
    X = (1.0 - step) * X + step * q[k] * q[k].transpose();
    const double a = step / (1.0 - step);
    const Eigen::Vector3d w = X_inv * q[k];
    const double denom = 1.0 + a * m[k];
    if (!(std::abs(denom) > 1e-12)) break;
    for (int i = 0; i < n; ++i) {
      const double c = q[i].dot(w);
      m[i] = (m[i] - a * c * c / denom) / (1.0 - step);
    }
    X_inv = (X_inv - a * w * w.transpose() / denom) / (1.0 - step);
  }
  Ellipse e;
  Eigen::Matrix2d second = Eigen::Matrix2d::Zero();
  for (int i = 0; i < n; ++i) {
    e.centre += u[i] * points[i];
    second.noalias() += u[i] * (points[i] - origin) * (points[i] - origin).transpose();
  }
  const Eigen::Vector2d mean_offset = e.centre - origin;
  e.shape = 2.0 * (second - mean_offset * mean_offset.transpose());
  // Stopped at a tolerance, the ellipse can miss the outermost points by about that much:
  // grow it until it contains them all.
  const Eigen::LDLT<Eigen::Matrix2d> shape_ldlt(e.shape);
  if (shape_ldlt.info() != Eigen::Success) return e;
  double worst = 0.0;
  for (const Eigen::Vector2d& p : points) {
    worst = std::max(worst, (p - e.centre).dot(shape_ldlt.solve(p - e.centre)));
  }
  if (worst > 1.0 && std::isfinite(worst)) e.shape *= worst;
  return e;
}

DifferenceResult minkowski_difference(const Eigen::Matrix2d& E1, const Eigen::Matrix2d& E2,
                                      int samples) noexcept {
  DifferenceResult result;
  const EllipseAxes e2 = ellipse_axes(E2);
  if (!(e2.major > 0.0)) {  // E2 a point: nothing to take away
    result.shape = E1;
    return result;
  }
  // A (near-)segment E2 is thickened a little so the map T below stays well-conditioned.
  const double b2 = std::max(e2.minor, 1e-3 * e2.major);
  const double c = std::cos(e2.orientation), s = std::sin(e2.orientation);
  Eigen::Matrix2d R2;
  R2 << c, -s, s, c;
  // T shrinks E2's major axis to b2 (eq. 43): T E2 T' = b2^2 I.
  const Eigen::Matrix2d T = R2 * Eigen::Vector2d(b2 / e2.major, 1.0).asDiagonal() * R2.transpose();
  const Eigen::Matrix2d T_inv =
      R2 * Eigen::Vector2d(e2.major / b2, 1.0).asDiagonal() * R2.transpose();
  const Eigen::Matrix2d E1t = T * E1 * T.transpose();  // Psi of eq. 44
  const EllipseAxes e1t = ellipse_axes(E1t);
  if (!(e1t.minor > b2)) {  // the circle does not fit: the difference is empty
    result.empty = true;
    return result;
  }
  const Eigen::Matrix2d root = sqrt_psd(E1t);
  const Eigen::Matrix2d inv = E1t.inverse();
  double d_max = -1.0, d_min = std::numeric_limits<double>::infinity(), angle = 0.0;
  for (int i = 0; i < samples; ++i) {
    const double phi = 2.0 * std::numbers::pi * i / samples;
    const Eigen::Vector2d D = root * Eigen::Vector2d(std::cos(phi), std::sin(phi));
    const Eigen::Vector2d grad = inv * D;                            // grad Gamma / 2 (eq. 45)
    const Eigen::Vector2d g = T_inv * (D - b2 * grad.normalized());  // eq. 45-46
    const double d = g.norm();
    if (d > d_max) d_max = d, angle = std::atan2(g.y(), g.x());
    d_min = std::min(d_min, d);
  }
  result.shape = shape_from_axes(d_max, d_min, angle);
  return result;
}

}  // namespace skytrack::extended
