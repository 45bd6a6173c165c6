// Murty's k-best assignments (Murty 1968; Cox & Miller 1995); see murty_k_best.hpp.
#include "skytrack/association/murty_k_best.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace skytrack {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::size_t at(int i) {
  return static_cast<std::size_t>(i);
}

// Heap order: the top is the cheapest entry, and among equal costs the oldest node.
bool later(const auto& a, const auto& b) {
  return a.cost > b.cost || (a.cost == b.cost && a.node > b.node);
}

}  // namespace

const KBestAssignments& MurtyKBest::solve(const Eigen::Ref<const Eigen::MatrixXd>& cost,
                                          int k) noexcept {
  rows_ = static_cast<int>(cost.rows());
  cols_ = static_cast<int>(cost.cols());
  result_.rows = rows_;
  result_.count = 0;
  result_.exhausted = false;
  result_.columns.clear();
  result_.costs.clear();
  nodes_.clear();
  forced_.clear();
  solutions_.clear();
  forbids_.clear();
  queue_.clear();
  if (rows_ > cols_) {
    result_.exhausted = true;
    return result_;
  }
  if (k <= 0) return result_;
  child_forced_.assign(at(rows_), -1);
  add_node(cost, child_forced_, -1);
  while (result_.count < k && !queue_.empty()) {
    std::pop_heap(queue_.begin(), queue_.end(),
                  [](const auto& a, const auto& b) { return later(a, b); });
    const int node = queue_.back().node;
    queue_.pop_back();
    const Node& best = nodes_[at(node)];
    result_.columns.insert(result_.columns.end(), solutions_.begin() + best.solution,
                           solutions_.begin() + best.solution + rows_);
    result_.costs.push_back(best.cost);
    ++result_.count;
    if (result_.count < k) partition(cost, node);
  }
  result_.exhausted = queue_.empty() && result_.count < k;
  return result_;
}

// Appends a node with the given forced columns and forbidden list; keeps it (and queues it)
// only if its subproblem has a complete assignment.
bool MurtyKBest::add_node(const Eigen::Ref<const Eigen::MatrixXd>& cost,
                          const std::vector<int>& forced, int forbid) noexcept {
  Node node;
  node.forced = static_cast<int>(forced_.size());
  node.solution = static_cast<int>(solutions_.size());
  node.forbid = forbid;
  forced_.insert(forced_.end(), forced.begin(), forced.end());
  solutions_.resize(solutions_.size() + at(rows_));
  if (!solve_node(cost, node)) {
    forced_.resize(at(node.forced));
    solutions_.resize(at(node.solution));
    return false;
  }
  nodes_.push_back(node);
  queue_.push_back({node.cost, static_cast<int>(nodes_.size()) - 1});
  std::push_heap(queue_.begin(), queue_.end(),
                 [](const auto& a, const auto& b) { return later(a, b); });
  return true;
}

// Best completion of the node's forced pairs avoiding its forbidden pairs, on the matrix
// reduced to free rows x free columns.
bool MurtyKBest::solve_node(const Eigen::Ref<const Eigen::MatrixXd>& cost, Node& node) noexcept {
  const int* forced = forced_.data() + node.forced;
  row_pos_.assign(at(rows_), -1);
  col_pos_.assign(at(cols_), 0);
  int free_rows = 0;
  for (int r = 0; r < rows_; ++r) {
    if (forced[r] >= 0) {
      col_pos_[at(forced[r])] = -1;
    } else {
      row_pos_[at(r)] = free_rows++;
    }
  }
  col_of_.clear();
  for (int c = 0; c < cols_; ++c) {
    if (col_pos_[at(c)] < 0) continue;
    col_pos_[at(c)] = static_cast<int>(col_of_.size());
    col_of_.push_back(c);
  }
  const int free_cols = static_cast<int>(col_of_.size());
  reduced_.resize(at(free_rows) * at(free_cols));
  Eigen::Map<Eigen::MatrixXd> reduced(reduced_.data(), free_rows, free_cols);
  for (int r = 0; r < rows_; ++r) {
    if (row_pos_[at(r)] < 0) continue;
    for (int j = 0; j < free_cols; ++j) reduced(row_pos_[at(r)], j) = cost(r, col_of_[at(j)]);
  }
  for (int f = node.forbid; f >= 0; f = forbids_[at(f)].next) {
    const Forbid& pair = forbids_[at(f)];
    if (row_pos_[at(pair.row)] >= 0 && col_pos_[at(pair.col)] >= 0) {
      reduced(row_pos_[at(pair.row)], col_pos_[at(pair.col)]) = kInf;
    }
  }
  const AssignmentResult& solved = solver_.solve(reduced);
  if (!solved.feasible || solved.assigned != free_rows) return false;
  int* solution = solutions_.data() + node.solution;
  node.cost = 0.0;
  for (int r = 0; r < rows_; ++r) {
    solution[r] = forced[r] >= 0 ? forced[r] : col_of_[at(solved.row_to_col[at(row_pos_[at(r)])])];
    node.cost += cost(r, solution[r]);  // summed in row order: equal assignments, equal costs
  }
  return std::isfinite(node.cost);
}

// Murty's partition of the popped node's space minus its best assignment A.
void MurtyKBest::partition(const Eigen::Ref<const Eigen::MatrixXd>& cost, int node) noexcept {
  const Node parent = nodes_[at(node)];
  child_forced_.assign(forced_.begin() + parent.forced, forced_.begin() + parent.forced + rows_);
  parent_solution_.assign(solutions_.begin() + parent.solution,
                          solutions_.begin() + parent.solution + rows_);
  for (int r = 0; r < rows_; ++r) {
    if (child_forced_[at(r)] >= 0) continue;
    forbids_.push_back({r, parent_solution_[at(r)], parent.forbid});
    if (!add_node(cost, child_forced_, static_cast<int>(forbids_.size()) - 1)) forbids_.pop_back();
    child_forced_[at(r)] = parent_solution_[at(r)];  // later children keep (r, c_r)
  }
}

}  // namespace skytrack
