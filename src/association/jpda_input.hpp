#pragma once
// Internal helpers shared by the association solvers: input validation, the all-miss result
// used when no association can be computed, and the plots several tracks gate.
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include "skytrack/association/jpda_problem.hpp"

namespace skytrack::detail {

/// Sizes agree, likelihoods and miss weights are finite and >= 0, lambda is finite > 0.
inline bool valid_jpda_problem(const JpdaProblem& problem) noexcept {
  if (problem.miss.size() != problem.likelihood.rows()) return false;
  if (!(problem.clutter_density > 0.0) || !std::isfinite(problem.clutter_density)) return false;
  if (!problem.likelihood.allFinite() || !problem.miss.allFinite()) return false;
  return (problem.likelihood.size() == 0 || problem.likelihood.minCoeff() >= 0.0) &&
         (problem.miss.size() == 0 || problem.miss.minCoeff() >= 0.0);
}

/// Sizes beta to tracks x (plots + 1) (reallocates only when the size changes) and resets
/// the other fields.
inline void reset_result(JpdaResult& result, Eigen::Index tracks, Eigen::Index plots) noexcept {
  result.beta.resize(tracks, plots + 1);
  result.approximated = false;
  result.hypotheses = 0;
  result.status = JpdaStatus::kOk;
}

/// Every track undetected: the safe hard decision when nothing better is known.
inline void set_all_miss(JpdaResult& result, JpdaStatus status) noexcept {
  result.beta.setZero();
  if (result.beta.cols() > 0) result.beta.col(0).setOnes();
  result.status = status;
}

/// A rows x cols view of `buffer`, which grows only when needed (no Eigen reallocation).
inline Eigen::Map<Eigen::MatrixXd> reuse(std::vector<double>& buffer, Eigen::Index rows,
                                         Eigen::Index cols) noexcept {
  buffer.resize(static_cast<std::size_t>(rows * cols));
  return {buffer.data(), rows, cols};
}

/// The plot columns (c >= 1 of tracks x (1 + plots) weights, column 0 the misses) gated by two
/// or more tracks (weight > 0): appended to `shared` in column order and flagged in
/// `is_shared` (one entry per column).
inline void find_shared_plots(const Eigen::Ref<const Eigen::MatrixXd>& weights,
                              std::vector<int>& shared, std::vector<char>& is_shared) noexcept {
  const Eigen::Index tracks = weights.rows(), columns = weights.cols();
  shared.clear();
  is_shared.assign(static_cast<std::size_t>(columns), 0);
  for (Eigen::Index c = 1; c < columns; ++c) {
    int gating = 0;
    for (Eigen::Index t = 0; t < tracks && gating < 2; ++t) gating += weights(t, c) > 0.0 ? 1 : 0;
    if (gating < 2) continue;
    shared.push_back(static_cast<int>(c));
    is_shared[static_cast<std::size_t>(c)] = 1;
  }
}

/// -log(x), +inf (forbidden) for x <= 0.
inline double neg_log(double x) noexcept {
  return x > 0.0 ? -std::log(x) : std::numeric_limits<double>::infinity();
}

}  // namespace skytrack::detail
