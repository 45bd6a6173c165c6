#pragma once
// Internal: the PDA mixture (filter/pda.hpp) over any indexable set of innovations, so the
// IMM can run it on one mode's column of its plot hypotheses without copying them.
#include <cmath>
#include <cstddef>

#include "skytrack/filter/fixed_size.hpp"
#include "skytrack/filter/innovation.hpp"

namespace skytrack::filter_detail {

/// Parametric PDA weights of an isolated track (filter/pda.hpp, pda_weights):
/// beta_0 = miss, beta_i = per_likelihood * L_i. With lambda <= 0 (no clutter) the limit
/// lambda -> 0 is taken: all weight on the plots in proportion to L_i.
struct PdaScale {
  double miss = 1.0;
  double per_likelihood = 0.0;
};

inline PdaScale pda_scale(double sum_likelihood, double detection_probability,
                          double gate_probability, double clutter_density) noexcept {
  if (!(sum_likelihood > 0.0) || !std::isfinite(sum_likelihood)) return {};
  if (!(clutter_density > 0.0)) return {0.0, 1.0 / sum_likelihood};
  const double miss = 1.0 - detection_probability * gate_probability;
  const double scale = detection_probability / clutter_density;
  const double total = miss + scale * sum_likelihood;
  if (!(total > 0.0) || !std::isfinite(total)) return {};
  return {miss / total, scale / total};
}

/// pda_mixture's sums at a compile-time state size N (Vec, Mat) or at runtime sizes (StateVec,
/// StateMat): Eigen's loops over runtime sizes cost several times more.
template <class Vec, class Mat, class InnovationAt, class WeightAt>
Gaussian pda_mixture_sum(const Gaussian& predicted, std::size_t count,
                         const InnovationAt& innovation, const WeightAt& weight, double miss,
                         double total) noexcept {
  Vec mean = predicted.mean;  // x_pred + sum_i beta_i K_i nu_i
  for (std::size_t i = 0; i < count; ++i) {
    const double b = weight(i) / total;
    if (b > 0.0) mean += Vec(b * (innovation(i).gain * innovation(i).residual));
  }
  Vec dx = Vec(predicted.mean) - mean;
  Mat covariance = (miss / total) * Mat(predicted.covariance);
  covariance.noalias() += (miss / total) * (dx * dx.transpose());
  for (std::size_t i = 0; i < count; ++i) {
    const double b = weight(i) / total;
    if (b <= 0.0) continue;
    const Gaussian updated = kalman_update(predicted, innovation(i));
    dx = Vec(updated.mean) - mean;
    covariance += b * Mat(updated.covariance);
    covariance.noalias() += b * (dx * dx.transpose());
  }
  return Gaussian{mean, covariance};
}

/// innovation(i) -> const Innovation&, beta(i) -> double, for i < count.
template <class InnovationAt, class BetaAt>
Gaussian pda_mixture(const Gaussian& predicted, std::size_t count, const InnovationAt& innovation,
                     const BetaAt& beta, double beta_miss) noexcept {
  const auto weight = [&](std::size_t i) {
    const double b = beta(i);
    return (innovation(i).ok && b > 0.0) ? b : 0.0;
  };
  const double miss = beta_miss > 0.0 ? beta_miss : 0.0;
  double total = miss;
  for (std::size_t i = 0; i < count; ++i) total += weight(i);
  if (!(total > 0.0) || !std::isfinite(total)) return predicted;
  Gaussian out;
  if (with_fixed_state_size(static_cast<int>(predicted.mean.size()), [&](auto n) {
        constexpr int N = decltype(n)::value;
        out = pda_mixture_sum<Eigen::Matrix<double, N, 1>, Eigen::Matrix<double, N, N>>(
            predicted, count, innovation, weight, miss, total);
      })) {
    return out;
  }
  return pda_mixture_sum<StateVec, StateMat>(predicted, count, innovation, weight, miss, total);
}

}  // namespace skytrack::filter_detail
