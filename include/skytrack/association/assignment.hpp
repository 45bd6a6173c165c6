#pragma once
// Optimal rectangular linear assignment: shortest augmenting paths with dual variables
// (Jonker & Volgenant 1987), in the rectangular form of Crouse 2016, "On implementing 2D
// rectangular assignment algorithms", IEEE TAES 52(4): the shortest augmenting path method
// that also backs SciPy's linear_sum_assignment. Rows are augmented one by one on the
// short side; reduced costs c_ij - u_i - v_j stay >= 0 (complementary slackness).
//
// Forbidden pairs. An entry that is +inf (or any non-finite value) may not be used. The
// solver returns a MAXIMUM-CARDINALITY assignment over the allowed pairs and, among those,
// the one of minimum total cost; `feasible` says whether that cardinality is the full
// min(rows, cols). Internally each forbidden entry becomes one large finite cost M larger
// than any possible difference of finite totals, so using one fewer forbidden pair always
// wins, and pairs that used M are dropped afterwards. Precondition for exactness:
// min(rows, cols) * (max - min of the finite costs) is far below 1e15 (double precision).
#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace skytrack {

struct AssignmentResult {
  std::vector<int> row_to_col;  // column assigned to each row, -1 when unassigned
  std::vector<int> col_to_row;  // row assigned to each column, -1 when unassigned
  double total_cost = 0.0;      // sum of the costs of the assigned (allowed) pairs
  int assigned = 0;             // number of assigned pairs
  bool feasible = true;         // all min(rows, cols) pairs assigned with allowed costs
};

/// Keeps its buffers between calls: after warm-up on the largest problem, solve() does not
/// allocate. O(rows * cols * min(rows, cols)).
class AssignmentSolver {
 public:
  /// Minimum-cost assignment of the rows x cols matrix (any shape, may be empty). The
  /// reference stays valid until the next call.
  const AssignmentResult& solve(const Eigen::Ref<const Eigen::MatrixXd>& cost) noexcept;

  const AssignmentResult& result() const { return result_; }

 private:
  // Crouse 2016 shortest augmenting path on the n x m (n <= m) row-major working matrix in cost_.
  void solve_short_side(int n, int m) noexcept;
  int augmenting_path(int n, int m, int row, double& min_value) noexcept;

  AssignmentResult result_;
  std::vector<double> cost_;  // row-major, short side first, forbidden -> big M
  std::vector<double> u_, v_, shortest_;
  std::vector<int> path_, col4row_, row4col_, remaining_;
  std::vector<char> visited_rows_, visited_cols_;
};

/// One-shot convenience over AssignmentSolver.
AssignmentResult solve_assignment(const Eigen::Ref<const Eigen::MatrixXd>& cost);

}  // namespace skytrack
