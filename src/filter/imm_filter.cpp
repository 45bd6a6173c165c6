// IMM filter (Blom & Bar-Shalom 1988) as paper 003 §3.1 writes it: mixing eq. 1-2, per-mode
// filtering, mode probabilities eq. 3-5 (extended to association weights as derived in
// imm_filter.hpp), combination eq. 6-7; with the JPDA marginals of eq. 8-10 as weights.
#include "skytrack/filter/imm_filter.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <utility>

#include "pda_detail.hpp"
#include "skytrack/filter/fixed_size.hpp"

namespace skytrack {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
/// A track's plot weights per mode kept on the stack (more plots are weighed again).
constexpr std::size_t kKeptWeights = 16;
/// Bounds the cost of a long coast: beyond this many steps, the Markov matrix over each
/// longer step still gives the modes' probabilities.
constexpr int kMaxPredictionSteps = 8;

/// moment_match at a compile-time state size N.
template <int N, class WeightAt>
Gaussian moment_match_fixed(const std::vector<Gaussian>& parts, const WeightAt& weight) noexcept {
  using Vec = Eigen::Matrix<double, N, 1>;
  using Mat = Eigen::Matrix<double, N, N>;
  Vec mean = Vec::Zero();
  for (std::size_t i = 0; i < parts.size(); ++i) mean += weight(i) * Vec(parts[i].mean);
  Mat covariance = Mat::Zero();
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const double w = weight(i);
    if (w == 0.0) continue;
    const Vec dx = Vec(parts[i].mean) - mean;
    covariance += w * Mat(parts[i].covariance);
    covariance.noalias() += w * (dx * dx.transpose());
  }
  return Gaussian{mean, covariance};
}

/// sum_i w_i (P_i + (x_i - x)(x_i - x)') with x = sum_i w_i x_i, the weights summing to 1.
template <class WeightAt>
Gaussian moment_match(const std::vector<Gaussian>& parts, const WeightAt& weight) noexcept {
  Gaussian out;
  if (with_fixed_state_size(static_cast<int>(parts.front().mean.size()), [&](auto n) {
        out = moment_match_fixed<decltype(n)::value>(parts, weight);
      })) {
    return out;
  }
  out.mean = StateVec::Zero(parts.front().mean.size());
  for (std::size_t i = 0; i < parts.size(); ++i) out.mean += weight(i) * parts[i].mean;
  out.covariance = StateMat::Zero(out.mean.size(), out.mean.size());
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const double w = weight(i);
    if (w == 0.0) continue;
    const StateVec dx = parts[i].mean - out.mean;
    out.covariance += w * parts[i].covariance;
    out.covariance.noalias() += w * (dx * dx.transpose());
  }
  return out;
}

/// Mode j's innovation of a hypothesis, or a failed one when the hypothesis lacks the mode.
const Innovation& innovation_of(const PlotHypothesis& hypothesis, int j, int modes) noexcept {
  static const Innovation kMissing;  // ok = false
  return static_cast<int>(hypothesis.per_mode.size()) == modes ? hypothesis.per_mode[j] : kMissing;
}

/// A track's association weights: the given ones normalised to sum to 1 with beta_miss, or,
/// when they are unusable (sum <= 0 or not finite), the isolated-track PDA weights.
class AssociationWeights {
 public:
  AssociationWeights(std::span<const PlotHypothesis> hypotheses, std::span<const double> beta_plots,
                     double beta_miss, double pd, double pg, double clutter_density) noexcept
      : hypotheses_(hypotheses), beta_plots_(beta_plots) {
    const std::size_t count = std::min(hypotheses.size(), beta_plots.size());
    double sum_likelihood = 0.0;
    total_ = std::max(beta_miss, 0.0);
    for (std::size_t i = 0; i < count; ++i) {
      total_ += std::max(beta_plots[i], 0.0);
      if (hypotheses[i].usable) sum_likelihood += hypotheses[i].likelihood;
    }
    given_ = total_ > 0.0 && std::isfinite(total_);
    fallback_ = filter_detail::pda_scale(sum_likelihood, pd, pg, clutter_density);
    miss = given_ ? std::max(beta_miss, 0.0) / total_ : fallback_.miss;
  }
  double operator()(std::size_t i) const noexcept {
    if (given_) return std::max(beta_plots_[i], 0.0) / total_;
    return hypotheses_[i].usable ? fallback_.per_likelihood * hypotheses_[i].likelihood : 0.0;
  }
  double miss = 1.0;

 private:
  std::span<const PlotHypothesis> hypotheses_;
  std::span<const double> beta_plots_;
  double total_ = 0.0;
  bool given_ = false;
  filter_detail::PdaScale fallback_;
};

}  // namespace

