#pragma once
// What a Bernoulli filter reports after each scan: the existence probability q (published
// every batch) and, meaningful while q exceeds the threshold, the model-probability-weighted
// state (paper 001, eq. 28) and the model probabilities (eq. 17).
#include <array>
#include <cstdint>
#include <span>

#include <Eigen/Core>

#include "skytrack/bernoulli/bernoulli_spec.hpp"

namespace skytrack::bernoulli {

/// A polar plot for the plain per-scan call: range and azimuth (clockwise from north, in the
/// tracking frame) about the scan's platform position, with their standard deviations.
struct PolarPlot2d {
  double range = 0.0;           // [m]
  double azimuth = 0.0;         // [rad]
  double sigma_range = 5.0;     // [m]
  double sigma_azimuth = 3e-3;  // [rad]
};

struct BernoulliEstimate {
  double time = 0.0;             // [s] the scan's
  double existence = 0.0;        // q_k
  bool target_reported = false;  // q_k > existence_threshold
  /// How many times q has risen above the threshold since the start: a new value is a new
  /// target (the pipeline gives it a new track number), the same value the same track.
  std::uint64_t report_epoch = 0;
  /// Eq. 28: sum_m mu_m x_m, [x, vx, y, vy] [m, m/s] in the tracking frame, and the mixture
  /// covariance sum_m mu_m (P_m + (x_m - x)(x_m - x)'). Zero before any particle exists.
  Eigen::Vector4d mean = Eigen::Vector4d::Zero();
  Eigen::Matrix4d covariance = Eigen::Matrix4d::Zero();
  std::array<double, kMaxModels> model_probabilities{};  // mu_k, the first model_count used
  int model_count = 0;
  int plots_used = 0;         // plots of this scan in the update
  int plots_rejected = 0;     // non-finite, non-positive sigma, or a kind the filter cannot use
  bool scan_skipped = false;  // time not after the previous scan's (or not finite): no update
};

}  // namespace skytrack::bernoulli
