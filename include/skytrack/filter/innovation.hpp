#pragma once
// The measurement-update building blocks: innovation, its covariance and gain, the Gaussian
// log-likelihood (paper 003 eq. 3) and the Kalman update.
//   EKF (Bar-Shalom, Li & Kirubarajan 2001, §10.3):
//     nu = z - h(x) (wrapped), S = H P H' + R, K = P H' S^-1.
//   Unscented (Wan & van der Merwe 2000, eq. 15 and Algorithm 3.1): 2n+1 sigma points with
//     lambda = alpha^2 (n + kappa) - n; Wm0 = lambda / (n + lambda),
//     Wc0 = Wm0 + (1 - alpha^2 + beta), Wi = 1 / (2 (n + lambda)); azimuths of the sigma
//     points are unwrapped around h(mean) before averaging. S = sum Wc dz dz' + R,
//     K = Pxz S^-1.
//   Update in Joseph form (Bar-Shalom et al. 2001, ch. 5):
//     P+ = (I - K H) P (I - K H)' + K R K'; the unscented update uses P - K S K'.
// S is factorised once (LLT) and solved against; a failed factorisation gives ok = false.
#include <variant>

#include <Eigen/Cholesky>

#include "skytrack/config/profile.hpp"
#include "skytrack/filter/state.hpp"
#include "skytrack/measurement/plot_measurement.hpp"

namespace skytrack {

struct Innovation {
  MeasVec residual;  // nu = z - zhat, azimuth wrapped to [-pi, pi)
  MeasMat S;         // innovation covariance
  GainMat gain;      // K
  MeasJacobian H;    // EKF Jacobian at the prediction; empty (0 x 0) for the unscented update
  MeasMat R;         // measurement noise
  double log_likelihood = 0.0;  // log N(nu; 0, S); -infinity when !ok
  double nis = 0.0;             // nu' S^-1 nu; +infinity when !ok
  bool ok = false;              // S positive definite and everything finite
};

/// Innovation of one plot against one predicted Gaussian, by EKF linearisation or the
/// unscented transform as `spec.update` says.
Innovation innovate(const Gaussian& predicted, const StateLayout& layout,
                    const PlotMeasurement& measurement,
                    const config::MeasurementSpec& spec) noexcept;

/// The parts of an EKF innovation that depend on a plot only through its measurement model
/// (its form, sensor geometry and noise): against one prediction, every plot of one model
/// has the same h(x), H, R, S, factor of S and gain. Made once, they serve all such plots.
struct InnovationShape {
  Innovation shared;  // H, R, S and gain (no residual); ok = false: no plot can be innovated
  MeasVec expected;   // h(x)
  std::variant<std::monostate, Eigen::LLT<Eigen::Matrix2d>, Eigen::LLT<Eigen::Matrix3d>,
               Eigen::LLT<Eigen::Matrix4d>, Eigen::LLT<MeasMat>>
      factor;  // of S, at its compile-time size when it has one
  double log_det = 0.0;
};

/// The EKF innovation's shape of a prediction for plots of `model`.
InnovationShape innovation_shape(const Gaussian& predicted, const StateLayout& layout,
                                 const MeasurementModel& model) noexcept;

/// log det S of the EKF innovation's covariance S = H P H' + R for plots of `model` (S as
/// innovation_shape makes it), without the gain: what a gate's volume needs. NaN when S is
/// not positive definite.
double innovation_log_det(const Gaussian& predicted, const StateLayout& layout,
                          const MeasurementModel& model) noexcept;

/// innovate() by EKF for a plot of the model `shape` was made for: the same numbers.
Innovation innovate(const InnovationShape& shape, const PlotMeasurement& measurement) noexcept;

/// The NIS innovate(shape, measurement) gives (+infinity when it is not ok), without the rest.
double innovation_nis(const InnovationShape& shape, const PlotMeasurement& measurement) noexcept;

/// True when plots of models `a` and `b` share an innovation shape against any prediction.
bool same_innovation_shape(const MeasurementModel& a, const MeasurementModel& b) noexcept;

/// x + K nu and the Joseph-form covariance (symmetrised). Returns `predicted` unchanged when
/// the innovation is not ok.
Gaussian kalman_update(const Gaussian& predicted, const Innovation& innovation) noexcept;

}  // namespace skytrack
