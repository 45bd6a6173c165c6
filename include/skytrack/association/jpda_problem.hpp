#pragma once
// Input and output of one cluster's association (paper 003 sec. 3.2, eq. 8-10; Fortmann,
// Bar-Shalom & Scheffe 1983, "Sonar tracking of multiple targets using joint probabilistic
// data association", IEEE JOE 8(3)), shared by JpdaSolver and GnnAssociator.
//
// A feasible joint event theta assigns each track either "undetected" or one of its gated
// plots, each plot to at most one track; plots assigned to no track are clutter. With a
// Poisson clutter model of density lambda its posterior weight is (the parametric JPDA of
// Bar-Shalom, Daum & Huang 2009, "The probabilistic data association filter", IEEE CSM 29(6))
//
//   w(theta) = prod_{t undetected} miss_t * prod_{t -> j} likelihood_tj * lambda^(m - d)
//
// with m plots in the cluster and d detected tracks. CONVENTION: the solvers divide every
// likelihood by lambda, i.e. they use w(theta) / lambda^m = prod miss_t * prod (L_tj /
// lambda). The factor lambda^m is the same for every event, so the marginals
// beta_tj = sum_{theta: t -> j} w(theta) / sum_theta w(theta) (eq. 8; rows sum to 1,
// eq. 9; eq. 10 then combines the per-plot IMM updates with them) are unchanged, and the
// weights stay well scaled however many plots the cluster has. lambda must be > 0.
#include <cstdint>

#include <Eigen/Core>

namespace skytrack {

struct JpdaProblem {
  Eigen::MatrixXd likelihood;    // tracks x plots: PD * N(nu; 0, S) (IMM-weighted) [1/m^d]
                                 // for a gated pair, 0 if not gated
  Eigen::VectorXd miss;          // per track: 1 - PD * PG, weight of "track undetected"
  double clutter_density = 0.0;  // lambda [1/m^d], > 0; each unassigned plot contributes it
};

enum class JpdaStatus {
  kOk,
  kInvalidInput,     // sizes disagree, negative / non-finite entries, or lambda <= 0
  kNoFeasibleEvent,  // every joint event has weight 0 (e.g. miss 0 and no gated plot)
  kExactLimit,       // solve_exact only: > 64 live shared plots or the state bound was hit
};

struct JpdaResult {
  Eigen::MatrixXd beta;         // tracks x (plots + 1); column 0 = miss, column 1 + j = plot j;
                                // each row sums to 1 (all miss when status != kOk)
  bool approximated = false;    // true: marginals over the k best events only
  std::int64_t hypotheses = 0;  // joint events summed (saturates at INT64_MAX)
  JpdaStatus status = JpdaStatus::kOk;
};

}  // namespace skytrack
