// The extended tracker's rules on the plots a track took in a scan, before its update:
// lone plots beside its cluster, a second noise level for a manoeuvre, the plots taken as
// clutter (see extended_tracker.hpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <Eigen/Cholesky>

#include "skytrack/extended/extended_existence.hpp"
#include "skytrack/extended/extended_tracker.hpp"

namespace skytrack::extended {

void ExtendedTracker::drop_lone_plots(int t) {
  // An object seen gives a cluster of plots (a partition of at least min_partition_plots,
  // as a new track needs). A plot alone in its partition is an outlying scatterer of that
  // object only within the object's reach of its cluster; elsewhere, or in a scan without
  // a cluster, it is clutter, which a gate widened by a coast holds in growing numbers:
  // taken, a few lone plots turned a coasting track off its object, or swelled a returning
  // object's scan into a count that read as clutter and deleted the track.
  std::vector<int>& plots = track_plots_[t];
  const int min_plots = std::max(1, spec_.min_partition_plots);
  auto lone = [this, min_plots](int i) { return partition_size(i) < min_plots; };
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  Eigen::Matrix2d noise = Eigen::Matrix2d::Zero();
  int clustered = 0;
  for (int i : plots) {
    if (!lone(i)) mean += positions_[i], noise += noises_[i], ++clustered;
  }
  if (clustered == static_cast<int>(plots.size())) return;
  if (clustered == 0) {
    plots.clear();
    return;
  }
  mean /= static_cast<double>(clustered);
  noise /= static_cast<double>(clustered);
  // The whole extent X, not the scatter X/4: the cluster may lie at one end of the object
  // and the lone plot at the other, and X estimated on few plots may fall short of the
  // object. (1 + 1/n): the cluster's mean of n plots scatters about the object's centre too.
  const double spread = 1.0 + 1.0 / static_cast<double>(clustered);
  const Eigen::LLT<Eigen::Matrix2d> llt(spread * (association_extents_[t] + noise));
  std::erase_if(plots, [&](int i) {
    if (!lone(i)) return false;
    const Eigen::Vector2d d = positions_[i] - mean;
    return llt.info() != Eigen::Success || !(d.dot(llt.solve(d)) <= spec_.plot_gate);
  });
}

void ExtendedTracker::keep_partitions_within_reach(int t) {
  // A track may take several partitions: a long hull's plots can leave a gap wider than the
  // partition distance. Pieces of one object have means within its extent of each other; a
  // partition farther than that from the track's best one (the mean nearest its prediction)
  // is another object's or clutter that a gate widened by a coast or a manoeuvre reached.
  // Taken, it pulled the track off its object towards the neighbour, whose own track then
  // found nothing. Its share of a split is dropped; a partition this track alone gated is
  // left unassigned (for a track's missed-scan branch, a claim, or a new track). SMF-EOT's
  // extent is an inner bound (the Minkowski difference) that a few plots of a long hull leave
  // far short of it, so there it tells no reach: such a partition stays, as one within reach
  // does, unless the missed-scan branch of a track that found nothing explains it
  // (reconsider_missed_scans: the neighbour's object, its track pulled off by clutter).
  std::vector<int>& plots = track_plots_[t];
  const int min_plots = std::max(1, spec_.min_partition_plots);
  pieces_.clear();
  for (int i : plots) {
    if (partition_size(i) < min_plots) continue;  // lone plots: drop_lone_plots
    auto piece = std::find_if(pieces_.begin(), pieces_.end(),
                              [&](const Piece& p) { return p.partition == partition_of_[i]; });
    if (piece == pieces_.end()) piece = pieces_.insert(pieces_.end(), Piece{partition_of_[i]});
    piece->mean += positions_[i], piece->noise += noises_[i], ++piece->count;
  }
  if (pieces_.size() < 2) return;
  const Piece* best = nullptr;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (Piece& piece : pieces_) {
    piece.mean /= static_cast<double>(piece.count);
    piece.noise /= static_cast<double>(piece.count);
    const double d2 = gate_distance(t, piece.mean, piece.noise, 1.0, nullptr);
    if (d2 < best_d2) best_d2 = d2, best = &piece;
  }
  if (!best) return;
  const Eigen::Matrix2d& X = association_extents_[t];
  for (const Piece& piece : pieces_) {
    if (&piece == best) continue;
    const bool shared = partition_split_[piece.partition];
    // Each piece's mean scatters about its own centre by (X / 4 + R) / n.
    const Eigen::Matrix2d G = X + (kUniformScatter * X + best->noise) / best->count +
                              (kUniformScatter * X + piece.noise) / piece.count;
    const Eigen::LLT<Eigen::Matrix2d> llt(G);
    const Eigen::Vector2d d = piece.mean - best->mean;
    const bool within = llt.info() == Eigen::Success && d.dot(llt.solve(d)) <= spec_.plot_gate;
    if (within || (!shared && spec_.kind == EstimatorKind::kSmf)) {
      if (!shared) yieldable_.push_back({t, piece.partition});
      continue;
    }
    std::erase_if(plots, [&](int i) { return partition_of_[i] == piece.partition; });
    if (!shared) unassigned_.push_back(&groups_[piece.partition]);
  }
}

Eigen::Matrix2d ExtendedTracker::buffer_track_plots(int t) {
  plot_buffer_.clear();
  Eigen::Matrix2d noise = Eigen::Matrix2d::Zero();
  for (int i : track_plots_[t]) plot_buffer_.push_back(positions_[i]), noise += noises_[i];
  return noise / static_cast<double>(track_plots_[t].size());
}

bool ExtendedTracker::predict_manoeuvre_if_likelier(int t, const Eigen::Matrix2d& noise) {
  // Two noise levels, chosen by the plots' likelihood under each prediction (no threshold
  // of its own): a quiet level keeps the gates of objects going straight tight against
  // clutter and crossing neighbours, the manoeuvre level follows a turn the quiet one lags.
  if (!chooses_levels() || !(scan_dt_ > 0.0)) return false;
  ExtendedTrack& track = tracks_[t];
  const Eigen::Matrix2d spread = kUniformScatter * association_extents_[t] + noise;
  const PosMat H = position_matrix();
  auto log_f = [&](const ExtendedObject& o) {
    return object_plots_log_density(plot_buffer_, o.position(), H * o.P * H.transpose(), spread);
  };
  turning_ = manoeuvre_predictions_[t];  // gate_centre_cov's
  // Page's CUSUM at zero: the evidence for a manoeuvre over the scans since it last fell to
  // zero, so a turn shown by several scans holds the manoeuvre level through a quiet-looking
  // scan of few plots.
  const double llr = log_f(turning_) - log_f(track.object);
  double& evidence = track.manoeuvre_evidence;
  evidence = std::isfinite(llr) ? std::max(0.0, evidence + llr) : 0.0;  // no density: quiet
  if (!(evidence > 0.0)) return false;
  std::swap(track.object, turning_);  // turning_ keeps the quiet prediction
  return true;
}

double ExtendedTracker::clutter_log_ratio(int t, const Eigen::Matrix2d& noise) const {
  // The plots' joint density under the track (centre N(c, HPH'), each plot scattered by
  // X/4 + R) against clutter of density lambda in a scan that missed the object.
  if (!spec_.clutter_scan_test) return std::numeric_limits<double>::quiet_NaN();
  const PosMat H = position_matrix();
  const ExtendedTrack& track = tracks_[t];
  const Eigen::Matrix2d spread = kUniformScatter * association_extents_[t] + noise;
  return object_plots_log_ratio(plot_buffer_, track.position(), H * track.object.P * H.transpose(),
                                spread, spec_.existence);
}

}  // namespace skytrack::extended
