// IMMBPF baseline recursion: jump-Markov Bernoulli particle filter (paper 001 §1, refs.
// [11], [12]; Ristic et al. 2013 tutorial §V for the Bernoulli particle steps).
#include "skytrack/bernoulli/imm_bernoulli_filter.hpp"

#include <algorithm>
#include <cmath>

#include "skytrack/bernoulli/bernoulli_equations.hpp"

namespace skytrack::bernoulli {

ImmBernoulliFilter::ImmBernoulliFilter(const BernoulliSpec& spec, int particles_per_model)
    : spec_(spec), rng_(spec.seed), history_(spec), births_(spec) {
  spec_.model_count = std::clamp(spec_.model_count, 1, kMaxModels);
  const auto m = static_cast<std::size_t>(spec_.model_count);
  const auto n = m * static_cast<std::size_t>(std::max(particles_per_model, 1));
  const auto total = n + m * static_cast<std::size_t>(std::max(spec_.birth_particles, 0));
  posterior_.resize(n);
  posterior_model_.resize(n);
  work_.resize(total);
  newborn_.resize(static_cast<std::size_t>(std::max(spec_.birth_particles, 0)));
  work_model_.resize(total);
  weight_.resize(total);
  ratio_.resize(total);
  book_.reset(spec_.model_count);
}

BernoulliEstimate ImmBernoulliFilter::step(double time, const Eigen::Vector2d& platform,
                                           std::span<const PolarPlot2d> plots) noexcept {
  if (!book_.follows(time)) return book_.skipped();
  return begin_scan(time, history_.load(platform, plots));
}

BernoulliEstimate ImmBernoulliFilter::step(double time, const Eigen::Vector2d& platform,
                                           std::span<const PlotMeasurement> plots) noexcept {
  if (!book_.follows(time)) return book_.skipped();
  return begin_scan(time, history_.load(plots, platform));
}

BernoulliEstimate ImmBernoulliFilter::begin_scan(double time, int rejected) noexcept {
  BernoulliEstimate estimate =
      book_.open(time, rejected, static_cast<int>(history_.current().size()));
  if (book_.started()) recurse(time - book_.last_time(), estimate);
  history_.advance(time);
  return book_.close(estimate);
}

std::size_t ImmBernoulliFilter::predict(double survival_mass,
                                        const std::array<double, kMaxModels>& birth_mass,
                                        double q_predicted, double dt) noexcept {
  const int m = spec_.model_count;
  std::array<ModelDynamics, kMaxModels> dynamics;
  for (int j = 0; j < m; ++j) dynamics[j] = make_dynamics(spec_.models[j], dt);
  std::size_t n = 0;
  if (survival_mass > 0.0) {  // every particle jumps by the Markov chain, then moves
    const double w = survival_mass / q_predicted / static_cast<double>(posterior_.size());
    for (std::size_t k = 0; k < posterior_.size(); ++k, ++n) {
      const auto& row = spec_.transition[posterior_model_[k]];
      const double u = rng_.uniform();
      int j = 0;
      for (double c = row[0]; j + 1 < m && c < u; c += row[++j]) {
      }
      work_[n] = posterior_[k];
      work_model_[n] = static_cast<std::uint8_t>(j);
      propagate(dynamics[j], work_[n], rng_);
      weight_[n] = w;
    }
  }
  const auto per_model = static_cast<std::size_t>(std::max(spec_.birth_particles, 0));
  for (int j = 0; j < m; ++j) {
    birth_begin_[j] = n;
    if (!(birth_mass[j] > 0.0) || per_model == 0) continue;
    std::copy(newborn_.begin(), newborn_.end(), work_.begin() + static_cast<std::ptrdiff_t>(n));
    const double w = birth_mass[j] / q_predicted / static_cast<double>(per_model);
    for (std::size_t k = n; k < n + per_model; ++k) {
      work_model_[k] = static_cast<std::uint8_t>(j);
      propagate(dynamics[j], work_[k], rng_);
      weight_[k] = w;
    }
    n += per_model;
  }
  birth_begin_[m] = n;
  return n;
}

void ImmBernoulliFilter::recurse(double dt, BernoulliEstimate& estimate) noexcept {
  const int m = spec_.model_count;
  const double pd = spec_.detection_probability;
  const bool pairs = spec_.birth_proposal == BirthProposal::kPlotPairs;
  births_.choose_seeds(history_.previous(),
                       pairs && history_.scans_seen() >= 2 ? history_.before_previous()
                                                           : std::span<const ScanPlot>{},
                       history_.previous_time() - history_.before_previous_time(),
                       static_cast<std::size_t>(std::max(spec_.birth_particles, 0)), rng_);
  const bool has_birth = births_.seed_count() > 0 && spec_.birth_particles > 0;
  if (has_birth) births_.sample(newborn_, rng_);  // shared by the models, as in the MMBPF
  const double survival = has_posterior_ ? spec_.survival_probability * q_ : 0.0;
  std::array<double, kMaxModels> birth{};
  double q_predicted = survival;  // eq. 9
  for (int j = 0; j < m; ++j) {
    birth[j] =
        has_birth ? spec_.birth_probability * (1.0 - q_) * spec_.birth_model_probabilities[j] : 0.0;
    q_predicted += birth[j];
  }
  if (!(q_predicted > 0.0)) {
    q_ = 0.0;
    has_posterior_ = false;
    estimate.existence = 0.0;
    estimate.target_reported = false;
    return;
  }
  const std::size_t n = predict(survival, birth, q_predicted, dt);
  std::fill_n(ratio_.begin(), n, 0.0);
  const auto plots = history_.current();
  const double gate = spec_.gate_distance_squared;
  const std::span<const Particle> work(work_.data(), n);
  const std::span<double> ratio(ratio_.data(), n);
  const std::size_t survivors = birth_begin_[0];
  accumulate_likelihood_ratios(work.first(survivors), plots, gate, ratio.first(survivors));
  for (int j = 0; j < m; ++j) {
    const std::size_t b0 = birth_begin_[j], count = birth_begin_[j + 1] - b0;
    for (std::size_t s = 0; s < births_.seed_count() && count > 0; ++s) {
      const std::size_t b = b0 + births_.group_begin(s, count);
      const std::size_t e = b0 + births_.group_begin(s + 1, count);
      accumulate_likelihood_ratios(work.subspan(b, e - b), plots, gate, ratio.subspan(b, e - b));
    }
  }
  double integral = 0.0;  // eq. 25 over the whole cloud
  for (std::size_t k = 0; k < n; ++k) integral += weight_[k] * ratio_[k];
  const double one = 1.0, omd = one_minus_delta(pd, integral);
  q_ = update_existence(q_predicted, std::span(&one, 1), std::span(&omd, 1));
  estimate_and_resample(n, estimate);
  estimate.existence = q_;
  estimate.target_reported = q_ > spec_.existence_threshold;
}

void ImmBernoulliFilter::estimate_and_resample(std::size_t n,
                                               BernoulliEstimate& estimate) noexcept {
  const int m = spec_.model_count;
  const double pd = spec_.detection_probability;
  double sum = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    weight_[k] *= 1.0 - pd + pd * ratio_[k];
    sum += weight_[k];
  }
  const double scale = sum > 0.0 ? 1.0 / sum : 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    weight_[k] = sum > 0.0 ? weight_[k] * scale : 1.0 / static_cast<double>(n);
  }
  // Model probabilities as sums of weights, per-model moments in one pass.
  std::array<double, kMaxModels> mass{};
  std::array<Eigen::Vector4d, kMaxModels> first;
  std::array<Eigen::Matrix4d, kMaxModels> second;
  for (int j = 0; j < m; ++j) {
    first[j].setZero();
    second[j].setZero();
  }
  for (std::size_t k = 0; k < n; ++k) {
    const int j = work_model_[k];
    const Eigen::Vector4d x(work_[k].x, work_[k].vx, work_[k].y, work_[k].vy);
    mass[j] += weight_[k];
    first[j] += weight_[k] * x;
    second[j].noalias() += weight_[k] * x * x.transpose();
  }
  estimate.mean.setZero();
  std::array<Eigen::Vector4d, kMaxModels> means;
  for (int j = 0; j < m; ++j) {
    means[j] = mass[j] > 0.0 ? Eigen::Vector4d(first[j] / mass[j]) : Eigen::Vector4d::Zero();
    estimate.mean += mass[j] * means[j];
    estimate.model_probabilities[j] = mass[j];
  }
  estimate.covariance.setZero();
  for (int j = 0; j < m; ++j) {
    if (!(mass[j] > 0.0)) continue;
    const Eigen::Matrix4d cov = second[j] / mass[j] - means[j] * means[j].transpose();
    const Eigen::Vector4d d = means[j] - estimate.mean;
    estimate.covariance += mass[j] * (cov + d * d.transpose());
  }
  estimate.model_count = m;
  // Systematic resampling of the whole cloud, model indices with their particles.
  const double step = 1.0 / static_cast<double>(posterior_.size());
  const double u0 = rng_.uniform();
  double cumulative = weight_[0];
  std::size_t source = 0;
  for (std::size_t k = 0; k < posterior_.size(); ++k) {
    const double target = (u0 + static_cast<double>(k)) * step;
    while (cumulative < target && source + 1 < n) cumulative += weight_[++source];
    posterior_[k] = work_[source];
    posterior_model_[k] = work_model_[source];
  }
  has_posterior_ = true;
}

}  // namespace skytrack::bernoulli