ImmFilter::ImmFilter(std::vector<AnyMotionModel> models, std::vector<std::string> names,
                     Eigen::MatrixXd transition, StateLayout layout,
                     config::MeasurementSpec measurement, double transition_interval)
    : models_(std::move(models)),
      names_(std::move(names)),
      transition_(std::move(transition)),
      transition_interval_(transition_interval),
      layout_(layout),
      measurement_(std::move(measurement)) {
  assert(!models_.empty() && models_.size() <= kMaxImmModes);
  memos_.resize(models_.size());
  assert(names_.size() == models_.size());
  assert(transition_.rows() == mode_count() && transition_.cols() == mode_count());
  assert(transition_interval_ >= 0.0);
}

Eigen::MatrixXd ImmFilter::transition_over(double dt) const {
  if (transition_interval_ <= 0.0) return transition_;
  const Eigen::Index n = transition_.rows();
  if (!(dt > 0.0)) return Eigen::MatrixXd::Identity(n, n);
  // Beyond 64 intervals every row is at the chain's stationary mix for any sensible P.
  const double steps = std::min(dt / transition_interval_, 64.0);
  const double whole = std::floor(steps);
  Eigen::MatrixXd out = Eigen::MatrixXd::Identity(n, n) +
                        (steps - whole) * (transition_ - Eigen::MatrixXd::Identity(n, n));
  Eigen::MatrixXd power = transition_;  // P^(2^b) for the bits b of `whole`
  for (auto k = static_cast<unsigned>(whole); k != 0; k >>= 1) {
    if (k & 1u) out = power * out;
    if (k > 1) power = power * power;
  }
  return out;
}

ImmEstimate ImmFilter::initial(const Gaussian& state, const Eigen::VectorXd& probabilities,
                               double time) const {
  ImmEstimate out;
  out.modes.assign(models_.size(), state);
  out.time = time;
  const int n = mode_count();
  const bool usable = probabilities.size() == n && probabilities.allFinite() &&
                      (probabilities.array() >= 0.0).all() && probabilities.sum() > 0.0;
  out.probabilities = usable ? Eigen::VectorXd(probabilities / probabilities.sum())
                             : Eigen::VectorXd::Constant(n, 1.0 / n);
  return out;
}

ImmEstimate ImmFilter::predict(const ImmEstimate& posterior, double time) const noexcept {
  ImmEstimate out;
  predict_modes(posterior, time, -1, out);
  return out;
}

void ImmFilter::predict(const ImmEstimate& posterior, double time,
                        ImmEstimate& out) const noexcept {
  predict_modes(posterior, time, -1, out);
}

ImmEstimate ImmFilter::predict_certain(const ImmEstimate& posterior, int mode,
                                       double time) const noexcept {
  ImmEstimate out;
  predict_modes(posterior, time, mode, out);
  return out;
}

void ImmFilter::predict_certain(const ImmEstimate& posterior, int mode, double time,
                                ImmEstimate& out) const noexcept {
  predict_modes(posterior, time, mode, out);
}

void ImmFilter::predict_modes(const ImmEstimate& posterior, double time, int certain,
                              ImmEstimate& out) const noexcept {
  assert(&out != &posterior);
  const double dt = time - posterior.time;
  // The chain may switch once per interval, so a prediction over several intervals is made
  // interval by interval (the remainder last), the modes interacting between them: a turn
  // can then begin within the prediction, and the turn mode's estimate spreads over its
  // possible onsets. A remainder near zero mixes with a Markov matrix near I, so the
  // prediction is continuous in dt.
  const double intervals = transition_interval_ > 0.0 ? dt / transition_interval_ : 0.0;
  if (certain >= 0 || mode_count() == 1 || !(intervals > 1.0)) {
    predict_step(posterior, time, certain, out);
    return;
  }
  const int whole = static_cast<int>(std::min(std::floor(intervals), double{kMaxPredictionSteps}));
  const double step =
      intervals > kMaxPredictionSteps ? dt / kMaxPredictionSteps : transition_interval_;
  ImmEstimate between[2];
  const ImmEstimate* from = &posterior;
  for (int k = 1; k <= whole; ++k) {
    const double at = posterior.time + step * k;
    if (!(at < time)) break;
    ImmEstimate& to = between[k % 2];
    predict_step(*from, at, -1, to);
    from = &to;
  }
  predict_step(*from, time, -1, out);
}

