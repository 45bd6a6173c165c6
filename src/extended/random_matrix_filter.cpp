// Random-matrix filter, Feldmann, Fraenken & Koch 2011 (see random_matrix_filter.hpp).
#include "skytrack/extended/random_matrix_filter.hpp"

#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

namespace skytrack::extended {
namespace {

// Symmetric square root of an SPD matrix and of its inverse; false when not SPD.
bool roots(const Eigen::Matrix2d& A, Eigen::Matrix2d& root, Eigen::Matrix2d& inv_root) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(A);
  if (eig.info() != Eigen::Success || !(eig.eigenvalues().minCoeff() > 0.0)) return false;
  const Eigen::Vector2d r = eig.eigenvalues().cwiseSqrt();
  root = eig.eigenvectors() * r.asDiagonal() * eig.eigenvectors().transpose();
  inv_root = eig.eigenvectors() * r.cwiseInverse().asDiagonal() * eig.eigenvectors().transpose();
  return true;
}

}  // namespace

void random_matrix_predict(const MotionSpec& motion, const RandomMatrixSpec& spec,
                           ExtendedObject& object, double dt) noexcept {
  if (!(dt > 0.0)) return;
  const KinMat F = transition(motion, dt);
  object.x = F * object.x;
  object.P = F * object.P * F.transpose() + process_noise(motion, dt);
  // The extent's certainty decays towards alpha = 2 (its mean X is kept).
  object.dof = 2.0 + std::exp(-dt / spec.extent_time_constant) * (object.dof - 2.0);
}

UpdateStatus random_matrix_update(const RandomMatrixSpec& spec, ExtendedObject& object,
                                  std::span<const Eigen::Vector2d> plots,
                                  const Eigen::Matrix2d& noise) noexcept {
  if (plots.empty()) return UpdateStatus::kNoPlots;
  const double n = static_cast<double>(plots.size());
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& z : plots) mean += z;
  mean /= n;
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  for (const Eigen::Vector2d& z : plots) scatter.noalias() += (z - mean) * (z - mean).transpose();

  const PosMat H = position_matrix();
  const Eigen::Matrix2d Y = spec.scattering * object.extent + noise;
  const Eigen::Matrix2d S = H * object.P * H.transpose() + Y / n;
  Eigen::Matrix2d X_root, X_inv_root, S_root, S_inv_root, Y_root, Y_inv_root;
  if (!mean.allFinite() || !roots(object.extent, X_root, X_inv_root) ||
      !roots(S, S_root, S_inv_root) || !roots(Y, Y_root, Y_inv_root)) {
    return UpdateStatus::kNumericFailure;
  }
  const Eigen::LLT<Eigen::Matrix2d> llt(S);
  const Eigen::Matrix<double, 6, 2> K = llt.solve(H * object.P).transpose();
  const Eigen::Vector2d eps = mean - H * object.x;
  object.x += K * eps;
  object.P -= K * S * K.transpose();
  object.P = 0.5 * (object.P + object.P.transpose()).eval();

  const Eigen::Vector2d e = S_inv_root * eps;
  const Eigen::Matrix2d N_hat = X_root * e * e.transpose() * X_root;
  const Eigen::Matrix2d Z_hat = X_root * Y_inv_root * scatter * Y_inv_root * X_root;
  object.extent = (object.dof * object.extent + N_hat + Z_hat) / (object.dof + n);
  object.extent = 0.5 * (object.extent + object.extent.transpose()).eval();
  object.dof += n;
  return UpdateStatus::kUpdated;
}

}  // namespace skytrack::extended
