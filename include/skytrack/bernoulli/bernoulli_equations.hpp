#pragma once
// The Bernoulli recursion of paper 001 on the existence probability and the model
// probabilities, apart from the particles, so each equation can be checked by hand.
#include <span>

namespace skytrack::bernoulli {

/// Eq. 9: q_{k|k-1} = p_b (1 - q_{k-1}) + p_s q_{k-1}.
inline double predict_existence(double q, double survival, double birth) noexcept {
  return birth * (1.0 - q) + survival * q;
}

/// Eq. 15 / 25 with the integral done: 1 - Delta = 1 - p_d + p_d sum_z integral g s / kappa,
/// where `ratio_integral` is sum_z integral g(z|x) s(x) dx / kappa(z).
inline double one_minus_delta(double detection, double ratio_integral) noexcept {
  return 1.0 - detection + detection * ratio_integral;
}

/// Eq. 13: q_k from q_{k|k-1}, the predicted model probabilities mu_{k|k-1} and each
/// model's 1 - Delta_k.
inline double update_existence(double q_predicted, std::span<const double> mu_predicted,
                               std::span<const double> one_minus_delta) noexcept {
  double sum = 0.0;
  for (std::size_t m = 0; m < mu_predicted.size(); ++m) sum += mu_predicted[m] * one_minus_delta[m];
  const double numerator = sum * q_predicted;
  const double denominator = 1.0 - q_predicted + numerator;
  return denominator > 0.0 ? numerator / denominator : 0.0;
}

/// Eq. 17: mu_k = mu_{k|k-1} (1 - Delta_k), normalised; `mu` is overwritten. Unchanged when
/// every product is 0.
inline void update_model_probabilities(std::span<double> mu,
                                       std::span<const double> one_minus_delta) noexcept {
  double sum = 0.0;
  for (std::size_t m = 0; m < mu.size(); ++m) sum += mu[m] * one_minus_delta[m];
  if (!(sum > 0.0)) return;
  for (std::size_t m = 0; m < mu.size(); ++m) mu[m] = mu[m] * one_minus_delta[m] / sum;
}

}  // namespace skytrack::bernoulli
