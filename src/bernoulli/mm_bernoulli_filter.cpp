// MMBPF recursion (paper 001, §3.2 steps 1-4, eq. 9-28).
#include "skytrack/bernoulli/mm_bernoulli_filter.hpp"

#include <algorithm>
#include <cmath>

#include "skytrack/bernoulli/bernoulli_equations.hpp"

namespace skytrack::bernoulli {
namespace {

/// Block resampling needs the survivors to carry the posterior (the newborns, resampled with
/// neither block, hold less than 1 - this) and one plot to explain their likelihood (the
/// others and the miss term hold less than 1 - this), so that it factorises.
constexpr double kBlockShare = 0.99;
/// ... and the model's predicted density to be near the product of its blocks: their mutual
/// information (block_dependence) at most this [nats], a canonical correlation of 0.30 for
/// one pair. The block resampling drops that dependence.
constexpr double kBlockDependence = 0.05;

}  // namespace

MmBernoulliFilter::MmBernoulliFilter(const BernoulliSpec& spec)
    : spec_(spec), rng_(spec.seed), history_(spec), births_(spec) {
  spec_.model_count = std::clamp(spec_.model_count, 1, kMaxModels);
  const auto births = static_cast<std::size_t>(std::max(spec_.birth_particles, 0));
  newborn_.resize(births);
  for (int j = 0; j < spec_.model_count; ++j) {
    const auto n = static_cast<std::size_t>(std::max(spec_.models[j].particles, 1));
    posterior_[j].resize(n);
    block_scratch_.resize(std::max(block_scratch_.size(), 2 * n));
    work_[j].resize(n + births);
    weight_[j].resize(n + births);
    ratio_[j].resize(n + births);
  }
  reset();
}

void MmBernoulliFilter::reset() noexcept {
  for (int j = 0; j < spec_.model_count; ++j) mu_[j] = spec_.birth_model_probabilities[j];
  q_ = 0.0;
  has_posterior_ = false;
  history_.clear();
  book_.reset(spec_.model_count);
}

BernoulliEstimate MmBernoulliFilter::step(double time, const Eigen::Vector2d& platform,
                                          std::span<const PlotMeasurement> plots) noexcept {
  if (!book_.follows(time)) return book_.skipped();
  return begin_scan(time, history_.load(plots, platform));
}

BernoulliEstimate MmBernoulliFilter::step(double time, const Eigen::Vector2d& platform,
                                          std::span<const PolarPlot2d> plots) noexcept {
  if (!book_.follows(time)) return book_.skipped();
  return begin_scan(time, history_.load(platform, plots));
}

BernoulliEstimate MmBernoulliFilter::begin_scan(double time, int rejected) noexcept {
  BernoulliEstimate estimate =
      book_.open(time, rejected, static_cast<int>(history_.current().size()));
  if (book_.started()) recurse(time - book_.last_time(), estimate);
  history_.advance(time);
  return book_.close(estimate);
}

std::size_t MmBernoulliFilter::predict_model(int j, double survival_mass, double birth_mass,
                                             const std::array<double, kMaxModels>& mu_predicted,
                                             const ModelDynamics& dynamics) noexcept {
  const int m = spec_.model_count;
  std::vector<Particle>& work = work_[j];
  std::vector<double>& weight = weight_[j];
  const std::size_t survivors = survival_mass > 0.0 ? posterior_[j].size() : 0;
  // Step 2 (eq. 19): N_j particles drawn from the previous posteriors of all models, as many
  // from model i as the mixing probability pi_ij mu_i / mu_{k|k-1}(j) gives (systematic
  // allocation of the counts), picked from model i's equally weighted cloud at a regular
  // stride from a random start (systematic, not multinomial, draws: a model's own cloud
  // passes on whole instead of losing a third of its distinct particles each scan).
  std::size_t n = 0;
  MomentAccumulator parents;  // local: its sums stay in registers in the loops below
  double cumulative = 0.0;
  const double offset = rng_.uniform();
  int last_source = 0;  // the last model with a share: it fills what rounding leaves
  for (int i = 0; i < m && survivors > 0; ++i) {
    const double share = spec_.transition[i][j] * mu_[i] / mu_predicted[j];
    if (share > 0.0) last_source = i;
    cumulative += share;
    const auto end = std::min(
        survivors, static_cast<std::size_t>(std::max(0.0, cumulative * survivors + offset)));
    if (end <= n) continue;
    const std::vector<Particle>& source = posterior_[i];
    const double stride = static_cast<double>(source.size()) / static_cast<double>(end - n);
    const double start = rng_.uniform() * stride;
    // Gather, then the parents' moments, then the propagation, each a tight loop (the
    // moments' sums stay in registers; interleaved with the sampler they spill).
    const std::size_t begin = n;
    for (std::size_t k = 0; n < end; ++n, ++k) {
      const auto index = std::min(
          source.size() - 1, static_cast<std::size_t>(start + static_cast<double>(k) * stride));
      work[n] = source[index];
    }
    for (std::size_t k = begin; k < end; ++k) parents.add(work[k]);
    for (std::size_t k = begin; k < end; ++k) propagate(dynamics, work[k], rng_);
  }
  for (; n < survivors; ++n) {  // rounding left a slot: the last model fills it
    const std::vector<Particle>& source = posterior_[last_source];
    work[n] = source[rng_.index(static_cast<std::uint32_t>(source.size()))];
    parents.add(work[n]);
    propagate(dynamics, work[n], rng_);
  }
  survivors_[j] = survivors;
  parents.moments(predicted_mean_[j], predicted_covariance_[j]);
  predict_moments(dynamics, predicted_mean_[j], predicted_covariance_[j]);
  const std::size_t newborn = birth_mass > 0.0 ? work.size() - posterior_[j].size() : 0;
  // The newborn cloud at scan k-1 is drawn once per scan and shared by the models (common
  // random numbers: each model's birth cloud is still a sample of the proposal).
  for (std::size_t k = 0; k < newborn; ++k) {
    work[survivors + k] = newborn_[k];
    propagate(dynamics, work[survivors + k], rng_);
  }
  // Eq. 23-24 within the model: survivors share p_s q mu, newborns p_b (1 - q) gamma.
  const double total = survival_mass + birth_mass;
  const double w_survivor = survivors ? survival_mass / total / static_cast<double>(survivors) : 0;
  const double w_newborn = newborn ? birth_mass / total / static_cast<double>(newborn) : 0;
  std::fill_n(weight.begin(), survivors, w_survivor);
  std::fill_n(weight.begin() + static_cast<std::ptrdiff_t>(survivors), newborn, w_newborn);
  return survivors + newborn;
}

double MmBernoulliFilter::likelihood_integral(int j, std::size_t survivors,
                                              std::size_t count) noexcept {
  const std::span<const Particle> work(work_[j].data(), count);
  const std::span<double> ratio(ratio_[j].data(), count);
  std::fill(ratio.begin(), ratio.end(), 0.0);
  const auto plots = history_.current();
  const double gate = spec_.gate_distance_squared;
  // Gate per compact block: the survivors, then each birth seed's group.
  dominant_[j] =
      accumulate_likelihood_ratios(work.first(survivors), plots, gate, ratio.first(survivors));
  const std::size_t newborn = count - survivors;
  for (std::size_t s = 0; s < births_.seed_count() && newborn > 0; ++s) {
    const std::size_t b = survivors + births_.group_begin(s, newborn);
    const std::size_t e = survivors + births_.group_begin(s + 1, newborn);
    accumulate_likelihood_ratios(work.subspan(b, e - b), plots, gate, ratio.subspan(b, e - b));
  }
  double integral = 0.0;  // eq. 25
  for (std::size_t n = 0; n < count; ++n) integral += weight_[j][n] * ratio[n];
  return integral;
}

Eigen::Vector4d MmBernoulliFilter::model_estimate(int j, const BlockMean& survivors,
                                                  const Eigen::Vector4d& mean) const noexcept {
  // The weighted mean of the velocity carries, besides E[v|p], the residual v - E[v|p]:
  // independent of the position under the predicted density, so of the likelihood, its
  // posterior mean is its prior mean 0, but its weighted average over the few particles
  // the weights keep (ESS ~ 10 % of N_j when the model's prediction is wide, the CT2 model's
  // 40 m/s^2) is Monte Carlo noise. Conditioning on the position (Rao-Blackwellisation,
  // conditional Monte Carlo) drops that noise for the survivors; newborns keep their own
  // weighted mean (their birth cloud is not one Gaussian).
  Eigen::Vector4d estimate = mean;
  if (survivors_[j] < 2 || !(survivors.mass > 0.0)) return estimate;
  const Eigen::Vector4d& s = survivors.mean;
  double cx = s[1], cy = s[3];
  if (!velocity_given_position(predicted_mean_[j], predicted_covariance_[j], s[0], s[2], cx, cy)) {
    return estimate;
  }
  estimate[1] += survivors.mass * (cx - s[1]);  // the survivors' share of the model's velocity
  estimate[3] += survivors.mass * (cy - s[3]);
  return estimate;
}

bool MmBernoulliFilter::block_resample_model(int j, const BlockMean& survivors,
                                             const Eigen::Vector4d& mean,
                                             Eigen::Vector4d& estimate) noexcept {
  // The CV transition moves (a, v.along) and (c, v.across) apart in any fixed frame; a turn
  // rotates the velocity from one block into the other.
  const std::size_t s = survivors_[j];
  if (spec_.models[j].turn_rate != 0.0 || s == 0 || s != posterior_[j].size()) return false;
  const DominantPlot& d = dominant_[j];
  const double pd = spec_.detection_probability;
  const double integral = (1.0 - pd) * static_cast<double>(s) + pd * d.total;  // sum_n l(x_n)
  if (!(survivors.mass >= kBlockShare) || !(pd * d.sum >= kBlockShare * integral)) return false;
  const ScanPlot& plot = history_.current()[d.index];
  if (!(block_dependence(plot, predicted_covariance_[j]) <= kBlockDependence)) return false;
  Eigen::Vector4d block;
  const double u_along = rng_.uniform(), u_across = rng_.uniform();
  if (!block_resample(std::span<const Particle>(work_[j].data(), s), plot, u_along, u_across,
                      block_scratch_, posterior_[j], block)) {
    return false;
  }
  // The survivors' share of the model's mean takes their block mean, and their velocity is
  // conditioned on its position (model_estimate, step 5).
  const Eigen::Vector4d blended = mean + survivors.mass * (block - survivors.mean);
  estimate = model_estimate(j, BlockMean{survivors.mass, block}, blended);
  return true;
}

void MmBernoulliFilter::update_and_resample(const std::array<std::size_t, kMaxModels>& count,
                                            double dt, BernoulliEstimate& estimate) noexcept {
  const int m = spec_.model_count;
  const double pd = spec_.detection_probability;
  // Eq. 26-27 and step 3(3): weights times l(x), normalised, resampled to N_j.
  estimate.mean.setZero();
  std::array<Eigen::Vector4d, kMaxModels> means;
  std::array<Eigen::Matrix4d, kMaxModels> covariances;
  std::array<Eigen::Vector4d, kMaxModels> estimates;  // x_j of eq. 28
  for (int j = 0; j < m; ++j) {
    const std::size_t n = count[j];
    if (n == 0) {  // no mass in this model: keep its cloud for the mixing, empty of weight
      means[j].setZero();
      covariances[j].setZero();
      estimates[j].setZero();
      continue;
    }
    double sum = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      weight_[j][k] *= 1.0 - pd + pd * ratio_[j][k];
      sum += weight_[j][k];
    }
    const double scale = sum > 0.0 ? 1.0 / sum : 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      weight_[j][k] = sum > 0.0 ? weight_[j][k] * scale : 1.0 / static_cast<double>(n);
    }
    const std::span<const Particle> cloud(work_[j].data(), n);
    const std::span<const double> w(weight_[j].data(), n);
    BlockMean survivors;  // taken in the moments' pass
    weighted_moments(cloud, w, survivors_[j], means[j], covariances[j], survivors);
    if (!block_resample_model(j, survivors, means[j], estimates[j])) {
      estimates[j] = model_estimate(j, survivors, means[j]);
      systematic_resample(cloud, w, rng_.uniform(), posterior_[j]);
    }
    const auto n_j = posterior_[j].size();
    // Step 3(3) keeps N_j particles, but after a birth they descend from the few newborns
    // near the target and the model's small process noise (5 m/s^2 for the CV) spreads their
    // copies far less than the posterior's velocity spread: regularise with the kernel for
    // the effective number of draws the weights hold, the model's own moments only (no
    // particle interaction). Only a reported target: a cloud of clutter-born hypotheses is
    // renewed by the births anyway.
    if (q_ > spec_.existence_threshold) {
      const double draws = std::min(effective_sample_size(w), static_cast<double>(n_j));
      const double velocity_sigma = spec_.models[j].accel_sigma * dt;
      regularise_velocity(posterior_[j], means[j], covariances[j], optimal_kernel_bandwidth(draws),
                          velocity_sigma * velocity_sigma, rng_);
    }
    estimate.mean += mu_[j] * estimates[j];
  }
  has_posterior_ = true;
  estimate.covariance.setZero();  // eq. 28 and its spread of means
  for (int j = 0; j < m; ++j) {
    if (count[j] == 0) continue;
    const Eigen::Vector4d d = estimates[j] - estimate.mean;
    estimate.covariance += mu_[j] * (covariances[j] + d * d.transpose());
  }
}

