// Existence probability of an extended track (see extended_existence.hpp).
#include "skytrack/extended/extended_existence.hpp"

#include <algorithm>
#include <cmath>

namespace skytrack::extended {
namespace {

double logit(double r) {
  return std::log(r / (1.0 - r));
}

// ln Poisson(n; mean).
double log_poisson(int n, double mean) {
  return n * std::log(mean) - mean - std::lgamma(static_cast<double>(n) + 1.0);
}

}  // namespace

double existence_birth(const ExistenceSpec& spec) noexcept {
  return logit(spec.birth);
}

double existence_predict(double log_odds, const ExistenceSpec& spec) noexcept {
  // odds' = p_s r / (1 - p_s r) with r = odds / (1 + odds).
  const double odds = std::exp(std::min(log_odds, 700.0));
  return std::log(spec.survival * odds / (1.0 + odds - spec.survival * odds));
}

double existence_hit(double log_odds, int plots, double gate_area,
                     const ExistenceSpec& spec) noexcept {
  const double clutter = std::max(spec.clutter_density * gate_area, 1e-12);
  const double log_ratio = std::log(spec.detection_probability) +
                           log_poisson(plots, spec.expected_plots) - log_poisson(plots, clutter);
  return log_odds + log_ratio;
}

double existence_miss(double log_odds, int min_plots, const ExistenceSpec& spec) noexcept {
  // P(n >= m) for n ~ Poisson(gamma).
  double below = 0.0;
  for (int n = 0; n < min_plots; ++n) below += std::exp(log_poisson(n, spec.expected_plots));
  const double detected = spec.detection_probability * std::clamp(1.0 - below, 0.0, 1.0);
  return log_odds + std::log1p(-std::min(detected, 1.0 - 1e-12));
}

double existence_probability(double log_odds) noexcept {
  return 1.0 / (1.0 + std::exp(-log_odds));
}

}  // namespace skytrack::extended
