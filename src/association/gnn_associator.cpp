// GNN: the MAP joint event by optimal assignment; costs derived in gnn_associator.hpp.
#include "skytrack/association/gnn_associator.hpp"

#include <cstddef>
#include <limits>

#include "jpda_input.hpp"

namespace skytrack {

const JpdaResult& GnnAssociator::associate(const JpdaProblem& problem) noexcept {
  const int tracks = static_cast<int>(problem.likelihood.rows());
  const int plots = static_cast<int>(problem.likelihood.cols());
  detail::reset_result(result_, tracks, plots);
  assignment_.assign(static_cast<std::size_t>(tracks), -1);
  if (!detail::valid_jpda_problem(problem)) {
    detail::set_all_miss(result_, JpdaStatus::kInvalidInput);
    return result_;
  }
  Eigen::Map<Eigen::MatrixXd> cost = detail::reuse(costs_, tracks, plots + tracks);
  cost.setConstant(std::numeric_limits<double>::infinity());
  for (int t = 0; t < tracks; ++t) {
    for (int j = 0; j < plots; ++j) cost(t, j) = detail::neg_log(problem.likelihood(t, j));
    cost(t, plots + t) = detail::neg_log(problem.miss(t) * problem.clutter_density);
  }
  const AssignmentResult& solved = solver_.solve(cost);
  result_.beta.setZero();
  result_.hypotheses = 1;
  for (int t = 0; t < tracks; ++t) {
    const int c = solved.row_to_col[static_cast<std::size_t>(t)];
    if (c >= 0 && c < plots) assignment_[static_cast<std::size_t>(t)] = c;
    result_.beta(t, c >= 0 && c < plots ? 1 + c : 0) = 1.0;
    if (c < 0) result_.status = JpdaStatus::kNoFeasibleEvent;
  }
  return result_;
}

}  // namespace skytrack
