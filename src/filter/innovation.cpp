// EKF innovation and the Joseph-form Kalman update (Bar-Shalom, Li & Kirubarajan 2001,
// §10.3 and ch. 5); the Gaussian log-likelihood is paper 003 eq. 3.
#include "skytrack/filter/innovation.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <type_traits>
#include <variant>

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

/// log det S from S's Cholesky factor.
template <class Factor>
double log_det_of(const Factor& llt) noexcept {
  return 2.0 * llt.matrixLLT().diagonal().array().log().sum();
}

/// The gain K = cross S^-1 and log det S from S's factor at its compile-time size M (S^-1 in
/// closed form when the state size is a common one: a runtime-size solve costs several
/// times more).
template <int M>
void factorise_fixed(const GainMat& cross, InnovationShape& shape) noexcept {
  Innovation& out = shape.shared;
  const auto& llt = shape.factor.emplace<Eigen::LLT<Eigen::Matrix<double, M, M>>>(out.S);
  if (llt.info() != Eigen::Success) {
    fail_innovation(out);
    return;
  }
  if (!with_fixed_state_size(static_cast<int>(cross.rows()), [&](auto n) {
        constexpr int N = decltype(n)::value;
        const Eigen::Matrix<double, M, M> s = out.S;
        const Eigen::Matrix<double, N, M> c = cross;
        const Eigen::Matrix<double, N, M> gain = c * s.inverse();  // S positive definite
        out.gain = gain;
      })) {
    out.gain = llt.solve(cross.transpose()).transpose();
  }
  shape.log_det = log_det_of(llt);
  out.ok = out.gain.allFinite();
  if (!out.ok) fail_innovation(out);
}

}  // namespace

void factorise(const GainMat& cross, InnovationShape& shape) noexcept {
  Innovation& out = shape.shared;
  if (!out.S.allFinite() || !cross.allFinite()) {
    fail_innovation(out);
    return;
  }
  switch (out.S.rows()) {
    case 2:
      return factorise_fixed<2>(cross, shape);
    case 3:
      return factorise_fixed<3>(cross, shape);
    case 4:
      return factorise_fixed<4>(cross, shape);
    default:
      break;
  }
  const auto& llt = shape.factor.emplace<Eigen::LLT<MeasMat>>(out.S);
  if (llt.info() != Eigen::Success) {
    fail_innovation(out);
    return;
  }
  out.gain = llt.solve(cross.transpose()).transpose();  // K = cross S^-1, S symmetric
  shape.log_det = log_det_of(llt);
  out.ok = out.gain.allFinite();
  if (!out.ok) fail_innovation(out);
}

void whiten(const InnovationShape& shape, Innovation& out) noexcept {
  if (!shape.shared.ok || !out.residual.allFinite()) {
    fail_innovation(out);
    return;
  }
  std::visit(
      [&](const auto& llt) {
        using Factor = std::decay_t<decltype(llt)>;
        if constexpr (!std::is_same_v<Factor, std::monostate>) {
          constexpr int M = Factor::MatrixType::RowsAtCompileTime;
          if constexpr (M == Eigen::Dynamic) {
            const MeasVec whitened = llt.matrixL().solve(out.residual);
            out.nis = whitened.squaredNorm();
            const double m = static_cast<double>(out.residual.size());
            out.log_likelihood =
                -0.5 * (m * std::log(2.0 * std::numbers::pi) + shape.log_det + out.nis);
          } else {
            const Eigen::Matrix<double, M, 1> whitened = llt.matrixL().solve(out.residual);
            out.nis = whitened.squaredNorm();
            out.log_likelihood =
                -0.5 * (M * std::log(2.0 * std::numbers::pi) + shape.log_det + out.nis);
          }
        }
      },
      shape.factor);
  out.ok = std::isfinite(out.log_likelihood);
  if (!out.ok) fail_innovation(out);
}

void finish_innovation(const GainMat& cross, Innovation& out) noexcept {
  InnovationShape shape;
  shape.shared.S = out.S;
  factorise(cross, shape);
  out.gain = shape.shared.gain;
  whiten(shape, out);
}

}  // namespace filter_detail

