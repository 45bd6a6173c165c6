#pragma once
// Global nearest neighbour baseline: the single most probable feasible joint event (the MAP
// event of paper 003 eq. 8, the same weights JPDA sums), by one optimal assignment
// (AssignmentSolver), GNN with a per-track non-assignment option as in Blackman & Popoli
// 1999, "Design and analysis of modern tracking systems".
//
// Derivation. With m plots, event weight w(theta) = prod_{missed} miss_t * prod_{t -> j}
// L_tj * lambda^(m - d) (jpda_problem.hpp). Maximising log w is minimising
//   sum_{t -> j} -log(L_tj / lambda) + sum_{missed} -log(miss_t)   (dropping m log lambda).
// Every track takes exactly one entry of its row, so adding -log(lambda) to all of row t
// changes no argmin; the costs become
//   C(t, j)     = -log(L_tj)             for a gated pair, +inf otherwise,
//   C(t, P + t) = -log(miss_t * lambda)   (dummy column: track t undetected),
//   C(t, P + u) = +inf for u != t,
// on the tracks x (plots + tracks) matrix. A complete assignment is one feasible joint event
// and the optimum is the MAP event, i.e. the best event of Murty's list. An unassigned plot
// costs nothing here because its lambda was folded into the rows.
// Cost O(T^2 (T + P)). Works for one cluster or a whole scan (clusters are independent).
#include <span>
#include <vector>

#include "skytrack/association/assignment.hpp"
#include "skytrack/association/jpda_problem.hpp"

namespace skytrack {

class GnnAssociator {
 public:
  /// beta with one 1 per row (column 0 = undetected, 1 + j = plot j), approximated = false,
  /// hypotheses = 1. A track whose every option has weight 0 is set undetected and status
  /// is kNoFeasibleEvent. The reference stays valid until the next call.
  const JpdaResult& associate(const JpdaProblem& problem) noexcept;

  /// Plot given to each track by the last call, -1 = undetected.
  std::span<const int> assignment() const noexcept { return assignment_; }

 private:
  AssignmentSolver solver_;
  std::vector<double> costs_;
  std::vector<int> assignment_;
  JpdaResult result_;
};

}  // namespace skytrack
