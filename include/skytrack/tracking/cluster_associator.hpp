#pragma once
// The point tracker's cluster associator: tracks that share candidate plots form clusters,
// each solved for its JPDA marginals (paper 003 §3.2, eq. 8-10: exact, k-best joint events
// above a size, per-track PDA above that) or, with association.method gnn, its best joint
// event. Also the clutter density each plot is weighed against.
#include <functional>
#include <span>
#include <vector>

#include "skytrack/association/cluster_builder.hpp"
#include "skytrack/association/gnn_associator.hpp"
#include "skytrack/association/jpda_solver.hpp"
#include "skytrack/config/profile.hpp"
#include "skytrack/core/scan_report.hpp"
#include "skytrack/core/track_report.hpp"
#include "skytrack/preprocess/preprocessing.hpp"
#include "skytrack/tracking/gater.hpp"

namespace skytrack {

class ClusterAssociator {
 public:
  explicit ClusterAssociator(const config::TrackingProfile& profile);

  /// Called per track of each cluster in cluster order with its candidates (indices into
  /// the pool), their weights and its miss weight; also for tracks with no candidate (empty
  /// spans, miss weight 1).
  using OnTrack = std::function<void(int, std::span<const int>, std::span<const double>, double)>;
  struct Look {  // what a look's association reads and where it counts
    const Preprocessing& pre;
    int tracks = 0;
    ScanReport& report;
    std::vector<TrackEvent>& events;
    int& numeric_failures;
  };
  /// JPDA over the clusters of the candidates `list` (indices into `pool`, grouped by
  /// track). `manoeuvre`: the branch layer's manoeuvre kinds, whose probabilities only
  /// choose which branches to start: a cheaper exact attempt, fewer joint events, and
  /// per-track PDA above association.max_exact_cluster_size (their wide gates in dense
  /// clutter chain hundreds of tracks, where k-best joint events cost seconds).
  void solve(const Look& look, const std::vector<Candidate>& pool, std::span<const int> list,
             double gate_probability, const OnTrack& on_track, bool manoeuvre = false);

  /// Each plot's clutter density for this look; the clutter map counts the plots no firm
  /// track gates (in `candidates`): those are the false plots. The plots of each track's gate
  /// then share its density (Preprocessing::share_density).
  void estimate_clutter_density(Preprocessing& pre, const std::vector<PointTrack>& tracks,
                                const std::vector<Candidate>& candidates);

 private:
  const JpdaResult& pda_marginals(const JpdaProblem& problem);

  config::AssociationSpec spec_;
  ClusterBuilder clusters_;
  JpdaSolver jpda_;
  JpdaSolver jpda_manoeuvre_;
  GnnAssociator gnn_;
  JpdaResult pda_result_;
  std::vector<GatedPair> pairs_;
  std::vector<std::uint8_t> false_plots_;
  std::vector<int> gate_;  // one track's candidate plots (estimate_clutter_density)
  // Per-solve workspaces, kept from cluster to cluster and look to look.
  JpdaProblem problem_;
  std::vector<int> first_;
  std::vector<double> beta_;
  std::vector<int> mine_;
};

}  // namespace skytrack
