// Motion-model dispatch and the prediction step (Bar-Shalom, Li & Kirubarajan 2001, §5.2
// for linear models, §10.3 for the EKF prediction of the coordinated turn with estimated
// rate); negative dt as documented in motion_model.hpp.
#include "skytrack/motion/motion_model.hpp"

#include <cassert>
#include <type_traits>

#include "skytrack/filter/fixed_size.hpp"

namespace skytrack {
namespace {

template <class Model>
constexpr bool kNonLinear = std::is_same_v<Model, CoordinatedTurnEstimated>;

/// P' = F P F' + Q (dt > 0) or F (P + Q) F' (dt < 0), symmetrised.
template <int N>
void propagate_fixed(const StateMat& F, const StateMat& Q, double dt, StateMat& P) noexcept {
  using Mat = Eigen::Matrix<double, N, N>;
  const Mat f = F, q = Q;
  Mat p = P;
  if (dt > 0.0) {
    const Mat fp = f * p;
    p.noalias() = fp * f.transpose();
    p += q;
  } else {
    p += q;
    const Mat fp = f * p;
    p.noalias() = fp * f.transpose();
  }
  P = 0.5 * (p + p.transpose());
}

void propagate_covariance(const StateMat& F, const StateMat& Q, double dt, StateMat& P) noexcept {
  if (with_fixed_state_size(static_cast<int>(P.rows()),
                            [&](auto n) { propagate_fixed<decltype(n)::value>(F, Q, dt, P); })) {
    return;
  }
  StateMat FP;
  if (dt > 0.0) {
    FP.noalias() = F * P;
    P.noalias() = FP * F.transpose();
    P += Q;
  } else {
    P += Q;
    FP.noalias() = F * P;
    P.noalias() = FP * F.transpose();
  }
  // Keep P exactly symmetric: round-off would otherwise accumulate over many scans.
  const StateMat upper = P;
  P = 0.5 * (upper + upper.transpose());
}

/// x' = F x, at a compile-time size when the state's is a common one.
void transition_mean(const StateMat& F, const StateVec& x, StateVec& out) noexcept {
  if (!with_fixed_state_size(static_cast<int>(x.size()), [&](auto n) {
        constexpr int N = decltype(n)::value;
        const Eigen::Matrix<double, N, N> f = F;
        const Eigen::Matrix<double, N, 1> v = x;
        out = f * v;
      })) {
    out.noalias() = F * x;
  }
}

template <class Model>
void predict_with(const Model& model, const StateLayout& layout, const Gaussian& prior, double dt,
                  DiscretisationMemo* memo, Gaussian& out) noexcept {
  assert(prior.mean.size() == layout.size() && prior.covariance.rows() == layout.size());
  assert(&out != &prior);
  if (dt == 0.0) {
    out = prior;
    return;
  }
  if constexpr (kNonLinear<Model>) {
    StateMat F, Q;
    model.linearise(layout, prior.mean, dt, F, Q);
    out.mean = model.propagate(layout, prior.mean, dt);
    out.covariance = prior.covariance;
    propagate_covariance(F, Q, dt, out.covariance);
  } else {
    const auto discretise = [&](double interval, StateMat& F, StateMat& Q) {
      model.discretise(layout, interval, F, Q);
    };
    DiscretisationMemo once;  // without a memo, one used once
    const DiscretisationMemo::Entry& d = (memo != nullptr ? *memo : once).at(dt, discretise);
    transition_mean(d.F, prior.mean, out.mean);
    out.covariance = prior.covariance;
    propagate_covariance(d.F, d.Q, dt, out.covariance);
  }
}

}  // namespace

AnyMotionModel make_motion_model(const config::MotionModelSpec& spec) {
  using config::MotionModelType;
  switch (spec.type) {
    case MotionModelType::kConstantVelocity:
      return ConstantVelocity{spec.accel_sigma, spec.vertical_accel_sigma};
    case MotionModelType::kConstantAcceleration:
      return ConstantAcceleration{spec.jerk_sigma, spec.vertical_accel_sigma};
    case MotionModelType::kCoordinatedTurn:
      return CoordinatedTurn{spec.turn_rate, spec.accel_sigma, spec.vertical_accel_sigma};
    case MotionModelType::kCoordinatedTurnEstimated:
      return CoordinatedTurnEstimated{spec.accel_sigma, spec.turn_rate_sigma,
                                      spec.vertical_accel_sigma, spec.initial_turn_rate_sigma};
    case MotionModelType::kSinger:
      return Singer{spec.accel_sigma, spec.time_constant, spec.vertical_accel_sigma};
  }
  return ConstantVelocity{spec.accel_sigma, spec.vertical_accel_sigma};
}

StateLayout layout_for(const std::vector<config::MotionModelSpec>& specs, int dims) {
  using config::MotionModelType;
  StateLayout layout;
  layout.dims = dims;
  for (const config::MotionModelSpec& spec : specs) {
    if (spec.type == MotionModelType::kConstantAcceleration ||
        spec.type == MotionModelType::kSinger) {
      layout.acceleration = true;
    }
    if (spec.type == MotionModelType::kCoordinatedTurnEstimated) layout.turn_rate = true;
  }
  return layout;
}

bool supports(const AnyMotionModel& model, const StateLayout& layout) noexcept {
  if (layout.dims != 2 && layout.dims != 3) return false;
  if (std::holds_alternative<ConstantAcceleration>(model) ||
      std::holds_alternative<Singer>(model)) {
    return layout.acceleration;
  }
  if (std::holds_alternative<CoordinatedTurnEstimated>(model)) return layout.turn_rate;
  return true;
}

Gaussian predict(const AnyMotionModel& model, const StateLayout& layout, const Gaussian& prior,
                 double dt) noexcept {
  Gaussian out;
  std::visit([&](const auto& concrete) { predict_with(concrete, layout, prior, dt, nullptr, out); },
             model);
  return out;
}

void predict(const AnyMotionModel& model, const StateLayout& layout, const Gaussian& prior,
             double dt, DiscretisationMemo& memo, Gaussian& out) noexcept {
  std::visit([&](const auto& concrete) { predict_with(concrete, layout, prior, dt, &memo, out); },
             model);
}

}  // namespace skytrack
