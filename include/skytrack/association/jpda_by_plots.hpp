#pragma once
// Exact JPDA marginals of one cluster by the same dynamic programme run over its shared plots
// instead of its tracks: the transposed problem. Where a crossing puts more shared plots than
// tracks on the frontier (fathers and their branches round a few targets, with clutter),
// its key is the set of tracks already taken, which stays small when JpdaExact's set of
// plots already used does not.
//
// The transposition. Row t of the cluster's weights chooses its miss or a private plot
// (weight stay_t = miss_t + its private plots' weights) or one shared plot j (w_tj), each
// shared plot taken at most once. Dividing row t by stay_t changes no marginal (every joint
// event takes one entry per row), so a joint event's weight is prod over the taken pairs of
// w_tj / stay_t. Read by plots: each shared plot is clutter (weight 1) or taken by one track
// that gates it (w_tj / stay_t), each track taken at most once: the JPDA problem with plots
// as rows and tracks as columns. Its marginals give
//   beta_tj = P(plot j taken by t),  u_t = 1 - sum_j beta_tj,
//   beta_t0 = u_t miss_t / stay_t,   beta_tc = u_t w_tc / stay_t  (c private to t),
// and the events count is the original's with each track, when no plot takes it, standing
// for its stay events (JpdaExact's unused_events).
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "skytrack/association/jpda_exact.hpp"

namespace skytrack {

class JpdaByPlots {
 public:
  /// Builds and plans the transposed problem of `weights` (tracks x (1 + plots), column 0 =
  /// miss, as JpdaExact takes them). False when there is none: a track that can neither miss
  /// nor take a private plot (stay_t = 0).
  bool plan(const Eigen::Ref<const Eigen::MatrixXd>& weights) noexcept;
  /// JpdaExact::planned_states() of the transposed problem.
  double planned_states() const noexcept { return exact_.planned_states(); }
  /// The planned run. Completed with Z > 0: `beta` (the shape of `weights`) holds the
  /// cluster's marginals; otherwise beta is untouched. The outcome's states, frontier and
  /// total weight are the transposed problem's; its events count is the cluster's.
  JpdaExactOutcome run(const Eigen::Ref<const Eigen::MatrixXd>& weights, std::int64_t max_states,
                       Eigen::Ref<Eigen::MatrixXd> beta) noexcept;

 private:
  JpdaExact exact_;
  std::vector<int> shared_;                // cluster column of each transposed row
  std::vector<char> is_shared_;            // per cluster column
  std::vector<double> stay_;               // per track
  std::vector<std::int64_t> stay_events_;  // per track: its miss and private plots
  std::vector<double> transposed_;         // shared plots x (1 + tracks)
  std::vector<double> transposed_beta_;
};

}  // namespace skytrack
