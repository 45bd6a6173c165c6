#pragma once
// Probabilistic data association update (Bar-Shalom & Tse 1975; Bar-Shalom, Willett & Tian
// 2011, §3.4; paper 003 eq. 8-10 with the JPDA marginals beta as weights).
// The posterior is the moment-matched mixture of the miss hypothesis (the prediction, weight
// beta_0) and each plot's own Kalman update (weight beta_i):
//   x = beta_0 x_pred + sum_i beta_i x_i,
//   P = beta_0 P_pred + sum_i beta_i P_i + sum_{i>=0} beta_i (x_i - x)(x_i - x)'.
// Each plot may have its own H, S and K (the polar Jacobian differs per plot). When they are
// common this is Bar-Shalom's PDA: x = x_pred + K nu, nu = sum beta_i nu_i,
//   P = beta_0 P_pred + (1 - beta_0) P_c + K (sum beta_i nu_i nu_i' - nu nu') K'.
#include <span>

#include "skytrack/filter/innovation.hpp"
#include "skytrack/filter/state.hpp"

namespace skytrack {

/// Innovations that are not ok are left out; the weights of the others (and beta_miss) are
/// renormalised to sum to 1. Returns the prediction when no weight is left.
Gaussian pda_update(const Gaussian& predicted, std::span<const Innovation> innovations,
                    std::span<const double> beta_plots, double beta_miss) noexcept;

/// PDA association weights of one isolated track with Poisson clutter of density lambda
/// (parametric PDA, Bar-Shalom, Daum & Huang 2009, IEEE CSM 29(6)): with L_i the plot
/// likelihoods,
///   beta_i = (PD / lambda) L_i / D,  beta_0 = (1 - PD PG) / D,
///   D = 1 - PD PG + (PD / lambda) sum_i L_i.
/// lambda <= 0 takes the limit lambda -> 0 (beta_0 = 0, beta_i ~ L_i); with no usable
/// likelihood beta_0 = 1. Writes beta_plots (same size as likelihoods) and returns beta_0.
double pda_weights(std::span<const double> likelihoods, double detection_probability,
                   double gate_probability, double clutter_density,
                   std::span<double> beta_plots) noexcept;

}  // namespace skytrack
