#include "skytrack/tracking/cluster_associator.hpp"

#include <algorithm>
#include <string>

#include "point_tracker_support.hpp"

namespace skytrack {

using namespace tracking_detail;

ClusterAssociator::ClusterAssociator(const config::TrackingProfile& profile)
    : spec_(profile.association),
      jpda_(JpdaOptions{.max_exact_tracks = profile.association.max_exact_cluster_size,
                        .k_best = profile.association.k_best}),
      jpda_manoeuvre_(JpdaOptions{.max_exact_tracks = profile.association.max_exact_cluster_size,
                                  .k_best = std::min(profile.association.k_best, kManoeuvreKBest),
                                  .max_exact_states = kManoeuvreExactStates}) {}

const JpdaResult& ClusterAssociator::pda_marginals(const JpdaProblem& problem) {
  // Each track on its own (PDA): beta_j ~ likelihood ratio_j, beta_0 ~ miss weight.
  pda_result_ = JpdaResult{};
  const Eigen::Index n = problem.likelihood.rows(), m = problem.likelihood.cols();
  pda_result_.beta = Eigen::MatrixXd::Zero(n, m + 1);
  for (Eigen::Index t = 0; t < n; ++t) {
    const double total =
        problem.miss[t] + problem.likelihood.row(t).sum() / problem.clutter_density;
    if (!(total > 0.0)) {
      pda_result_.beta(t, 0) = 1.0;
      continue;
    }
    pda_result_.beta(t, 0) = problem.miss[t] / total;
    for (Eigen::Index j = 0; j < m; ++j) {
      pda_result_.beta(t, j + 1) = problem.likelihood(t, j) / problem.clutter_density / total;
    }
  }
  pda_result_.approximated = true;
  return pda_result_;
}

void ClusterAssociator::solve(const Look& look, const std::vector<Candidate>& pool,
                              std::span<const int> list, double gate_probability,
                              const OnTrack& on_track, bool manoeuvre) {
  const double pd = spec_.detection_probability;
  const Preprocessing& pre = look.pre;
  // Candidates are grouped by track (they were made track by track) and clustered.
  pairs_.clear();
  for (const int k : list) pairs_.push_back({pool[k].track, pool[k].plot});
  const std::span<const Cluster> clusters =
      clusters_.build(look.tracks, static_cast<int>(pre.plots().size()), pairs_);
  const auto n_all = static_cast<std::size_t>(look.tracks);
  std::vector<int>& first = first_;  // range of `list` per track
  first.assign(n_all + 1, 0);
  for (const int k : list) ++first[pool[k].track + 1];
  for (std::size_t t = 0; t < n_all; ++t) first[t + 1] += first[t];

  std::vector<double>& beta = beta_;
  std::vector<int>& mine = mine_;
  JpdaProblem& problem = problem_;
  for (const Cluster& cluster : clusters) {
    const auto n_tracks = static_cast<Eigen::Index>(cluster.tracks.size());
    const auto n_plots = static_cast<Eigen::Index>(cluster.plots.size());
    if (n_plots == 0) {
      for (const int t : cluster.tracks) on_track(t, {}, {}, 1.0);
      continue;
    }
    ++look.report.point.clusters;
    look.report.point.largest_cluster =
        std::max(look.report.point.largest_cluster, static_cast<int>(n_tracks));
    // Each plot's likelihood ratio against clutter in its own measurement space.
    problem.likelihood.setZero(n_tracks, n_plots);
    problem.miss.setConstant(n_tracks, 1.0 - pd * gate_probability);
    problem.clutter_density = 1.0;
    const auto column = [&](int plot) {
      return std::find(cluster.plots.begin(), cluster.plots.end(), plot) - cluster.plots.begin();
    };
    for (Eigen::Index ti = 0; ti < n_tracks; ++ti) {
      const int t = cluster.tracks[ti];
      for (int k = first[t]; k < first[t + 1]; ++k) {
        const Candidate& c = pool[list[k]];
        problem.likelihood(ti, column(c.plot)) =
            pd * c.likelihood / pre.density(pre.plots()[c.plot], c.plot);
      }
    }
    const bool gnn = spec_.method == config::AssociationMethod::kGnn;
    const auto exact = static_cast<Eigen::Index>(spec_.max_exact_cluster_size);
    const bool too_large = n_tracks > kKBestClusterFactor * exact;
    const bool pda = !gnn && n_tracks > exact && (manoeuvre || too_large);
    const JpdaResult& result = pda ? pda_marginals(problem)
                                   : (gnn ? gnn_.associate(problem)
                                          : (manoeuvre ? jpda_manoeuvre_ : jpda_).solve(problem));
    look.numeric_failures += result.status != JpdaStatus::kOk;
    if (pda) {
      ++look.report.point.approximated_clusters;
      add_event(look.events, TrackEventType::kJpdaApproximated, 0,
                std::to_string(n_tracks) + " tracks, " + std::to_string(n_plots) + " plots, " +
                    (manoeuvre ? "manoeuvre gates" : "too many for k-best") + ": PDA per track");
    } else if (result.approximated) {
      ++look.report.point.approximated_clusters;
      add_event(look.events, TrackEventType::kJpdaApproximated, 0,
                std::to_string(n_tracks) + " tracks, " + std::to_string(n_plots) + " plots, " +
                    std::to_string(spec_.k_best) + " best joint events");
    }
    for (Eigen::Index ti = 0; ti < n_tracks; ++ti) {
      const int t = cluster.tracks[ti];
      beta.clear();
      mine.clear();
      for (int k = first[t]; k < first[t + 1]; ++k) {
        beta.push_back(result.beta(ti, column(pool[list[k]].plot) + 1));
        mine.push_back(list[k]);
      }
      on_track(t, mine, beta, result.beta(ti, 0));
    }
  }
}

void ClusterAssociator::estimate_clutter_density(Preprocessing& pre,
                                                 const std::vector<PointTrack>& tracks,
                                                 const std::vector<Candidate>& candidates) {
  false_plots_.assign(pre.plots().size(), 1);
  for (const Candidate& c : candidates) {
    if (is_reported_as_firm(tracks[c.track].life.status)) false_plots_[c.plot] = 0;
  }
  pre.estimate_density(false_plots_);
  // Candidates come track by track (gater.cpp): each run is one track's gate.
  for (std::size_t k = 0; k < candidates.size();) {
    gate_.clear();
    const int track = candidates[k].track;
    for (; k < candidates.size() && candidates[k].track == track; ++k) {
      gate_.push_back(candidates[k].plot);
    }
    pre.share_density(gate_);
  }
}

}  // namespace skytrack
