// EKF innovation and the Joseph-form Kalman update (Bar-Shalom, Li & Kirubarajan 2001,
// §10.3 and ch. 5); the Gaussian log-likelihood is paper 003 eq. 3.
#include "skytrack/filter/innovation.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include "innovation_detail.hpp"
#include "skytrack/filter/fixed_size.hpp"

namespace skytrack {
namespace filter_detail {

void fail_innovation(Innovation& out) noexcept {
  out.ok = false;
  out.log_likelihood = -std::numeric_limits<double>::infinity();
  out.nis = std::numeric_limits<double>::infinity();
}

namespace {

/// finish_innovation with S factorised at its compile-time size M, and the gain at N x M when
/// the state size is a common one (a runtime-size solve costs several times more).
template <int M>
void finish_fixed(const GainMat& cross, Innovation& out) noexcept {
  const Eigen::LLT<Eigen::Matrix<double, M, M>> llt(out.S);
  if (llt.info() != Eigen::Success) {
    fail_innovation(out);
    return;
  }
  // K = cross S^-1; S^-1 in closed form at these sizes (S is positive definite here).
  if (!with_fixed_state_size(static_cast<int>(cross.rows()), [&](auto n) {
        constexpr int N = decltype(n)::value;
        const Eigen::Matrix<double, M, M> s = out.S;
        const Eigen::Matrix<double, N, M> c = cross;
        const Eigen::Matrix<double, N, M> gain = c * s.inverse();
        out.gain = gain;
      })) {
    out.gain = llt.solve(cross.transpose()).transpose();
  }
  const Eigen::Matrix<double, M, 1> whitened = llt.matrixL().solve(out.residual);
  out.nis = whitened.squaredNorm();
  const double log_det = 2.0 * llt.matrixLLT().diagonal().array().log().sum();
  out.log_likelihood = -0.5 * (M * std::log(2.0 * std::numbers::pi) + log_det + out.nis);
  out.ok = std::isfinite(out.log_likelihood) && out.gain.allFinite();
  if (!out.ok) fail_innovation(out);
}

}  // namespace

void finish_innovation(const GainMat& cross, Innovation& out) noexcept {
  if (!out.S.allFinite() || !out.residual.allFinite() || !cross.allFinite()) {
    fail_innovation(out);
    return;
  }
  switch (out.S.rows()) {
    case 2:
      return finish_fixed<2>(cross, out);
    case 3:
      return finish_fixed<3>(cross, out);
    case 4:
      return finish_fixed<4>(cross, out);
    default:
      break;
  }
  const Eigen::LLT<MeasMat> llt(out.S);
  if (llt.info() != Eigen::Success) {
    fail_innovation(out);
    return;
  }
  out.gain = llt.solve(cross.transpose()).transpose();  // K = cross S^-1, S symmetric
  const MeasVec whitened = llt.matrixL().solve(out.residual);
  out.nis = whitened.squaredNorm();
  const double log_det = 2.0 * llt.matrixLLT().diagonal().array().log().sum();
  const double m = static_cast<double>(out.residual.size());
  out.log_likelihood = -0.5 * (m * std::log(2.0 * std::numbers::pi) + log_det + out.nis);
  out.ok = std::isfinite(out.log_likelihood) && out.gain.allFinite();
  if (!out.ok) fail_innovation(out);
}

}  // namespace filter_detail

namespace {

void innovate_ekf(const Gaussian& predicted, const StateLayout& layout,
                  const PlotMeasurement& measurement, Innovation& out) noexcept {
  const MeasurementModel& model = measurement.model;
  out.H = model.jacobian(layout, predicted.mean);
  out.residual = model.residual(measurement.z, model.measure(layout, predicted.mean));
  out.R = model.noise();
  GainMat cross;  // P H'
  const bool fixed = with_fixed_sizes(
      static_cast<int>(out.H.cols()), static_cast<int>(out.H.rows()), [&](auto n, auto m) {
        constexpr int N = decltype(n)::value, M = decltype(m)::value;
        const Eigen::Matrix<double, N, N> p = predicted.covariance;
        const Eigen::Matrix<double, M, N> h = out.H;
        const Eigen::Matrix<double, N, M> c = p * h.transpose();
        const Eigen::Matrix<double, M, M> r = out.R;
        cross = c;
        out.S = h * c + r;
      });
  if (!fixed) {
    cross.noalias() = predicted.covariance * out.H.transpose();
    out.S.noalias() = out.H * cross;
    out.S += out.R;
  }
  filter_detail::finish_innovation(cross, out);
}

}  // namespace

Innovation innovate(const Gaussian& predicted, const StateLayout& layout,
                    const PlotMeasurement& measurement,
                    const config::MeasurementSpec& spec) noexcept {
  Innovation out;
  const int n = layout.size();
  if (predicted.mean.size() != n || predicted.covariance.rows() != n ||
      predicted.covariance.cols() != n || measurement.model.state_dims != layout.dims ||
      measurement.z.size() != measurement.model.size()) {
    filter_detail::fail_innovation(out);
    return out;
  }
  if (spec.update == config::MeasurementUpdate::kUnscented) {
    filter_detail::innovate_unscented(predicted, layout, measurement, spec.unscented, out);
  } else {
    innovate_ekf(predicted, layout, measurement, out);
  }
  return out;
}

namespace {

/// Joseph form (I - K H) P (I - K H)' + K R K', at compile-time sizes when they are common.
StateMat joseph_covariance(const StateMat& P, const Innovation& innovation) noexcept {
  StateMat out;
  const auto n = static_cast<int>(P.rows()), m = static_cast<int>(innovation.H.rows());
  if (with_fixed_sizes(n, m, [&](auto sn, auto sm) {
        constexpr int N = decltype(sn)::value, M = decltype(sm)::value;
        const Eigen::Matrix<double, N, M> k = innovation.gain;
        const Eigen::Matrix<double, M, N> h = innovation.H;
        const Eigen::Matrix<double, M, M> r = innovation.R;
        const Eigen::Matrix<double, N, N> p = P;
        const Eigen::Matrix<double, N, N> a = Eigen::Matrix<double, N, N>::Identity() - k * h;
        const Eigen::Matrix<double, N, N> joseph = a * p * a.transpose() + k * r * k.transpose();
        out = joseph;
      })) {
    return out;
  }
  StateMat A = StateMat::Identity(n, n);
  A.noalias() -= innovation.gain * innovation.H;
  StateMat AP;
  AP.noalias() = A * P;
  out.noalias() = AP * A.transpose();
  GainMat KR;
  KR.noalias() = innovation.gain * innovation.R;
  out.noalias() += KR * innovation.gain.transpose();
  return out;
}

}  // namespace

Gaussian kalman_update(const Gaussian& predicted, const Innovation& innovation) noexcept {
  if (!innovation.ok) return predicted;
  Gaussian out;
  out.mean = predicted.mean;
  out.mean.noalias() += innovation.gain * innovation.residual;
  StateMat P;
  if (innovation.H.rows() == 0) {  // unscented: P - K S K'
    GainMat KS;
    KS.noalias() = innovation.gain * innovation.S;
    P = predicted.covariance;
    P.noalias() -= KS * innovation.gain.transpose();
  } else {
    P = joseph_covariance(predicted.covariance, innovation);
  }
  out.covariance = 0.5 * (P + P.transpose());
  return out;
}

}  // namespace skytrack
