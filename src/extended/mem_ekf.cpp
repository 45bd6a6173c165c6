// MEM-EKF*, Yang & Baum 2019, Table I (see mem_ekf.hpp).
#include "skytrack/extended/mem_ekf.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>

namespace skytrack::extended {
namespace {

Eigen::Matrix2d shape_root(const Eigen::Vector3d& p) {
  const double c = std::cos(p[0]), s = std::sin(p[0]);
  Eigen::Matrix2d S;
  S << p[1] * c, -p[2] * s, p[1] * s, p[2] * c;
  return S;
}

// The (1 - Phi(z)) lower quantile of chi^2 with nu degrees of freedom, Wilson & Hilferty's
// cube-root approximation (0 when it has none: nu too small for the confidence).
double chi_squared_lower_quantile(int nu, double z) {
  const double v = 2.0 / (9.0 * nu);
  const double root = 1.0 - v - z * std::sqrt(v);
  return root > 0.0 ? nu * root * root * root : 0.0;
}

// Bound of the semi-axes by the scan's plots (not in Yang & Baum): n scatterers uniform over
// the object's ellipse plus noise R spread along a unit direction u with variance
// u'(X/4 + R)u, so from the plots' sum of squares T_u = sum (u'(z - zbar))^2 about their mean,
// u'Xu <= 4 (T_u / chi^2_{n-1, lower} - u'Ru) at the confidence of `sigmas` (conservative:
// the projection of a uniform ellipse has lighter tails than a Gaussian). Applied along the
// estimate's two axes, it caps a semi-axis grown by an innovation the plots' own spread does
// not show: the centre's error read as extent.
void bound_by_spread(double sigmas, std::span<const Eigen::Vector2d> plots,
                     const Eigen::Matrix2d& noise, Eigen::Vector3d& p) {
  const int n = static_cast<int>(plots.size());
  if (!(sigmas > 0.0) || n < 3) return;
  const double q = chi_squared_lower_quantile(n - 1, sigmas);
  if (!(q > 0.0)) return;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& z : plots) mean += z;
  mean /= static_cast<double>(n);
  Eigen::Matrix2d T = Eigen::Matrix2d::Zero();
  for (const Eigen::Vector2d& z : plots) T.noalias() += (z - mean) * (z - mean).transpose();
  const double c = std::cos(p[0]), s = std::sin(p[0]);
  const Eigen::Vector2d axes[2] = {{c, s}, {-s, c}};
  for (int i = 0; i < 2; ++i) {
    const Eigen::Vector2d& u = axes[i];
    const double bound = 2.0 * std::sqrt(std::max(u.dot(T * u) / q - u.dot(noise * u), 0.0));
    if (std::abs(p[1 + i]) > bound) p[1 + i] = std::copysign(bound, p[1 + i]);
  }
}

}  // namespace

Eigen::Matrix2d mem_ekf_extent(const Eigen::Vector3d& shape) noexcept {
  const Eigen::Matrix2d S = shape_root(shape);
  return S * S.transpose();
}

void mem_ekf_predict(const MotionSpec& motion, const MemEkfSpec& spec, ExtendedObject& object,
                     double dt) noexcept {
  if (!(dt > 0.0)) return;
  const KinMat F = transition(motion, dt);
  object.x = F * object.x;
  object.P = F * object.P * F.transpose() + process_noise(motion, dt);
  object.shape_cov +=
      Eigen::Vector3d(spec.orientation_noise, spec.axis_noise, spec.axis_noise).asDiagonal();
  object.extent = mem_ekf_extent(object.shape);
}

