// Shortest augmenting path assignment (Crouse 2016, IEEE TAES 52(4); Jonker & Volgenant
// 1987). See assignment.hpp for the treatment of forbidden pairs.
#include "skytrack/association/assignment.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace skytrack {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

const AssignmentResult& AssignmentSolver::solve(
    const Eigen::Ref<const Eigen::MatrixXd>& cost) noexcept {
  const int rows = static_cast<int>(cost.rows());
  const int cols = static_cast<int>(cost.cols());
  result_.row_to_col.assign(static_cast<std::size_t>(rows), -1);
  result_.col_to_row.assign(static_cast<std::size_t>(cols), -1);
  result_.total_cost = 0.0;
  result_.assigned = 0;
  result_.feasible = true;
  if (rows == 0 || cols == 0) return result_;

  // Work on the short side (n <= m) so every augmentation ends in a free column.
  const bool transposed = rows > cols;
  const int n = transposed ? cols : rows;
  const int m = transposed ? rows : cols;

  // Shift finite costs to [0, span]; every complete assignment has n entries, so the shift
  // does not change the optimum. M > n * span makes one fewer forbidden pair always cheaper.
  double lo = kInf, hi = -kInf;
  for (int j = 0; j < cols; ++j) {
    for (int i = 0; i < rows; ++i) {
      const double c = cost(i, j);
      if (std::isfinite(c)) {
        lo = std::min(lo, c);
        hi = std::max(hi, c);
      }
    }
  }
  const bool any_finite = lo <= hi;
  const double span = any_finite ? hi - lo : 0.0;
  const double big = static_cast<double>(n + 1) * span + 1.0;

  cost_.resize(static_cast<std::size_t>(n) * static_cast<std::size_t>(m));
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < m; ++c) {
      const double x = transposed ? cost(c, r) : cost(r, c);
      cost_[static_cast<std::size_t>(r) * m + c] = std::isfinite(x) ? x - lo : big;
    }
  }

  solve_short_side(n, m);

  for (int r = 0; r < n; ++r) {
    const int c = col4row_[r];
    if (c < 0) {
      result_.feasible = false;
      continue;
    }
    const int row = transposed ? c : r;
    const int col = transposed ? r : c;
    const double x = cost(row, col);
    if (!std::isfinite(x)) {
      result_.feasible = false;  // only a forbidden pair was left for this row
      continue;
    }
    result_.row_to_col[row] = col;
    result_.col_to_row[col] = row;
    result_.total_cost += x;
    ++result_.assigned;
  }
  return result_;
}

void AssignmentSolver::solve_short_side(int n, int m) noexcept {
  const auto un = static_cast<std::size_t>(n);
  const auto um = static_cast<std::size_t>(m);
  u_.assign(un, 0.0);
  v_.assign(um, 0.0);
  shortest_.resize(um);
  path_.assign(um, -1);
  col4row_.assign(un, -1);
  row4col_.assign(um, -1);
  remaining_.resize(um);
  visited_rows_.resize(un);
  visited_cols_.resize(um);

  for (int row = 0; row < n; ++row) {
    double min_value = 0.0;
    const int sink = augmenting_path(n, m, row, min_value);
    if (sink < 0) continue;  // only if costs overflowed to inf; the row stays unassigned

    // Dual update keeps reduced costs non-negative and tight on the new path.
    u_[row] += min_value;
    for (int i = 0; i < n; ++i) {
      if (visited_rows_[i] && i != row) u_[i] += min_value - shortest_[col4row_[i]];
    }
    for (int j = 0; j < m; ++j) {
      if (visited_cols_[j]) v_[j] -= min_value - shortest_[j];
    }

    // Augment: flip the alternating path back from the sink.
    int j = sink;
    while (j >= 0) {
      const int i = path_[j];
      row4col_[j] = i;
      std::swap(col4row_[i], j);
      if (i == row) break;
    }
  }
}

// Dijkstra over reduced costs from `row` to the nearest unassigned column; returns it.
int AssignmentSolver::augmenting_path(int n, int m, int row, double& min_value) noexcept {
  int num_remaining = m;
  for (int k = 0; k < m; ++k) remaining_[k] = m - k - 1;
  std::fill(visited_rows_.begin(), visited_rows_.begin() + n, 0);
  std::fill(visited_cols_.begin(), visited_cols_.begin() + m, 0);
  std::fill(shortest_.begin(), shortest_.begin() + m, kInf);

  min_value = 0.0;
  int i = row;
  int sink = -1;
  while (sink < 0) {
    visited_rows_[i] = 1;
    int index = -1;
    double lowest = kInf;
    const double* cost_row = cost_.data() + static_cast<std::size_t>(i) * m;
    for (int k = 0; k < num_remaining; ++k) {
      const int j = remaining_[k];
      const double reduced = min_value + cost_row[j] - u_[i] - v_[j];
      if (reduced < shortest_[j]) {
        path_[j] = i;
        shortest_[j] = reduced;
      }
      // Ties prefer a free column: it ends the search sooner.
      if (shortest_[j] < lowest || (shortest_[j] == lowest && row4col_[j] < 0)) {
        lowest = shortest_[j];
        index = k;
      }
    }
    if (index < 0) return -1;  // unreachable with finite costs
    min_value = lowest;
    const int j = remaining_[index];
    if (row4col_[j] < 0) {
      sink = j;
    } else {
      i = row4col_[j];
    }
    visited_cols_[j] = 1;
    remaining_[index] = remaining_[--num_remaining];
  }
  return sink;
}

AssignmentResult solve_assignment(const Eigen::Ref<const Eigen::MatrixXd>& cost) {
  AssignmentSolver solver;
  return solver.solve(cost);
}

}  // namespace skytrack
