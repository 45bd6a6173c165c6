// The extended tracker's association of partitions several tracks or no track gate: the
// likeliest of the tentative tracks sharing one, the coast of two shapeless tracks through a
// crossing, the split of a shared partition (hard-assignment EM, and its exchange where
// likelier) and the claim of an ungated partition by a confirmed track seen off its prediction
// (see extended_tracker.hpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "skytrack/extended/extended_existence.hpp"
#include "skytrack/extended/extended_tracker.hpp"

namespace skytrack::extended {
namespace {

// Assign-and-move rounds of a shared partition's split: the centres settle in two or three.
constexpr int kSplitIterations = 3;

}  // namespace

Eigen::Matrix2d ExtendedTracker::association_extent(const ExtendedTrack& track) const noexcept {
  // The extent association uses is floored at a new track's semi-axes: an estimate that
  // collapsed on a scan of two or three plots (SMF-EOT's empty Minkowski difference) would
  // otherwise shrink the track's gate and its share of a split below the object it follows.
  const double floor = spec_.initial_extent_axis * spec_.initial_extent_axis;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(track.object.extent);
  if (eig.info() != Eigen::Success) return track.object.extent;
  const Eigen::Vector2d axes = eig.eigenvalues().cwiseMax(floor);
  return eig.eigenvectors() * axes.asDiagonal() * eig.eigenvectors().transpose();
}

bool ExtendedTracker::crossing_unresolved() const noexcept {
  // Two confirmed tracks whose predicted objects overlap share one partition. The split
  // goes by the objects' shapes and centres; when a track's extent estimate collapsed below
  // the floor (SMF-EOT's inner estimate on a few plots) it has no shape, and with the
  // centres within the objects' size the split is arbitrary: a wrong one moves each centre
  // towards the other object and turns its velocity, and the tracks leave the crossing with
  // each other's objects. When the tracks' own velocities separate the objects by the next
  // scan, both coast through this one on their predictions (identity by motion), once:
  // tracks still unresolved after it (a duplicate, objects in formation) are split.
  if (gated_.size() != 2 || !(scan_dt_ > 0.0)) return false;
  const int ta = gated_[0].track, tb = gated_[1].track;
  const ExtendedTrack& a = tracks_[ta];
  const ExtendedTrack& b = tracks_[tb];
  if (a.status != ExtendedTrackStatus::kConfirmed || b.status != ExtendedTrackStatus::kConfirmed ||
      was_unresolved_[ta] || was_unresolved_[tb]) {
    return false;
  }
  const double floor = spec_.initial_extent_axis * spec_.initial_extent_axis;
  auto shapeless = [floor](const ExtendedTrack& track) {
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(track.object.extent);
    return eig.info() == Eigen::Success && eig.eigenvalues().maxCoeff() <= floor;
  };
  if (!shapeless(a) && !shapeless(b)) return false;
  // Overlap: the centres' difference within the sum of both objects and centre covariances.
  const PosMat H = position_matrix();
  const Eigen::Matrix2d G = H * (a.object.P + b.object.P) * H.transpose() +
                            association_extents_[ta] + association_extents_[tb];
  const Eigen::LLT<Eigen::Matrix2d> llt(G);
  if (llt.info() != Eigen::Success) return false;
  const Eigen::Vector2d now = a.position() - b.position();
  const Eigen::Vector2d next = now + scan_dt_ * (a.velocity() - b.velocity());
  return now.dot(llt.solve(now)) <= 1.0 && next.dot(llt.solve(next)) > 1.0;
}

void ExtendedTracker::keep_likeliest_tentative(const Eigen::Vector2d& mean,
                                               const Eigen::Matrix2d& noise) {
  // Young tracks sharing a partition: the distance partitioning found one object's plots,
  // and the tracks are its earlier scans' pieces (a long hull whose plots left a gap wider
  // than the partition distance) or a duplicate. Split, each piece would keep its half and
  // be confirmed beside the other; the partition goes whole to the track likeliest to have
  // given its mean (d^2 + ln det G), and the others starve.
  int best = -1;
  double best_cost = std::numeric_limits<double>::infinity();
  for (const Gated& g : gated_) {
    double log_det = 0.0;
    const double cost = gate_distance(g.track, mean, noise, 1.0, &log_det) + log_det;
    if (cost < best_cost) best_cost = cost, best = g.track;
  }
  if (best < 0) return;
  gated_.clear();
  gated_.push_back({best, best_cost});
}

void ExtendedTracker::split_shared(const std::vector<int>& group) {
  // Several tracks gate it (objects close or crossing). A plot-by-plot split from the
  // predictions alone starves the less certain track: its flatter likelihood loses every
  // plot in the overlap, it coasts, grows flatter still and drifts off while the neighbour
  // takes both objects' plots and may leave with the wrong object. Instead the split is a
  // two-component mixture fitted by hard-assignment EM: assign each plot by its likelihood
  // N(z; c, C + X / 4 + R) under each track's current centre c (covariance C), move each
  // centre to its posterior given the plots it holds, and repeat, so each object's plots
  // pull its own centre rather than the prediction's error deciding.
  // Confirmed tracks only: tentative ones sharing a partition leave it to the likeliest
  // (keep_likeliest_tentative).
  const int k = static_cast<int>(gated_.size());
  split_centre_.resize(k);
  split_cov_.resize(k);
  const PosMat H = position_matrix();
  // The split starts from the predicted objects' shapes alone (C = 0): a track that faded
  // before the crossing has the larger HPH', and with it in the first assignment its flatter
  // likelihood would lose every plot, leaving it nothing to move to.
  for (int g = 0; g < k; ++g) {
    split_centre_[g] = tracks_[gated_[g].track].position();
    split_cov_[g].setZero();
  }
  split_owner_.assign(group.size(), -1);
  for (int iteration = 0; iteration < kSplitIterations; ++iteration) {
    for (std::size_t p = 0; p < group.size(); ++p) {
      const int i = group[p];
      double best_cost = std::numeric_limits<double>::infinity();
      split_owner_[p] = -1;
      for (int g = 0; g < k; ++g) {
        const Eigen::Matrix2d G =
            split_cov_[g] + kUniformScatter * association_extents_[gated_[g].track] + noises_[i];
        const Eigen::LLT<Eigen::Matrix2d> llt(G);
        if (llt.info() != Eigen::Success) continue;
        const Eigen::Vector2d nu = positions_[i] - split_centre_[g];
        const double cost =
            nu.dot(llt.solve(nu)) + 2.0 * std::log(llt.matrixL()(0, 0) * llt.matrixL()(1, 1));
        if (cost < best_cost) best_cost = cost, split_owner_[p] = g;
      }
    }
    for (int g = 0; g < k; ++g) {  // each centre's posterior from the plots it holds
      const ExtendedTrack& track = tracks_[gated_[g].track];
      Eigen::Vector2d mean = Eigen::Vector2d::Zero();
      Eigen::Matrix2d noise = Eigen::Matrix2d::Zero();
      int count = 0;
      for (std::size_t p = 0; p < group.size(); ++p) {
        if (split_owner_[p] != g) continue;
        mean += positions_[group[p]], noise += noises_[group[p]], ++count;
      }
      const Eigen::Matrix2d prior = H * track.object.P * H.transpose();
      split_centre_[g] = track.position();
      split_cov_[g] = prior;
      if (count == 0) continue;
      mean /= count;
      const Eigen::Matrix2d spread =
          (kUniformScatter * association_extents_[gated_[g].track] + noise / count) / count;
      const Eigen::LLT<Eigen::Matrix2d> llt(prior + spread);
      if (llt.info() != Eigen::Success) continue;
      const Eigen::Matrix2d K = llt.solve(prior).transpose();  // prior (prior + spread)^-1
      split_centre_[g] += K * (mean - track.position());
      split_cov_[g] = prior - K * prior;
    }
  }
  // SMF-EOT is not exchanged (exchange_if_likelier): without the test against one object its
  // split needs no models.
  if (k == 2 && (spec_.kind != EstimatorKind::kSmf || spec_.one_object_split_test)) {
    std::vector<Eigen::Vector2d> share[2];
    PlotsModel model[2];
    plots_models(group, share, model);
    exchange_if_likelier(share, model);
    if (spec_.one_object_split_test) one_object_only(share, model);
  }
  for (std::size_t p = 0; p < group.size(); ++p) {
    if (split_owner_[p] < 0) continue;
    const int t = gated_[split_owner_[p]].track;
    const int i = group[p];
    if (gate_distance(t, positions_[i], noises_[i], kUniformScatter, nullptr) <= spec_.plot_gate) {
      track_plots_[t].push_back(i);
    }
  }
}

void ExtendedTracker::exchange_if_likelier(std::vector<Eigen::Vector2d> (&share)[2],
                                           const PlotsModel (&model)[2]) {
  // The EM settles in the optimum nearest its start, the predicted shapes alone: a track that
  // coasted far behind its object starts nearer the other object's plots and may leave with
  // them. With two tracks the other labelling is the split exchanged; the likelier of the two
  // under the tracks' predictions with their centre covariances is kept. SMF-EOT's P bounds
  // its state set: it is no covariance to weigh the two with.
  if (spec_.kind == EstimatorKind::kSmf) return;
  if (!(exchange_log_ratio(share[0], share[1], model[0], model[1]) > 0.0)) return;
  for (int& owner : split_owner_) {
    if (owner >= 0) owner = 1 - owner;
  }
  std::swap(share[0], share[1]);
}

void ExtendedTracker::plots_models(const std::vector<int>& group,
                                   std::vector<Eigen::Vector2d> (&share)[2],
                                   PlotsModel (&model)[2]) const {
  // Each track's share of a two-track split and its model of its object's plots: centre at
  // its prediction with HPH', each plot scattered by X / 4 plus the plots' mean noise.
  Eigen::Matrix2d noise = Eigen::Matrix2d::Zero();
  for (std::size_t p = 0; p < group.size(); ++p) {
    if (split_owner_[p] >= 0) share[split_owner_[p]].push_back(positions_[group[p]]);
    noise += noises_[group[p]];
  }
  noise /= static_cast<double>(std::max<std::size_t>(group.size(), 1));
  const PosMat H = position_matrix();
  for (int g = 0; g < 2; ++g) {
    const int t = gated_[g].track;
    model[g] = {tracks_[t].position(), H * tracks_[t].object.P * H.transpose(),
                kUniformScatter * association_extents_[t] + noise};
  }
}

void ExtendedTracker::one_object_only(const std::vector<Eigen::Vector2d> (&share)[2],
                                      const PlotsModel (&model)[2]) {
  // Two tracks split the partition, but one object may be all of it (the other missed, as a
  // crossing's objects part): a split less likely than one track's object missed and the
  // other's giving every plot (split_log_ratio) gives them all to that other track.
  if (share[0].empty() || share[1].empty()) return;
  const ExistenceSpec& e = spec_.existence;
  const double without[2] = {split_log_ratio(share[0], share[1], model[0], model[1], e),
                             split_log_ratio(share[1], share[0], model[1], model[0], e)};
  const int absent = without[0] <= without[1] ? 0 : 1;
  if (!(without[absent] < 0.0)) return;
  for (int& owner : split_owner_) owner = 1 - absent;
}

bool ExtendedTracker::claim_by_confirmed(const std::vector<int>& group) {
  // A partition whose mean gates no track but whose plots fall inside the plot gate
  // (HPH' + X / 4 + R, which widens as the track coasts) of a confirmed track that found
  // no plots of its own this scan is that object seen off its prediction, not a new
  // object: a tentative track started on it would duplicate the confirmed one and take its
  // number when the confirmed one is dropped. A track that has its plots keeps them alone:
  // a second cluster would read as extent.
  const int min_plots = std::max(1, spec_.min_partition_plots);
  int best = -1, best_count = 0;
  for (int t = 0; t < static_cast<int>(tracks_.size()); ++t) {
    if (tracks_[t].status != ExtendedTrackStatus::kConfirmed || tracks_[t].unresolved) continue;
    if (static_cast<int>(track_plots_[t].size()) >= min_plots) continue;
    int count = 0;
    for (int i : group) {
      count +=
          gate_distance(t, positions_[i], noises_[i], kUniformScatter, nullptr) <= spec_.plot_gate;
    }
    if (count > best_count) best_count = count, best = t;
  }
  if (best < 0 || best_count < min_plots) return false;
  for (int i : group) {
    if (gate_distance(best, positions_[i], noises_[i], kUniformScatter, nullptr) <=
        spec_.plot_gate) {
      track_plots_[best].push_back(i);
    }
  }
  return true;
}

}  // namespace skytrack::extended