UpdateStatus mem_ekf_update(const MemEkfSpec& spec, ExtendedObject& object,
                            std::span<const Eigen::Vector2d> plots,
                            const Eigen::Matrix2d& noise) noexcept {
  if (plots.empty()) return UpdateStatus::kNoPlots;
  const PosMat H = position_matrix();
  const double ch = spec.scattering;
  UpdateStatus status = UpdateStatus::kUpdated;
  for (const Eigen::Vector2d& y : plots) {
    const Eigen::Vector3d& p = object.shape;
    const double c = std::cos(p[0]), s = std::sin(p[0]);
    const Eigen::Matrix2d S = shape_root(p);
    const Eigen::RowVector2d S1 = S.row(0), S2 = S.row(1);
    Eigen::Matrix<double, 2, 3> J1, J2;
    J1 << -p[1] * s, c, 0.0, -p[2] * c, 0.0, -s;
    J2 << p[1] * c, s, 0.0, -p[2] * s, 0.0, c;
    const Eigen::Matrix3d& Cp = object.shape_cov;
    const Eigen::Matrix2d C_I = ch * S * S.transpose();
    Eigen::Matrix2d C_II;
    C_II(0, 0) = ch * (Cp * J1.transpose() * J1).trace();
    C_II(0, 1) = ch * (Cp * J2.transpose() * J1).trace();
    C_II(1, 0) = ch * (Cp * J1.transpose() * J2).trace();
    C_II(1, 1) = ch * (Cp * J2.transpose() * J2).trace();
    Eigen::Matrix3d M;
    M.row(0) = 2.0 * ch * S1 * J1;
    M.row(1) = 2.0 * ch * S2 * J2;
    M.row(2) = ch * (S1 * J2 + S2 * J1);

    const Eigen::Vector2d e = y - H * object.x;  // both updates use the prior (MEM-EKF*)
    const Eigen::Matrix<double, 6, 2> C_ry = object.P * H.transpose();
    Eigen::Matrix2d C_y = H * C_ry + C_I + C_II + noise;
    C_y = 0.5 * (C_y + C_y.transpose()).eval();
    const Eigen::LLT<Eigen::Matrix2d> llt_y(C_y);
    if (llt_y.info() != Eigen::Success || !y.allFinite()) {
      status = UpdateStatus::kNumericFailure;
      continue;
    }
    const double a = C_y(0, 0), b = C_y(1, 1), cc = C_y(0, 1);
    Eigen::Matrix3d C_Y;
    C_Y << 2 * a * a, 2 * cc * cc, 2 * a * cc,  //
        2 * cc * cc, 2 * b * b, 2 * b * cc,     //
        2 * a * cc, 2 * b * cc, a * b + cc * cc;
    const Eigen::LDLT<Eigen::Matrix3d> ldlt_Y(C_Y);
    if (ldlt_Y.info() != Eigen::Success) {
      status = UpdateStatus::kNumericFailure;
      continue;
    }
    object.x += C_ry * llt_y.solve(e);
    object.P -= C_ry * llt_y.solve(C_ry.transpose());
    object.P = 0.5 * (object.P + object.P.transpose()).eval();

    const Eigen::Vector3d Y(e[0] * e[0], e[1] * e[1], e[0] * e[1]);
    const Eigen::Vector3d Y_bar(a, b, cc);
    const Eigen::Matrix3d C_pY = Cp * M.transpose();
    object.shape += C_pY * ldlt_Y.solve(Y - Y_bar);
    object.shape_cov -= C_pY * ldlt_Y.solve(C_pY.transpose());
    object.shape_cov = 0.5 * (object.shape_cov + object.shape_cov.transpose()).eval();
  }
  bound_by_spread(spec.spread_bound_sigmas, plots, noise, object.shape);
  // Plots no wider than their noise along an axis leave the object unresolved there, not of
  // zero size: the semi-axes keep a floor, so the extent stays definite.
  for (int i = 1; i <= 2; ++i) {
    if (std::abs(object.shape[i]) < spec.min_axis) {
      object.shape[i] = std::copysign(spec.min_axis, object.shape[i]);
    }
  }
  object.extent = mem_ekf_extent(object.shape);
  return status;
}

}  // namespace skytrack::extended
