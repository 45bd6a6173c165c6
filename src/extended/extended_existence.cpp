// Existence probability of an extended track (see extended_existence.hpp).
#include "skytrack/extended/extended_existence.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include <Eigen/Cholesky>

namespace skytrack::extended {
namespace {

double logit(double r) {
  return std::log(r / (1.0 - r));
}

// ln Poisson(n; mean).
double log_poisson(int n, double mean) {
  return n * std::log(mean) - mean - std::lgamma(static_cast<double>(n) + 1.0);
}

// The plots' joint density under one track's model (object_plots_log_density).
double log_f(std::span<const Eigen::Vector2d> plots, const PlotsModel& m) {
  return object_plots_log_density(plots, m.centre, m.centre_cov, m.spread);
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

double object_plots_log_density(std::span<const Eigen::Vector2d> plots,
                                const Eigen::Vector2d& centre, const Eigen::Matrix2d& centre_cov,
                                const Eigen::Matrix2d& spread) noexcept {
  constexpr double kNone = -std::numeric_limits<double>::infinity();
  const int n = static_cast<int>(plots.size());
  if (n == 0) return kNone;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& z : plots) mean += z;
  mean /= static_cast<double>(n);
  Eigen::Matrix2d sample = Eigen::Matrix2d::Zero();
  for (const Eigen::Vector2d& z : plots) sample.noalias() += (z - mean) * (z - mean).transpose();
  const Eigen::LLT<Eigen::Matrix2d> scatter(spread + sample / static_cast<double>(n));
  const Eigen::LLT<Eigen::Matrix2d> about(centre_cov + spread / static_cast<double>(n));
  if (scatter.info() != Eigen::Success || about.info() != Eigen::Success) return kNone;
  auto log_det = [](const Eigen::LLT<Eigen::Matrix2d>& llt) {
    return 2.0 * std::log(llt.matrixL()(0, 0) * llt.matrixL()(1, 1));
  };
  const double log_2pi = std::log(2.0 * std::numbers::pi);
  const Eigen::Vector2d nu = mean - centre;
  double log_f = -log_2pi - 0.5 * log_det(about) - 0.5 * nu.dot(about.solve(nu));
  double deviations = 0.0;
  for (const Eigen::Vector2d& z : plots) deviations += (z - mean).dot(scatter.solve(z - mean));
  return log_f - (n - 1) * log_2pi - 0.5 * (n - 1) * log_det(scatter) - std::log(n) -
         0.5 * deviations;
}

double object_plots_log_ratio(std::span<const Eigen::Vector2d> plots, const Eigen::Vector2d& centre,
                              const Eigen::Matrix2d& centre_cov, const Eigen::Matrix2d& spread,
                              const ExistenceSpec& spec) noexcept {
  const int n = static_cast<int>(plots.size());
  if (n == 0 || !(spec.clutter_density > 0.0) || !(spec.expected_plots > 0.0) ||
      !(spec.detection_probability > 0.0 && spec.detection_probability < 1.0)) {
    return -std::numeric_limits<double>::infinity();
  }
  const double p_d = spec.detection_probability;
  return std::log(p_d / (1.0 - p_d)) - spec.expected_plots +
         n * (std::log(spec.expected_plots) - std::log(spec.clutter_density)) +
         object_plots_log_density(plots, centre, centre_cov, spread);
}

double split_log_ratio(std::span<const Eigen::Vector2d> own, std::span<const Eigen::Vector2d> other,
                       const PlotsModel& own_model, const PlotsModel& other_model,
                       const ExistenceSpec& spec) {
  const double p_d = spec.detection_probability;
  if (own.empty() || other.empty() || !(p_d > 0.0 && p_d < 1.0)) {
    return -std::numeric_limits<double>::infinity();
  }
  std::vector<Eigen::Vector2d> all(own.begin(), own.end());
  all.insert(all.end(), other.begin(), other.end());
  return std::log(p_d / (1.0 - p_d)) - spec.expected_plots + log_f(own, own_model) +
         log_f(other, other_model) - log_f(all, other_model);
}

double exchange_log_ratio(std::span<const Eigen::Vector2d> own,
                          std::span<const Eigen::Vector2d> other, const PlotsModel& own_model,
                          const PlotsModel& other_model) {
  if (own.empty() || other.empty()) return -std::numeric_limits<double>::infinity();
  return log_f(other, own_model) + log_f(own, other_model) - log_f(own, own_model) -
         log_f(other, other_model);
}

double existence_probability(double log_odds) noexcept {
  return 1.0 / (1.0 + std::exp(-log_odds));
}

}  // namespace skytrack::extended
