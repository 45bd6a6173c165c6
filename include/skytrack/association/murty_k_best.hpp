#pragma once
// The k best assignments by Murty's partitioning (Murty 1968, "An algorithm for ranking all
// the assignments in order of increasing cost", Operations Research 16(3); in the form used
// for k-best JPDA and MHT hypotheses by Cox & Miller 1995, IEEE TAES 31(1)).
//
// Problem: `cost` is rows x cols with rows <= cols; an assignment gives every row its own
// column at finite cost (+inf or any non-finite entry is forbidden); its cost is the sum.
//
// Partitioning. A node is a subproblem (forced pairs, forbidden pairs) together with its
// best assignment A, whose pairs on the node's free rows r_1 < ... < r_f are (r_i, c_i).
// The cheapest node in the queue is popped and A is output; the rest of the node's space
// splits into f disjoint children: child i forces (r_1, c_1) .. (r_{i-1}, c_{i-1}) and
// forbids (r_i, c_i). Each child is solved with AssignmentSolver on the cost matrix reduced
// to its free rows and free columns; infeasible children are dropped. The live nodes always
// partition the assignments not yet output, so the i-th pop is the i-th best.
// Cost: at most 1 + (k - 1) * rows assignment solves, each O(rows^2 * cols).
// Ties between equal costs are broken by node creation order: deterministic.
//
// Buffers are kept between calls: after warm-up on the largest problem, no allocation.
#include <span>
#include <vector>

#include <Eigen/Core>

#include "skytrack/association/assignment.hpp"

namespace skytrack {

struct KBestAssignments {
  int rows = 0;
  int count = 0;              // assignments found, <= k
  bool exhausted = false;     // true: these are ALL the feasible assignments
  std::vector<int> columns;   // count x rows, row-major: column of each row, e-th best
  std::vector<double> costs;  // count entries, ascending

  std::span<const int> assignment(int e) const {
    return {columns.data() + static_cast<std::size_t>(e) * static_cast<std::size_t>(rows),
            static_cast<std::size_t>(rows)};
  }
};

class MurtyKBest {
 public:
  /// Up to k cheapest complete assignments in ascending cost. None when rows > cols or no
  /// complete assignment exists. The reference stays valid until the next call.
  const KBestAssignments& solve(const Eigen::Ref<const Eigen::MatrixXd>& cost, int k) noexcept;

  const KBestAssignments& result() const noexcept { return result_; }

 private:
  struct Node {
    double cost = 0.0;
    int forced = 0;    // offset of rows ints in forced_: column per row, -1 = free
    int solution = 0;  // offset of rows ints in solutions_
    int forbid = -1;   // head of the node's forbidden pairs in forbids_ (shared tails)
  };
  struct Forbid {
    int row = 0;
    int col = 0;
    int next = -1;
  };
  struct QueueEntry {
    double cost = 0.0;
    int node = 0;
  };

  bool add_node(const Eigen::Ref<const Eigen::MatrixXd>& cost, const std::vector<int>& forced,
                int forbid) noexcept;
  bool solve_node(const Eigen::Ref<const Eigen::MatrixXd>& cost, Node& node) noexcept;
  void partition(const Eigen::Ref<const Eigen::MatrixXd>& cost, int node) noexcept;

  AssignmentSolver solver_;
  std::vector<Node> nodes_;
  std::vector<int> forced_;
  std::vector<int> solutions_;
  std::vector<Forbid> forbids_;
  std::vector<QueueEntry> queue_;  // binary heap, cheapest (then oldest) on top
  std::vector<int> child_forced_, parent_solution_, row_pos_, col_pos_, col_of_;
  std::vector<double> reduced_;
  int rows_ = 0;
  int cols_ = 0;
  KBestAssignments result_;
};

}  // namespace skytrack
