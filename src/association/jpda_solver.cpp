// JPDA marginals (paper 003 eq. 8-9): exact dynamic programme, or Murty's k best joint
// events (Murty 1968) above the exact limits. See jpda_solver.hpp for the cost matrix.
#include "skytrack/association/jpda_solver.hpp"

#include <cmath>
#include <limits>

#include "jpda_input.hpp"

namespace skytrack {

const JpdaResult& JpdaSolver::solve(const JpdaProblem& problem) noexcept {
  if (!prepare(problem)) return result_;
  if (tracks_ <= options_.max_exact_tracks && run_exact()) return result_;
  run_k_best(options_.k_best);
  return result_;
}

const JpdaResult& JpdaSolver::solve_exact(const JpdaProblem& problem) noexcept {
  if (prepare(problem) && !run_exact()) detail::set_all_miss(result_, JpdaStatus::kExactLimit);
  return result_;
}

const JpdaResult& JpdaSolver::solve_k_best(const JpdaProblem& problem, int k) noexcept {
  if (prepare(problem)) run_k_best(k);
  return result_;
}

// Validates and fills weights_: miss_t and L_tj / lambda, each row divided by its maximum.
bool JpdaSolver::prepare(const JpdaProblem& problem) noexcept {
  tracks_ = static_cast<int>(problem.likelihood.rows());
  plots_ = static_cast<int>(problem.likelihood.cols());
  detail::reset_result(result_, tracks_, plots_);
  exact_outcome_ = JpdaExactOutcome{};
  if (!detail::valid_jpda_problem(problem)) {
    detail::set_all_miss(result_, JpdaStatus::kInvalidInput);
    return false;
  }
  Eigen::Map<Eigen::MatrixXd> w = detail::reuse(weights_, tracks_, plots_ + 1);
  for (int t = 0; t < tracks_; ++t) {
    w(t, 0) = problem.miss(t);
    for (int j = 0; j < plots_; ++j)
      w(t, 1 + j) = problem.likelihood(t, j) / problem.clutter_density;
    const double scale = w.row(t).maxCoeff();
    if (!std::isfinite(scale)) {  // L / lambda overflowed
      detail::set_all_miss(result_, JpdaStatus::kInvalidInput);
      return false;
    }
    if (scale > 0.0) w.row(t) /= scale;
  }
  return true;
}

bool JpdaSolver::run_exact() noexcept {
  const Eigen::Map<const Eigen::MatrixXd> w(weights_.data(), tracks_, plots_ + 1);
  exact_.plan(w);
  // Below this bound on the states, planning the other order costs more than it can save.
  constexpr double kWorthTransposing = 1024.0;
  const bool transposable = exact_.planned_states() > kWorthTransposing && by_plots_.plan(w);
  const bool by_plots = transposable && by_plots_.planned_states() < exact_.planned_states();
  const auto run = [&](bool over_plots) {
    exact_outcome_ = over_plots ? by_plots_.run(w, options_.max_exact_states, result_.beta)
                                : exact_.run(w, options_.max_exact_states, result_.beta);
  };
  run(by_plots);
  if (!exact_outcome_.completed && transposable) run(!by_plots);  // the bound is not the count
  if (!exact_outcome_.completed) return false;
  result_.approximated = false;
  result_.hypotheses = exact_outcome_.events;
  if (!(exact_outcome_.total_weight > 0.0))
    detail::set_all_miss(result_, JpdaStatus::kNoFeasibleEvent);
  return true;
}

void JpdaSolver::run_k_best(int k) noexcept {
  const Eigen::Map<const Eigen::MatrixXd> w(weights_.data(), tracks_, plots_ + 1);
  Eigen::Map<Eigen::MatrixXd> cost = detail::reuse(costs_, tracks_, plots_ + tracks_);
  cost.setConstant(std::numeric_limits<double>::infinity());
  for (int t = 0; t < tracks_; ++t) {
    for (int j = 0; j < plots_; ++j) cost(t, j) = detail::neg_log(w(t, 1 + j));
    cost(t, plots_ + t) = detail::neg_log(w(t, 0));
  }
  const KBestAssignments& events = murty_.solve(cost, k);
  result_.approximated = !events.exhausted;
  result_.hypotheses = events.count;
  if (events.count == 0) {
    detail::set_all_miss(result_, JpdaStatus::kNoFeasibleEvent);
    return;
  }
  result_.beta.setZero();
  double total = 0.0;
  for (int e = 0; e < events.count; ++e) {
    const double weight = std::exp(events.costs[static_cast<std::size_t>(0)] -
                                   events.costs[static_cast<std::size_t>(e)]);
    total += weight;
    const auto columns = events.assignment(e);
    for (int t = 0; t < tracks_; ++t) {
      const int c = columns[static_cast<std::size_t>(t)];
      result_.beta(t, c < plots_ ? 1 + c : 0) += weight;
    }
  }
  result_.beta /= total;
}

}  // namespace skytrack