namespace {

/// H, R and S = H P H' + R of the EKF innovation into `out`, and P H' into `cross`. False
/// when the prediction does not fit the layout or the model.
bool innovation_covariance(const Gaussian& predicted, const StateLayout& layout,
                           const MeasurementModel& model, Innovation& out,
                           GainMat& cross) noexcept {
  const int n = layout.size();
  if (predicted.mean.size() != n || predicted.covariance.rows() != n ||
      predicted.covariance.cols() != n || model.state_dims != layout.dims) {
    return false;
  }
  out.H = model.jacobian(layout, predicted.mean);
  out.R = model.noise();
  const bool fixed = with_fixed_sizes(
      static_cast<int>(out.H.cols()), static_cast<int>(out.H.rows()), [&](auto sn, auto sm) {
        constexpr int N = decltype(sn)::value, M = decltype(sm)::value;
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
  return true;
}

}  // namespace

InnovationShape innovation_shape(const Gaussian& predicted, const StateLayout& layout,
                                 const MeasurementModel& model) noexcept {
  InnovationShape shape;
  Innovation& out = shape.shared;
  GainMat cross;  // P H'
  if (!innovation_covariance(predicted, layout, model, out, cross)) {
    filter_detail::fail_innovation(out);
    return shape;
  }
  shape.expected = model.measure(layout, predicted.mean);
  filter_detail::factorise(cross, shape);
  return shape;
}

double innovation_log_det(const Gaussian& predicted, const StateLayout& layout,
                          const MeasurementModel& model) noexcept {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  Innovation out;
  GainMat cross;
  if (!innovation_covariance(predicted, layout, model, out, cross) || !out.S.allFinite() ||
      !cross.allFinite()) {
    return kNaN;
  }
  // Factored as factorise() factors S, so that log det S is the same number.
  const auto log_det = [&](const auto& llt) {
    return llt.info() == Eigen::Success ? filter_detail::log_det_of(llt) : kNaN;
  };
  switch (out.S.rows()) {
    case 2:
      return log_det(Eigen::LLT<Eigen::Matrix2d>(out.S));
    case 3:
      return log_det(Eigen::LLT<Eigen::Matrix3d>(out.S));
    case 4:
      return log_det(Eigen::LLT<Eigen::Matrix4d>(out.S));
    default:
      return log_det(Eigen::LLT<MeasMat>(out.S));
  }
}

Innovation innovate(const InnovationShape& shape, const PlotMeasurement& measurement) noexcept {
  Innovation out = shape.shared;
  const MeasurementModel& model = measurement.model;
  if (measurement.z.size() != model.size() || shape.expected.size() != model.size()) {
    filter_detail::fail_innovation(out);
    return out;
  }
  out.residual = model.residual(measurement.z, shape.expected);
  filter_detail::whiten(shape, out);
  return out;
}

double innovation_nis(const InnovationShape& shape, const PlotMeasurement& measurement) noexcept {
  Innovation out;
  const MeasurementModel& model = measurement.model;
  if (!shape.shared.ok || measurement.z.size() != model.size() ||
      shape.expected.size() != model.size()) {
    return std::numeric_limits<double>::infinity();
  }
  out.residual = model.residual(measurement.z, shape.expected);
  filter_detail::whiten(shape, out);
  return out.ok ? out.nis : std::numeric_limits<double>::infinity();
}

bool same_innovation_shape(const MeasurementModel& a, const MeasurementModel& b) noexcept {
  return a.kind == b.kind && a.state_dims == b.state_dims &&
         a.position_components == b.position_components && a.has_range_rate == b.has_range_rate &&
         a.platform == b.platform && a.enu_to_body == b.enu_to_body &&
         a.sigma.size() == b.sigma.size() && a.sigma == b.sigma;
}

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
    return out;
  }
  return innovate(innovation_shape(predicted, layout, measurement.model), measurement);
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
