#pragma once
// OSPA and GOSPA distances between a set of true positions X (|X| = m) and estimates Y
// (|Y| = n), both from one optimal assignment on the cost min(d, c)^p.
//
// OSPA (Schuhmacher, Vo & Vo 2008, "A consistent metric for performance evaluation of
// multi-object filters", IEEE TSP 56(8), Sec. III-A, the definition of d_p^(c)), m <= n:
//   OSPA = ( (1/n) [ min_pi sum_{i=1..m} min(d(x_i, y_pi(i)), c)^p + c^p (n - m) ] )^(1/p)
// and 0 when both sets are empty.
//
// GOSPA (Rahmathullah, Garcia-Fernandez & Svensson 2017, "Generalized optimal sub-pattern
// assignment metric", FUSION, Definition 1 with alpha = 2 and its assignment form,
// Proposition 1):
//   GOSPA = ( min_gamma sum_{(i,j) in gamma} d(x_i, y_j)^p + c^p/2 (|X| + |Y| - 2|gamma|) )^(1/p)
// over partial assignments gamma whose pairs have d < c. A pair at d >= c costs c^p either
// way (c^p/2 missed + c^p/2 false), so the OSPA assignment is also GOSPA-optimal.
//
// Distance d is Euclidean over the common leading components of the two vectors (a 2-D
// truth against a 3-D estimate compares x, y).
#include <span>
#include <vector>

#include <Eigen/Core>

#include "skytrack/association/assignment.hpp"

namespace skytrack::metrics {

struct OspaGospaConfig {
  double cutoff = 100.0;  // c [m], > 0
  double order = 2.0;     // p, >= 1
};

/// True when cutoff > 0 and order >= 1 (both finite).
bool is_valid(const OspaGospaConfig& config);

struct MatchedPair {
  int truth = 0;          // index into the truth set
  int estimate = 0;       // index into the estimate set
  double distance = 0.0;  // d < c [m]
};

struct OspaGospaResult {
  double ospa = 0.0;               // [m]
  double gospa = 0.0;              // [m], alpha = 2
  double localisation = 0.0;       // sum of d^p over `pairs` [m^p]
  int missed = 0;                  // truths without a pair closer than c
  int false_tracks = 0;            // estimates without a pair closer than c
  std::vector<MatchedPair> pairs;  // the assignment used, pairs with d < c
};

/// Keeps its cost matrix and solver between calls (the evaluator calls it once per scan).
class OspaGospa {
 public:
  explicit OspaGospa(OspaGospaConfig config = {}) : config_(config) {}

  const OspaGospaResult& compute(std::span<const Eigen::VectorXd> truths,
                                 std::span<const Eigen::VectorXd> estimates) noexcept;

  /// The result of the last compute().
  const OspaGospaResult& result() const { return result_; }
  const OspaGospaConfig& config() const { return config_; }

 private:
  OspaGospaConfig config_;
  Eigen::MatrixXd cost_;
  Eigen::MatrixXd distance_;
  AssignmentSolver solver_;
  OspaGospaResult result_;
};

/// Euclidean distance over the common leading components.
double common_distance(const Eigen::VectorXd& a, const Eigen::VectorXd& b);

// One-shot conveniences.
OspaGospaResult ospa_gospa(std::span<const Eigen::VectorXd> truths,
                           std::span<const Eigen::VectorXd> estimates,
                           const OspaGospaConfig& config = {});
double ospa(std::span<const Eigen::VectorXd> truths, std::span<const Eigen::VectorXd> estimates,
            const OspaGospaConfig& config = {});
double gospa(std::span<const Eigen::VectorXd> truths, std::span<const Eigen::VectorXd> estimates,
             const OspaGospaConfig& config = {});

}  // namespace skytrack::metrics