void ImmFilter::predict_step(const ImmEstimate& posterior, double time, int certain,
                             ImmEstimate& out) const noexcept {
  const int n = mode_count();
  assert(static_cast<int>(posterior.modes.size()) == n && posterior.probabilities.size() == n);
  out.time = time;
  out.failed_modes = 0;
  out.modes.resize(models_.size());
  const double dt = time - posterior.time;
  // The Markov matrix over dt (transition_over); within one interval, the common case, its
  // entries come straight from P without forming a matrix. Without an interval steps is 1.
  const double steps = transition_interval_ > 0.0 ? std::max(dt, 0.0) / transition_interval_ : 1.0;
  Eigen::MatrixXd long_transition;
  if (steps > 1.0) long_transition = transition_over(dt);
  const auto transition = [&](Eigen::Index i, Eigen::Index j) {
    if (steps > 1.0) return long_transition(i, j);
    if (steps == 1.0) return transition_(i, j);
    return (i == j ? 1.0 - steps : 0.0) + steps * transition_(i, j);
  };
  Eigen::VectorXd& c = out.probabilities;
  c.setZero(n);
  if (certain >= 0) {
    // mu is 1 at `certain`: c_j = p_certain,j, and every mode's mixed estimate is the certain
    // mode's own (its mixing weight is 1, the others' 0), so one prediction serves them all.
    for (int j = 0; j < n; ++j) c[j] = transition(certain, j);
    const auto k = static_cast<std::size_t>(certain);
    skytrack::predict(models_[k], layout_, posterior.modes[k], dt, memos_[k], out.modes[k]);
    for (std::size_t j = 0; j < out.modes.size(); ++j) {
      if (j != k) out.modes[j] = out.modes[k];
    }
  } else {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) c[j] += transition(i, j) * posterior.probabilities[i];  // c_j
    }
    for (int j = 0; j < n; ++j) {
      if (c[j] > 0.0) {  // eq. 1-2 with mu_i|j = p_ij mu_i / c_j
        const Gaussian mixed = moment_match(posterior.modes, [&](std::size_t i) {
          return transition(static_cast<Eigen::Index>(i), j) * posterior.probabilities[i] / c[j];
        });
        skytrack::predict(models_[j], layout_, mixed, dt, memos_[j], out.modes[j]);
      } else {  // unreachable mode: nothing to mix, carry its own estimate
        skytrack::predict(models_[j], layout_, posterior.modes[j], dt, memos_[j], out.modes[j]);
      }
    }
  }
  const double sum = c.sum();
  if (sum > 0.0 && std::isfinite(sum)) c /= sum;
}

PlotHypothesis ImmFilter::hypothesise(const ImmEstimate& predicted,
                                      const PlotMeasurement& measurement) const noexcept {
  PlotHypothesis out;
  out.per_mode.reserve(models_.size());
  for (int j = 0; j < mode_count(); ++j) {
    out.per_mode.push_back(innovate(predicted.modes[j], layout_, measurement, measurement_));
  }
  weigh(predicted, out);
  return out;
}

PlotHypothesis ImmFilter::hypothesise(const ImmEstimate& predicted,
                                      const PlotMeasurement& measurement,
                                      HypothesisShapes& shapes) const noexcept {
  if (measurement_.update == config::MeasurementUpdate::kUnscented) {
    return hypothesise(predicted, measurement);
  }
  shape(predicted, measurement, shapes);
  PlotHypothesis out;
  out.per_mode.reserve(models_.size());
  for (int j = 0; j < mode_count(); ++j) {
    out.per_mode.push_back(innovate(shapes.modes_[static_cast<std::size_t>(j)], measurement));
  }
  weigh(predicted, out);
  return out;
}

double ImmFilter::min_nis(const ImmEstimate& predicted, const PlotMeasurement& measurement,
                          HypothesisShapes& shapes) const noexcept {
  if (measurement_.update == config::MeasurementUpdate::kUnscented) {
    const PlotHypothesis whole = hypothesise(predicted, measurement);
    return whole.usable ? whole.min_nis : kInf;
  }
  shape(predicted, measurement, shapes);
  double least = kInf;
  for (const InnovationShape& mode : shapes.modes_) {
    const double nis = innovation_nis(mode, measurement);
    if (std::isfinite(nis)) least = std::min(least, nis);
  }
  return least;
}

void ImmFilter::shape(const ImmEstimate& predicted, const PlotMeasurement& measurement,
                      HypothesisShapes& shapes) const noexcept {
  if (shapes.valid_ && same_innovation_shape(shapes.model_, measurement.model)) return;
  shapes.modes_.resize(static_cast<std::size_t>(mode_count()));
  for (int j = 0; j < mode_count(); ++j) {
    shapes.modes_[static_cast<std::size_t>(j)] =
        innovation_shape(predicted.modes[j], layout_, measurement.model);
  }
  shapes.model_ = measurement.model;
  shapes.valid_ = true;
}

