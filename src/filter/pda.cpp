// PDA update as a moment-matched mixture (Bar-Shalom & Tse 1975; paper 003 eq. 8-10 with
// the JPDA marginals as weights) and the parametric PDA weights of an isolated track.
#include "skytrack/filter/pda.hpp"

#include <algorithm>
#include <cmath>

#include "pda_detail.hpp"

namespace skytrack {

Gaussian pda_update(const Gaussian& predicted, std::span<const Innovation> innovations,
                    std::span<const double> beta_plots, double beta_miss) noexcept {
  const std::size_t count = std::min(innovations.size(), beta_plots.size());
  return filter_detail::pda_mixture(
      predicted, count, [&](std::size_t i) -> const Innovation& { return innovations[i]; },
      [&](std::size_t i) { return beta_plots[i]; }, beta_miss);
}

double pda_weights(std::span<const double> likelihoods, double detection_probability,
                   double gate_probability, double clutter_density,
                   std::span<double> beta_plots) noexcept {
  const std::size_t count = std::min(likelihoods.size(), beta_plots.size());
  const auto usable = [&](std::size_t i) {
    return std::isfinite(likelihoods[i]) ? std::max(likelihoods[i], 0.0) : 0.0;
  };
  double sum = 0.0;
  for (std::size_t i = 0; i < count; ++i) sum += usable(i);
  const filter_detail::PdaScale scale =
      filter_detail::pda_scale(sum, detection_probability, gate_probability, clutter_density);
  std::fill(beta_plots.begin(), beta_plots.end(), 0.0);
  for (std::size_t i = 0; i < count; ++i) beta_plots[i] = scale.per_likelihood * usable(i);
  return scale.miss;
}

}  // namespace skytrack
