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

/// x + K nu and the Joseph-form covariance (symmetrised). Returns `predicted` unchanged when
/// the innovation is not ok.
Gaussian kalman_update(const Gaussian& predicted, const Innovation& innovation) noexcept;

}  // namespace skytrack
