// SMF-EOT, paper 002 eq. 23-48 (see smf_eot.hpp for the equations and our reading).
#include "skytrack/extended/smf_eot.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "skytrack/extended/ellipse_geometry.hpp"

namespace skytrack::extended {
namespace {

Eigen::Matrix2d floor_axes(const Eigen::Matrix2d& shape, double min_axis) {
  const EllipseAxes axes = ellipse_axes(shape);
  return shape_from_axes(std::max(axes.major, min_axis), std::max(axes.minor, min_axis),
                         axes.orientation);
}

// The scan's plots that can be one object's (not in paper 002): two plots of an object with
// semi-axes a and noise in E(0, U) lie at most 2 a + 2 u apart (u: U's major semi-axis). With
// a the predicted major semi-axis (floored) times `outlier_margin`, a plot farther than that
// from at least half of the scan's plots (itself included) is a stray: clutter or a
// neighbour's plot. All plots when fewer than two remain or the margin is 0.
std::span<const Eigen::Vector2d> consistent_plots(const SmfSpec& spec, const ExtendedObject& object,
                                                  std::span<const Eigen::Vector2d> plots,
                                                  const Eigen::Matrix2d& bound,
                                                  std::vector<Eigen::Vector2d>& kept) {
  if (!(spec.outlier_margin > 0.0) || plots.size() < 3) return plots;
  const double a = std::max(ellipse_axes(object.extent).major, spec.outlier_min_axis);
  const double u =
      std::sqrt(std::max(bound.selfadjointView<Eigen::Lower>().eigenvalues().maxCoeff(), 0.0));
  const double reach = 2.0 * spec.outlier_margin * a + 2.0 * u;
  const std::size_t needed = (plots.size() + 1) / 2;
  kept.clear();
  for (const Eigen::Vector2d& z : plots) {
    std::size_t near = 0;
    for (const Eigen::Vector2d& w : plots) near += (z - w).norm() <= reach ? 1 : 0;
    if (near >= needed) kept.push_back(z);
  }
  if (kept.size() < 2) return plots;
  return kept;
}

// E1 less E2 (eq. 42-48). Where E2 does not fit inside E1 across one axis (a long object's
// plots spread along its length but no wider than their noise across it) the exact
// difference is empty, yet the plots still measure the length: along each of E1's axes u the
// result keeps the support h_E1(u) - h_E2(u), zero where E2 reaches beyond E1.
Eigen::Matrix2d resolved_difference(const Eigen::Matrix2d& E1, const Eigen::Matrix2d& E2) {
  const DifferenceResult exact = minkowski_difference(E1, E2);
  if (!exact.empty) return exact.shape;
  const EllipseAxes axes = ellipse_axes(E1);
  const Eigen::Vector2d u(std::cos(axes.orientation), std::sin(axes.orientation));
  const Eigen::Vector2d w(-u.y(), u.x());
  auto support = [&E2](const Eigen::Vector2d& v) {
    return std::sqrt(std::max(v.dot(E2 * v), 0.0));
  };
  const double along = std::max(axes.major - support(u), 0.0);
  const double across = std::max(axes.minor - support(w), 0.0);
  return along * along * u * u.transpose() + across * across * w * w.transpose();
}

}  // namespace

void smf_predict(const MotionSpec& motion, ExtendedObject& object, double dt) noexcept {
  if (!(dt > 0.0)) return;
  const KinMat F = transition(motion, dt);
  const KinMat Q = process_noise(motion, dt);
  object.x = F * object.x;                      // eq. 27
  object.P = F * object.P * F.transpose() + Q;  // eq. 23
  const KinMat FSF = F * object.S * F.transpose();
  object.S = minkowski_sum_bound(FSF, Q).shape;  // eq. 27-29
}

Eigen::Matrix2d smf_extent_measurement(const SmfSpec& spec, std::span<const Eigen::Vector2d> plots,
                                       const Eigen::Matrix2d& centre_bound,
                                       const Eigen::Matrix2d& noise_bound,
                                       const Eigen::Matrix2d& sensor_bound,
                                       SmfWorkspace& workspace) noexcept {
  // eq. 38-39: every plot's bounding ellipse.
  const SumBound<Eigen::Matrix2d> omega_bound = minkowski_sum_bound(centre_bound, noise_bound);
  const Eigen::Matrix2d& omega = omega_bound.shape;
  workspace.boundary.clear();
  for (const Eigen::Vector2d& z : plots) {
    append_ellipse_boundary(z, omega, spec.boundary_points, workspace.boundary);
  }
  convex_hull(workspace.boundary, workspace.hull);                    // eq. 40 (Graham scan)
  const Ellipse B = minimum_enclosing_ellipse(workspace.hull, 1e-4);  // eq. 41
  if (spec.literal_extent) {  // the printed steps: (B (-) (1 + 1/p) HSH' (-) U) / lambda
    const double p = omega_bound.p > 0.0 ? omega_bound.p : 1.0;
    const DifferenceResult d =
        minkowski_difference(B.shape, Eigen::Matrix2d((1.0 + 1.0 / p) * centre_bound));
    const DifferenceResult x = minkowski_difference(d.shape, sensor_bound);
    const Eigen::Matrix2d X = x.empty ? Eigen::Matrix2d::Zero() : Eigen::Matrix2d(x.shape);
    return floor_axes(X / spec.scattering, spec.min_axis);
  }
  const Eigen::Matrix2d spread = resolved_difference(B.shape, omega);        // eq. 42-46
  const Eigen::Matrix2d object = resolved_difference(spread, sensor_bound);  // eq. 47-48
  return floor_axes(object, spec.min_axis);
}

UpdateStatus smf_update(const SmfSpec& spec, ExtendedObject& object,
                        std::span<const Eigen::Vector2d> plots, const Eigen::Matrix2d& bound,
                        SmfWorkspace& workspace) noexcept {
  if (plots.empty()) return UpdateStatus::kNoPlots;
  plots = consistent_plots(spec, object, plots, bound, workspace.kept);
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& z : plots) mean += z;
  mean /= static_cast<double>(plots.size());

  const PosMat H = position_matrix();
  const Eigen::Matrix2d C = minkowski_sum_bound(Eigen::Matrix2d(spec.scattering * object.extent),
                                                bound)
                                .shape;  // eq. 2
  const Eigen::Matrix2d innovation_cov = H * object.P * H.transpose() + C;
  const Eigen::LLT<Eigen::Matrix2d> llt(innovation_cov);
  if (llt.info() != Eigen::Success || !mean.allFinite()) return UpdateStatus::kNumericFailure;
  const Eigen::Matrix<double, 6, 2> K = llt.solve(H * object.P).transpose();  // eq. 32
  const KinMat I_KH = KinMat::Identity() - K * H;
  object.x = I_KH * object.x + K * mean;  // eq. 35
  object.P = I_KH * object.P;             // eq. 33
  object.P = 0.5 * (object.P + object.P.transpose()).eval();
  const KinMat shrunk = I_KH * object.S * I_KH.transpose();
  const KinMat spread = K * C * K.transpose();
  object.S = minkowski_sum_bound(shrunk, spread).shape;  // eq. 35-37

  const Eigen::Matrix2d centre_bound = H * object.S * H.transpose();
  const Eigen::Matrix2d measured =
      smf_extent_measurement(spec, plots, centre_bound, C, bound, workspace);
  object.extent = (1.0 - spec.extent_gain) * object.extent + spec.extent_gain * measured;
  return UpdateStatus::kUpdated;
}

}  // namespace skytrack::extended
