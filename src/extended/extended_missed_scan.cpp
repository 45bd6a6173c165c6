// One scan's deferred decision on the plots a track took (see extended_tracker.hpp): beside
// the track, the one it would be had that scan been a miss is kept, and the next scan's plots
// choose between the two (two track hypotheses over two scans, pruned after one scan: the
// N-scan pruning of multiple-hypothesis tracking with N = 1).
#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Cholesky>

#include "skytrack/extended/extended_existence.hpp"
#include "skytrack/extended/extended_tracker.hpp"

namespace skytrack::extended {

void ExtendedTracker::keep_missed_scan(int t, const ExtendedObject& quiet, double evidence_before,
                                       double log_ratio) {
  ExtendedTrack& track = tracks_[t];
  MissedScan& missed = track.missed_scan;
  missed.kept = std::isfinite(log_ratio);
  if (!missed.kept) return;
  // As the miss branch of the update loop: the quiet prediction, coasted at constant velocity.
  missed.object = quiet;
  if (spec_.coast_constant_velocity && scan_dt_ > 0.0) {
    const Eigen::Vector2d accel(priors_[t].x[4], priors_[t].x[5]);
    coast_constant_velocity(missed.object.x, accel, scan_dt_);
  }
  missed.levels = track.levels;
  if (mixes_levels()) {
    for (ExtendedObject& level : missed.levels.object) level.x = missed.object.x;
  }
  const ExistenceSpec& e = spec_.existence;
  missed.existence_log_odds = existence_miss(existence_predict(track.existence_log_odds, e),
                                             std::max(1, spec_.min_partition_plots), e);
  missed.manoeuvre_evidence = evidence_before;
  missed.log_ratio = log_ratio;
  missed.misses = track.misses + 1;
}

void ExtendedTracker::reconsider_missed_scans() {
  // A confirmed track that finds no plots of its own this scan, where the track it would be
  // had its last scan been a miss finds a partition no track gates: the two branches differ
  // in those two scans only, each scan's plots the object's against clutter (the clutter
  // test's log ratio, a miss 0). The track kept: the last scan's ratio plus this partition's
  // under it, if in its plot gate (the claim of an ungated partition), else a miss; the
  // other branch: this partition's under it. A coasting track's widened gate holds a clutter
  // cluster a few hundred metres off; taken, the track followed it off, and its object's
  // returning plots started a new track.
  const int min_plots = std::max(1, spec_.min_partition_plots);
  const PosMat H = position_matrix();
  std::vector<int>& taken = weighed_;
  std::vector<int>& best_taken = best_weighed_;
  // The plots of `group` in the plot gate of a track predicted at `object` (association extent
  // `extent`) into `taken`, and their log ratio (-inf: fewer than min_plots).
  auto weigh = [&](const ExtendedObject& object, const Eigen::Matrix2d& extent,
                   const std::vector<int>& group) {
    const Eigen::Matrix2d centre_cov = H * object.P * H.transpose();
    taken.clear();
    plot_buffer_.clear();
    Eigen::Matrix2d noise = Eigen::Matrix2d::Zero();
    for (int i : group) {
      const Eigen::LLT<Eigen::Matrix2d> llt(centre_cov + kUniformScatter * extent + noises_[i]);
      const Eigen::Vector2d nu = positions_[i] - object.position();
      if (llt.info() != Eigen::Success || !(nu.dot(llt.solve(nu)) <= spec_.plot_gate)) continue;
      taken.push_back(i);
      plot_buffer_.push_back(positions_[i]);
      noise += noises_[i];
    }
    if (static_cast<int>(taken.size()) < min_plots) return -std::numeric_limits<double>::infinity();
    noise /= static_cast<double>(taken.size());
    return object_plots_log_ratio(plot_buffer_, object.position(), centre_cov,
                                  kUniformScatter * extent + noise, spec_.existence);
  };
  for (int t = 0; t < static_cast<int>(tracks_.size()); ++t) {
    ExtendedTrack& track = tracks_[t];
    const MissedScan& missed = track.missed_scan;
    if (!missed.kept || track.status != ExtendedTrackStatus::kConfirmed || track.unresolved ||
        static_cast<int>(track_plots_[t].size()) >= min_plots) {
      continue;
    }
    ExtendedTrack alternative = track;
    alternative.object = missed.object;
    alternative.levels = missed.levels;
    if (scan_dt_ > 0.0 && mixes_levels()) {
      predict_levels(alternative.levels, estimator_, spec_.motion, scan_dt_, alternative.object);
    } else if (scan_dt_ > 0.0) {
      estimator_.predict(alternative.object, scan_dt_);
    }
    const Eigen::Matrix2d extent = association_extent(alternative);
    // The partitions no track gated, then those a track took beside a likelier one of its own.
    const std::size_t candidates = unassigned_.size() + yieldable_.size();
    auto candidate = [&](std::size_t g) -> const std::vector<int>& {
      return g < unassigned_.size() ? *unassigned_[g]
                                    : groups_[yieldable_[g - unassigned_.size()].partition];
    };
    std::size_t best = candidates;
    double best_margin = 0.0;
    for (std::size_t g = 0; g < candidates; ++g) {
      const double kept = missed.log_ratio +
                          std::max(0.0, weigh(track.object, association_extents_[t], candidate(g)));
      const double other = weigh(alternative.object, extent, candidate(g));
      if (other - kept > best_margin) best_margin = other - kept, best = g, best_taken = taken;
    }
    if (best == candidates) continue;
    // The last scan a miss: the branch's state, existence and counts, and this scan's plots.
    priors_[t] = missed.object;
    track.object = alternative.object;
    track.levels = alternative.levels;
    track.existence_log_odds = missed.existence_log_odds;
    track.manoeuvre_evidence = missed.manoeuvre_evidence;
    track.misses = missed.misses;
    track.hits = std::max(0, track.hits - 1);
    association_extents_[t] = extent;
    track_plots_[t] = best_taken;
    if (best < unassigned_.size()) {
      unassigned_.erase(unassigned_.begin() + static_cast<std::ptrdiff_t>(best));
    } else {  // the holder gives the piece up
      const Yieldable piece = yieldable_[best - unassigned_.size()];
      std::erase_if(track_plots_[piece.track],
                    [&](int i) { return partition_of_[i] == piece.partition; });
      yieldable_.erase(yieldable_.begin() + static_cast<std::ptrdiff_t>(best - unassigned_.size()));
    }
  }
}

}  // namespace skytrack::extended