void ImmFilter::weigh(const ImmEstimate& predicted, PlotHypothesis& out) const noexcept {
  double max_log = -kInf;
  out.max_nis = -kInf;
  out.min_nis = kInf;
  for (int j = 0; j < mode_count(); ++j) {
    const Innovation& innovation = out.per_mode[static_cast<std::size_t>(j)];
    if (!innovation.ok) continue;
    out.usable = true;
    out.max_nis = std::max(out.max_nis, innovation.nis);
    out.min_nis = std::min(out.min_nis, innovation.nis);
    if (predicted.probabilities[j] > 0.0) max_log = std::max(max_log, innovation.log_likelihood);
  }
  if (!out.usable) {
    out.max_nis = kInf;
    out.likelihood = 0.0;
    out.log_likelihood = -kInf;
    return;
  }
  double scaled = 0.0;  // log-sum-exp of log c_j + log N_j
  for (int j = 0; j < mode_count() && std::isfinite(max_log); ++j) {
    const Innovation& innovation = out.per_mode[j];
    if (innovation.ok && predicted.probabilities[j] > 0.0) {
      scaled += predicted.probabilities[j] * std::exp(innovation.log_likelihood - max_log);
    }
  }
  out.log_likelihood = scaled > 0.0 ? max_log + std::log(scaled) : -kInf;
  out.likelihood = std::exp(out.log_likelihood);
}

ImmEstimate ImmFilter::update(const ImmEstimate& predicted,
                              std::span<const PlotHypothesis> hypotheses,
                              std::span<const double> beta_plots, double beta_miss,
                              double detection_probability, double gate_probability,
                              double clutter_density) const noexcept {
  ImmEstimate out;
  update(predicted, hypotheses, beta_plots, beta_miss, detection_probability, gate_probability,
         clutter_density, out);
  return out;
}

void ImmFilter::update(const ImmEstimate& predicted, std::span<const PlotHypothesis> hypotheses,
                       std::span<const double> beta_plots, double beta_miss,
                       double detection_probability, double gate_probability,
                       double clutter_density, ImmEstimate& out) const noexcept {
  assert(&out != &predicted);
  const int n = mode_count();
  const std::size_t count = std::min(hypotheses.size(), beta_plots.size());
  const auto innovation_at = [&](std::size_t i, int j) -> const Innovation& {
    return innovation_of(hypotheses[i], j, n);
  };
  const AssociationWeights weights(hypotheses, beta_plots, beta_miss, detection_probability,
                                   gate_probability, clutter_density);
  const double beta0 = weights.miss;
  const auto beta = [&](std::size_t i) { return weights(i); };

  out.time = predicted.time;
  out.failed_modes = 0;
  out.modes.resize(models_.size());
  out.probabilities.resize(n);
  for (int j = 0; j < n; ++j) {
    // Mode j's own weights, P(theta_i | M_j, Z) ~ beta_i N_ij / L_i and beta_0 (normalised in
    // pda_mixture): a plot that fits this mode far better than the track's mixture moves
    // this mode even when the track as a whole gives it little weight.
    const auto plot_weight = [&](std::size_t i) {
      const double b = beta(i);
      if (b <= 0.0) return 0.0;
      const double log_ratio = innovation_at(i, j).log_likelihood - hypotheses[i].log_likelihood;
      return std::isfinite(log_ratio) ? b * std::exp(log_ratio) : 0.0;
    };
    std::array<double, kKeptWeights> kept{};
    bool failed = false;
    double weight = beta0;  // beta_0 + sum_i beta_i N_ij / L_i
    for (std::size_t i = 0; i < count; ++i) {
      if (beta(i) > 0.0 && !innovation_at(i, j).ok) {
        failed = true;
        continue;
      }
      const double w = plot_weight(i);
      if (i < kKeptWeights) kept[i] = w;
      weight += w;
    }
    out.probabilities[j] = predicted.probabilities[j] * weight;
    if (failed) {
      out.failed_modes |= 1u << j;
      out.modes[j] = predicted.modes[j];
      continue;
    }
    out.modes[j] = filter_detail::pda_mixture(
        predicted.modes[j], count,
        [&](std::size_t i) -> const Innovation& { return innovation_at(i, j); },
        [&](std::size_t i) { return i < kKeptWeights ? kept[i] : plot_weight(i); }, beta0);
  }
  const double norm = out.probabilities.sum();  // eq. 4
  if (norm > 0.0 && std::isfinite(norm)) {
    out.probabilities /= norm;  // eq. 5
  } else {
    out.probabilities = predicted.probabilities;
  }
}

Gaussian ImmFilter::combine(const ImmEstimate& estimate) const noexcept {
  const double sum = estimate.probabilities.sum();
  const double norm = sum > 0.0 && std::isfinite(sum) ? sum : 1.0;
  return moment_match(estimate.modes, [&](std::size_t j) {  // eq. 6-7
    return estimate.probabilities[static_cast<Eigen::Index>(j)] / norm;
  });
}

}  // namespace skytrack
