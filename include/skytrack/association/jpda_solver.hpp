#pragma once
// JPDA marginal association probabilities of one cluster (paper 003 sec. 3.2, eq. 8-9;
// Fortmann, Bar-Shalom & Scheffe 1983). Joint event weights and the lambda convention are
// in jpda_problem.hpp.
//
// EXACT: JpdaExact, a dynamic programme over (track, used shared plots) that sums every
// feasible joint event without listing them (complexity in jpda_exact.hpp), or the same
// programme over (shared plot, used tracks) (JpdaByPlots), whichever order's bound on the
// states is smaller; if that one stops at max_exact_states, the other is tried.
// APPROXIMATION, above max_exact_tracks tracks, > 64 shared plots live at once or
// max_exact_states states: the k best joint events by Murty's method (MurtyKBest) on the tracks x
// (plots + tracks) matrix
//   C(t, j)     = -log(L_tj / lambda / c_t)  for a gated pair, +inf otherwise,
//   C(t, P + t) = -log(miss_t / c_t)         (track t undetected), C(t, P + u) = +inf, u != t,
// where c_t = max(miss_t, max_j L_tj / lambda) scales each row to <= 1 (every event takes
// one entry per row, so the scaling changes no ranking or marginal). An assignment of every
// row is exactly one feasible joint event and exp(-cost) is its weight / (lambda^P prod c_t).
// Marginals are normalised over the k events; approximated = true unless those k turned out
// to be all the feasible events.
//
// Per-scan and noexcept. Buffers are reused; beta reallocates only when the cluster shape
// changes.
#include <cstdint>
#include <vector>

#include "skytrack/association/jpda_by_plots.hpp"
#include "skytrack/association/jpda_exact.hpp"
#include "skytrack/association/jpda_problem.hpp"
#include "skytrack/association/murty_k_best.hpp"

namespace skytrack {

struct JpdaOptions {
  int max_exact_tracks = 8;  // profile default; the exact method is practical well beyond
                             // (sparse 14-track clusters take microseconds, see the bench)
  int k_best = 100;          // joint events kept by the approximation
  // Exact DP bound: at 0.1-0.3 us and ~60 B per state (dev box) the default caps an exact
  // run, or a wasted attempt before the fallback, at ~5-20 ms and ~4 MB.
  std::int64_t max_exact_states = std::int64_t{1} << 16;
};

class JpdaSolver {
 public:
  JpdaSolver() = default;
  explicit JpdaSolver(const JpdaOptions& options) : options_(options) {}

  /// Exact when the cluster has <= max_exact_tracks tracks and fits the exact bounds,
  /// otherwise the k-best approximation. The reference stays valid until the next call.
  const JpdaResult& solve(const JpdaProblem& problem) noexcept;
  /// Exact only; status kExactLimit (beta all miss) when the exact bounds are exceeded.
  const JpdaResult& solve_exact(const JpdaProblem& problem) noexcept;
  /// Murty k-best approximation only.
  const JpdaResult& solve_k_best(const JpdaProblem& problem, int k) noexcept;

  const JpdaOptions& options() const noexcept { return options_; }
  /// Diagnostics of the last exact attempt (states, shared plots, frontier).
  const JpdaExactOutcome& exact_outcome() const noexcept { return exact_outcome_; }

 private:
  bool prepare(const JpdaProblem& problem) noexcept;
  bool run_exact() noexcept;
  void run_k_best(int k) noexcept;

  JpdaOptions options_;
  JpdaExact exact_;
  JpdaByPlots by_plots_;  // the same programme over the plots, where that order is cheaper
  JpdaExactOutcome exact_outcome_;
  MurtyKBest murty_;
  std::vector<double> weights_;  // tracks x (1 + plots), column 0 = miss, rows scaled to max 1
  std::vector<double> costs_;    // tracks x (plots + tracks), Murty's matrix
  int tracks_ = 0;
  int plots_ = 0;
  JpdaResult result_;
};

}  // namespace skytrack
