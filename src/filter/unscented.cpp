// Unscented innovation (Julier & Uhlmann 1997; Wan & van der Merwe 2000, "The unscented
// Kalman filter for nonlinear estimation", eq. 15 (sigma points and weights) and
// Algorithm 3.1 (measurement update)):
//   lambda = alpha^2 (n + kappa) - n,  chi_0 = x,  chi_{i, n+i} = x +- (sqrt((n + lambda) P))_i
//   Wm_0 = lambda / (n + lambda),  Wc_0 = Wm_0 + (1 - alpha^2 + beta),  W_i = 1 / (2 (n + lambda))
//   zhat = sum Wm_i Z_i,  S = sum Wc_i (Z_i - zhat)(Z_i - zhat)' + R,
//   Pxz = sum Wc_i (chi_i - x)(Z_i - zhat)',  K = Pxz S^-1.
// Azimuths of the Z_i are unwrapped around the central point's before averaging, and the
// differences Z_i - zhat use the model's wrapped residual. The matrix square root is taken
// from an LDL' factorisation, which also accepts the positive semi-definite covariances the
// augmented IMM produces (zeroed acceleration rows).
#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>

#include "innovation_detail.hpp"
#include "skytrack/geometry/angles.hpp"

namespace skytrack::filter_detail {
namespace {

constexpr int kMaxSigmaPoints = 2 * kMaxStateDim + 1;
using SigmaPoints =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxStateDim, kMaxSigmaPoints>;
using MeasSigmaPoints =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxMeasurementDim, kMaxSigmaPoints>;

/// root with root root' = P for a positive semi-definite P (P = T' L D L' T, root = T' L D^1/2).
bool psd_square_root(const StateMat& P, StateMat& root) noexcept {
  const Eigen::LDLT<StateMat> ldlt(P);
  if (ldlt.info() != Eigen::Success) return false;
  const auto d = ldlt.vectorD();
  const double scale = d.cwiseAbs().maxCoeff();
  StateMat lower = ldlt.matrixL();
  for (int i = 0; i < d.size(); ++i) {
    if (d[i] < -1e-12 * scale || !std::isfinite(d[i])) return false;
    lower.col(i) *= std::sqrt(std::max(d[i], 0.0));
  }
  root.noalias() = ldlt.transpositionsP().transpose() * lower;
  return true;
}

}  // namespace

void innovate_unscented(const Gaussian& predicted, const StateLayout& layout,
                        const PlotMeasurement& measurement, const config::UnscentedSpec& spec,
                        Innovation& out) noexcept {
  const MeasurementModel& model = measurement.model;
  const int n = static_cast<int>(predicted.mean.size()), points = 2 * n + 1;
  const double alpha2 = spec.alpha * spec.alpha;
  const double n_lambda = alpha2 * (n + spec.kappa);  // n + lambda
  StateMat root;
  if (!(n_lambda > 0.0) || !psd_square_root(predicted.covariance, root)) {
    fail_innovation(out);
    return;
  }
  root *= std::sqrt(n_lambda);
  SigmaPoints chi(n, points);
  chi.col(0) = predicted.mean;
  for (int i = 0; i < n; ++i) {
    chi.col(1 + i) = predicted.mean + root.col(i);
    chi.col(1 + n + i) = predicted.mean - root.col(i);
  }
  const double wm0 = (n_lambda - n) / n_lambda, wi = 0.5 / n_lambda;
  const double wc0 = wm0 + (1.0 - alpha2 + spec.beta);
  const int m = model.size(), az = model.azimuth_index();
  MeasSigmaPoints Z(m, points);
  for (int k = 0; k < points; ++k) Z.col(k) = model.measure(layout, chi.col(k));
  for (int k = 1; az >= 0 && k < points; ++k) {
    Z(az, k) = Z(az, 0) + wrap_angle(Z(az, k) - Z(az, 0));
  }
  MeasVec zhat = wm0 * Z.col(0);
  for (int k = 1; k < points; ++k) zhat += wi * Z.col(k);
  out.R = model.noise();
  out.S = out.R;
  GainMat cross = GainMat::Zero(n, m);
  for (int k = 0; k < points; ++k) {
    const double w = k == 0 ? wc0 : wi;
    const MeasVec dz = model.residual(Z.col(k), zhat);
    out.S.noalias() += w * dz * dz.transpose();
    cross.noalias() += w * (chi.col(k) - predicted.mean) * dz.transpose();
  }
  out.residual = model.residual(measurement.z, zhat);
  out.H.resize(0, 0);
  finish_innovation(cross, out);
}

}  // namespace skytrack::filter_detail
