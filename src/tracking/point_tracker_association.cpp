// The point tracker's association and update: clutter rejection, the clutter density each
// plot is weighed against, JPDA over the clusters of candidates, and the IMM-PDA update.
#include "skytrack/tracking/point_tracker.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <numbers>
#include <utility>

#include <Eigen/Eigenvalues>

#include "point_tracker_support.hpp"
#include "skytrack/core/chi_square.hpp"
#include "skytrack/geometry/frames.hpp"

namespace skytrack {

using namespace tracking_detail;

void PointTracker::reject_clutter(ScanReport& report) {
  if (!pre_->rejects_clutter() || pre_->plots().empty()) return;
  // Plots in the gate of a confirmed track are kept whatever their density.
  std::vector<std::uint8_t> protect(pre_->plots().size(), 0);
  for (const Candidate& c : candidates_) {
    const TrackStatus status = tracks_[c.track].life.status;
    if (status == TrackStatus::kConfirmed || status == TrackStatus::kCoasting) {
      protect[c.plot] = 1;
    }
  }
  const clutter::ClutterRejectionResult& result = pre_->reject_clutter(protect);
  std::erase_if(candidates_, [&](const Candidate& c) { return pre_->rejected(c.plot); });
  std::erase_if(manoeuvre_candidates_, [&](const Candidate& c) { return pre_->rejected(c.plot); });
  report.plots_rejected_clutter = result.rejected;
  add_event(
      events_, TrackEventType::kClutterRejected, 0,
      std::to_string(result.rejected) + " of " + std::to_string(pre_->plots().size()) + " plots");
}

void PointTracker::associate_and_update(ScanReport& report, TrackFrame& frame) {
  estimate_clutter_density();
  kind_list_.resize(candidates_.size());
  for (std::size_t k = 0; k < candidates_.size(); ++k) kind_list_[k] = static_cast<int>(k);
  solve_clusters(candidates_, kind_list_, profile_.association.gate_probability, report,
                 [&](int t, std::span<const int> mine, std::span<const double> beta, double miss) {
                   update_track(t, mine, beta, miss, frame);
                 });
}

const JpdaResult& PointTracker::pda_marginals(const JpdaProblem& problem) {
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

void PointTracker::solve_clusters(const std::vector<Candidate>& pool, std::span<const int> list,
                                  double gate_probability, ScanReport& report,
                                  const OnTrack& on_track, bool pda_above_exact) {
  const double pd = profile_.association.detection_probability;
  // Candidates are grouped by track (they were made track by track) and clustered.
  pairs_.clear();
  for (const int k : list) pairs_.push_back({pool[k].track, pool[k].plot});
  const std::span<const Cluster> clusters = clusters_.build(
      static_cast<int>(tracks_.size()), static_cast<int>(pre_->plots().size()), pairs_);
  std::vector<int> first(tracks_.size() + 1, 0);  // range of `list` per track
  for (const int k : list) ++first[pool[k].track + 1];
  for (std::size_t t = 0; t < tracks_.size(); ++t) first[t + 1] += first[t];

  std::vector<double> beta;
  std::vector<int> mine;
  for (const Cluster& cluster : clusters) {
    const auto n_tracks = static_cast<Eigen::Index>(cluster.tracks.size());
    const auto n_plots = static_cast<Eigen::Index>(cluster.plots.size());
    if (n_plots == 0) {
      for (const int t : cluster.tracks) on_track(t, {}, {}, 1.0);
      continue;
    }
    ++report.point.clusters;
    report.point.largest_cluster =
        std::max(report.point.largest_cluster, static_cast<int>(n_tracks));
    // Each plot's likelihood ratio against clutter in its own measurement space.
    JpdaProblem problem;
    problem.likelihood = Eigen::MatrixXd::Zero(n_tracks, n_plots);
    problem.miss = Eigen::VectorXd::Constant(n_tracks, 1.0 - pd * gate_probability);
    problem.clutter_density = 1.0;
    const auto column = [&](int plot) {
      return std::find(cluster.plots.begin(), cluster.plots.end(), plot) - cluster.plots.begin();
    };
    for (Eigen::Index ti = 0; ti < n_tracks; ++ti) {
      const int t = cluster.tracks[ti];
      for (int k = first[t]; k < first[t + 1]; ++k) {
        const Candidate& c = pool[list[k]];
        problem.likelihood(ti, column(c.plot)) =
            pd * c.likelihood / pre_->density(pre_->plots()[c.plot], c.plot);
      }
    }
    const bool gnn = profile_.association.method == config::AssociationMethod::kGnn;
    const auto exact = static_cast<Eigen::Index>(profile_.association.max_exact_cluster_size);
    const bool too_large = n_tracks > kKBestClusterFactor * exact;
    const bool pda = !gnn && n_tracks > exact && (pda_above_exact || too_large);
    const JpdaResult& result =
        pda ? pda_marginals(problem)
            : (gnn ? gnn_.associate(problem)
                   : (pda_above_exact ? jpda_manoeuvre_ : jpda_).solve(problem));
    numeric_failures_ += result.status != JpdaStatus::kOk;
    if (pda) {
      ++report.point.approximated_clusters;
      add_event(events_, TrackEventType::kJpdaApproximated, 0,
                std::to_string(n_tracks) + " tracks, " + std::to_string(n_plots) + " plots, " +
                    (pda_above_exact ? "manoeuvre gates" : "too many for k-best") +
                    ": PDA per track");
    } else if (result.approximated) {
      ++report.point.approximated_clusters;
      add_event(events_, TrackEventType::kJpdaApproximated, 0,
                std::to_string(n_tracks) + " tracks, " + std::to_string(n_plots) + " plots, " +
                    std::to_string(profile_.association.k_best) + " best joint events");
    }
    for (Eigen::Index ti = 0; ti < n_tracks; ++ti) {
      const int t = cluster.tracks[ti];
      beta.clear();
      mine.clear();
      for (int k = first[t]; k < first[t + 1]; ++k) {
        beta.push_back(result.beta(ti, column(pool[list[k]].plot) + 1));
        mine.push_back(list[k]);
      }
      // The non-manoeuvre gates decide which plots the tracks explain (initiation).
      if (&pool == &candidates_) note_explained(pool, mine, beta);
      on_track(t, mine, beta, result.beta(ti, 0));
    }
  }
}

void PointTracker::update_track(int t, std::span<const int> candidates,
                                std::span<const double> beta_plots, double beta_miss,
                                TrackFrame& frame, bool reports_deletion) {
  PointTrack& track = tracks_[t];
  if (!covered_[t] && candidates.empty()) return;  // not looked at: neither updated nor aged
  const double pd = profile_.association.detection_probability;
  const PlotRatios ratios =
      soft_update(t, candidates_, candidates, beta_plots, beta_miss, track.id, frame);
  const double detection = 1.0 - beta_miss;
  track.quality = 0.8 * track.quality + 0.2 * detection;
  // P_D on its detectability chain, as in its support: a target masked in a clutter area
  // is not evidence that there is none (IPDA with a detectability chain).
  update_existence(track.life, ratios.sum,
                   support_detection_probability(track.life, pd, detectability_at(t)),
                   profile_.association.gate_probability, profile_.point.track_life);
  add_support(track.life, ratios, t);
  bool detected = detection > 0.5;
  if (holds_last_motion() && is_reported_as_firm(track.life.status) &&
      static_cast<std::size_t>(t) < dense_.size() && dense_[t] != 0) {
    // branching.coast_on_last_motion: a father with no valid association (§2.2: no plot
    // likelier than its miss) coasts on the motion it was last seen in, however much its
    // plots weigh together; the turns it may have started are its sons' to find (§4.2).
    detected = valid_association(beta_plots, beta_miss);
    if (!detected) hold_last_motion(track);
  }
  const LifeChange change =
      advance_life(track.life, detected, mode_spread(track.estimate, kLifeSpreadDims),
                   profile_.point.track_life);
  if (change.confirmed) {
    add_event(events_, TrackEventType::kConfirmed, track.id, "");
    if (branching()) confirmed_now_.push_back(t);
  }
  if (change.started_coasting) add_event(events_, TrackEventType::kCoasting, track.id, "");
  if (change.deleted && reports_deletion)
    add_event(events_, TrackEventType::kDeleted, track.id, "");
}

PointTracker::PlotRatios PointTracker::soft_update(int t, std::vector<Candidate>& pool,
                                                   std::span<const int> candidates,
                                                   std::span<const double> beta_plots,
                                                   double beta_miss, std::int64_t number,
                                                   TrackFrame& frame) {
  PointTrack& track = tracks_[t];
  const double pd = profile_.association.detection_probability;
  if (candidates.empty()) {
    track.estimate = filter_.predict(track.estimate, std::max(frame.time, track.estimate.time));
    return {};
  }
  PlotRatios ratios;
  // Plots with a negligible weight change nothing but cost a Kalman update per mode: they
  // are left out and the other weights renormalised.
  hypotheses_.clear();
  kept_beta_.clear();
  double density = 0.0, kept = beta_miss;
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    Candidate& c = pool[candidates[k]];
    const double plot_density = pre_->density(pre_->plots()[c.plot], c.plot);
    density += plot_density / static_cast<double>(candidates.size());
    if (c.hypothesis.usable) {
      const double ratio = c.hypothesis.likelihood / plot_density;
      ratios.sum += ratio;
      ratios.best = std::max(ratios.best, ratio);
    }
    if (beta_plots[k] >= kAssociationReportThreshold) {
      add_association(frame, number, pre_->plots()[c.plot].plot_id, pre_->plots()[c.plot].scan,
                      beta_plots[k]);
    }
    if (beta_plots[k] < kNegligibleBeta) continue;
    hypotheses_.push_back(std::move(c.hypothesis));
    kept_beta_.push_back(beta_plots[k]);
    kept += beta_plots[k];
  }
  for (double& b : kept_beta_) b /= kept;
  track.estimate = counted(filter_.update(predicted_[t], hypotheses_, kept_beta_, beta_miss / kept,
                                          pd, profile_.association.gate_probability, density));
  if (holds_last_motion() && valid_association(beta_plots, beta_miss)) {
    track.last_detected = track.estimate;  // it found its target (a son, later a father)
  }
  return ratios;
}

void PointTracker::estimate_clutter_density() {
  // The clutter map counts the plots no firm track gates: those are the false plots.
  false_plots_.assign(pre_->plots().size(), 1);
  for (const Candidate& c : candidates_) {
    if (is_reported_as_firm(tracks_[c.track].life.status)) false_plots_[c.plot] = 0;
  }
  pre_->estimate_density(false_plots_);
}

}  // namespace skytrack