void MmBernoulliFilter::recurse(double dt, BernoulliEstimate& estimate) noexcept {
  const int m = spec_.model_count;
  const double pd = spec_.detection_probability;
  const bool pairs = spec_.birth_proposal == BirthProposal::kPlotPairs;
  const double pair_dt = history_.previous_time() - history_.before_previous_time();
  births_.choose_seeds(history_.previous(),
                       pairs && history_.scans_seen() >= 2 ? history_.before_previous()
                                                           : std::span<const ScanPlot>{},
                       pair_dt, static_cast<std::size_t>(std::max(spec_.birth_particles, 0)), rng_);
  const bool has_birth = births_.seed_count() > 0 && spec_.birth_particles > 0;
  if (has_birth) births_.sample(newborn_, rng_);
  // Step 1 (eq. 18) and eq. 9-10 split into survival and birth masses per model.
  std::array<double, kMaxModels> mu_predicted{}, survival{}, birth{}, mu_full{}, omd{};
  double q_predicted = 0.0;
  for (int j = 0; j < m; ++j) {
    for (int i = 0; i < m; ++i) mu_predicted[j] += spec_.transition[i][j] * mu_[i];
    survival[j] = has_posterior_ ? spec_.survival_probability * q_ * mu_predicted[j] : 0.0;
    birth[j] =
        has_birth ? spec_.birth_probability * (1.0 - q_) * spec_.birth_model_probabilities[j] : 0.0;
    q_predicted += survival[j] + birth[j];
  }
  if (!(q_predicted > 0.0)) {
    q_ = 0.0;
    has_posterior_ = false;
    estimate.existence = 0.0;
    estimate.target_reported = false;
    return;
  }
  std::array<std::size_t, kMaxModels> count{}, survivors{};
  for (int j = 0; j < m; ++j) {
    mu_full[j] = (survival[j] + birth[j]) / q_predicted;
    if (!(mu_full[j] > 0.0)) continue;
    const ModelDynamics dynamics = make_dynamics(spec_.models[j], dt);
    count[j] = predict_model(j, survival[j], birth[j], mu_predicted, dynamics);
    survivors[j] = survival[j] > 0.0 ? posterior_[j].size() : 0;
    omd[j] = one_minus_delta(pd, likelihood_integral(j, survivors[j], count[j]));
  }
  q_ = update_existence(q_predicted, std::span(mu_full).first(m), std::span(omd).first(m));
  mu_ = mu_full;
  update_model_probabilities(std::span(mu_).first(m), std::span(omd).first(m));
  update_and_resample(count, dt, estimate);
  estimate.existence = q_;
  estimate.target_reported = q_ > spec_.existence_threshold;
  for (int j = 0; j < m; ++j) estimate.model_probabilities[j] = mu_[j];
  estimate.model_count = m;
}

}  // namespace skytrack::bernoulli
