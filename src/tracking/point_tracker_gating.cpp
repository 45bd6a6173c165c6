// The point tracker's gating: each track's validation gates round its prediction (and the
// manoeuvre and last-motion gates of the branch layer), giving the track-plot candidates.
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

void PointTracker::gate(const PlotScan& scan, double batch_mid, double half_span) {
  candidates_.clear();
  manoeuvre_candidates_.clear();
  // branching.last_motion_false_plots weighs the clutter round each plot while gating: from
  // all of this batch's plots (associate_branches re-estimates it from the ungated ones).
  if (holds_last_motion() && profile_.point.branching.last_motion_false_plots > 0.0) {
    estimate_clutter_density();
  }
  batch_mid_ = batch_mid;
  half_span_ = half_span;
  predicted_.resize(tracks_.size());
  if (branching()) {  // the manoeuvre gates start from the estimates before this batch
    // Assigned in place: the slots keep their storage from batch to batch.
    previous_.resize(tracks_.size());
    has_previous_.assign(tracks_.size(), 0);
    // Only tracks that may get a manoeuvre gate or start sons need it: firm fathers and
    // branches (most tracks in heavy clutter are tentative fathers).
    for (std::size_t t = 0; t < tracks_.size(); ++t) {
      const PointTrack& track = tracks_[t];
      if (track.branch != BranchType::kFather || is_reported_as_firm(track.life.status)) {
        // A father holding its last motion since a miss: its manoeuvre gate and sons start
        // from its last update (rule 6), coasted by its IMM, whose turn modes reach where a
        // turn since then has gone.
        previous_[t] = starts_from_coast(track) ? *track.coasted : track.estimate;
        has_previous_[t] = 1;
      }
    }
  }
  covered_.assign(tracks_.size(), 1);
  took_candidates_.assign(tracks_.size(), 0);
  dense_.assign(tracks_.size(), profile_.point.branching.last_motion_false_plots > 0.0 ? 0 : 1);
  suspended_at_gate_.clear();
  const double widest = gate_threshold_[kMaxMeasurementDim];
  for (std::size_t t = 0; t < tracks_.size(); ++t) {
    PointTrack& track = tracks_[t];
    // Undecided until its sons are gone; for one look only when it holds its last motion,
    // which stays its hypothesis beside its sons' (rule 5 then decides between them).
    if (track.undecided() && (tree_.branch_count(track.id) == 0 || holds_last_motion())) {
      track.state = FatherState::kActive;
    }
    const ImmEstimate& estimate = track.estimate;
    if (scan.coverage) {
      // A sector look: most tracks lie far from it; a bound on the search region says which
      // need no prediction.
      SearchRegion bound = region_bound(static_cast<int>(t), scan,
                                        std::max(batch_mid, estimate.time), widest, region_accel_);
      bound.radius += seed_speed(static_cast<int>(t)) * half_span;
      if (!covers_region(scan, bound.centre, bound.radius)) {
        covered_[t] = 0;
        predicted_[t] = estimate;
        continue;
      }
    }
    const Gaussian mid =
        filter_.combine(filter_.predict(estimate, std::max(batch_mid, estimate.time)));
    const Eigen::Vector3d centre = position_of(mid.mean, layout_.dims);
    // A sector batch looks at a track whose predicted position lies in the sector; one whose
    // search region only reaches into it may take a plot from it but is not aged by it.
    covered_[t] =
        covers(scan, centre) && pre_->sweep() - track.looked_by(pre_->sensor()) > std::numbers::pi
            ? 1
            : 0;
    if (covered_[t] != 0 &&
        suspends_before_gating(tracks_[t], mid, std::max(batch_mid, estimate.time))) {
      tracks_[t].state = FatherState::kSuspended;
      suspended_at_gate_.push_back(static_cast<int>(t));
    }
    // Grandsons and doomed fathers take manoeuvre pairs only; manoeuvre gates are made
    // later, for the tracks that can use them (point_tracker_branch_pairs.cpp).
    const bool non_manoeuvre = tracks_[t].branch != BranchType::kGrandson && !tracks_[t].doomed();
    // Search radius: the widest gate in the most uncertain direction, plus the motion over
    // half the batch's time span. The exact gate test is per plot, in measurement space.
    const double radius = search_radius(mid, centre, widest, scan);
    if (!covered_[t] && !covers_region(scan, centre, radius)) {
      predicted_[t] = estimate;
      continue;
    }
    pre_->index().within(centre, radius, neighbours_);
    if (neighbours_.empty()) {
      predicted_[t] = estimate;
      continue;
    }
    // The track is updated at the time of its nearest candidate plot.
    predicted_[t] = filter_.predict(estimate, std::max(nearest_time(centre), estimate.time));
    if (!non_manoeuvre) continue;
    const std::optional<ImmEstimate> narrowed = last_motion(track, predicted_[t].time);
    // branching.last_motion_false_plots: the clutter is weighed in the last motion's gate,
    // whether or not the father gates on it in this look.
    const bool weighs_clutter =
        holds_last_motion() && profile_.point.branching.last_motion_false_plots > 0.0;
    const std::optional<ImmEstimate> held =
        narrowed || !weighs_clutter ? narrowed : last_motion(track, predicted_[t].time, true);
    // In a clutter area: a plot round it in dense clutter (without last_motion_false_plots
    // every track is, from the start of the batch).
    for (std::size_t k = 0; held && dense_[t] == 0 && k < neighbours_.size(); ++k) {
      const int j = neighbours_[k];
      const Innovation in =
          innovate(held->modes.front(), layout_, pre_->plots()[j], profile_.measurement);
      if (in.ok && in_dense_clutter(in, j)) dense_[t] = 1;
    }
    if (narrowed && dense_[t] != 0) {
      // In a clutter area its non-manoeuvre association is the motion unchanged (§2.1): it
      // gates, weighs and is updated on its last motion alone. The IMM's turn modes spread the
      // likelihood over the false plots (exp. 2, seeds 1-100: the number survives 52 -> 70 %)
      // and turn the father onto them; a turn is its sons' to follow (rule 6).
      predicted_[t] = *narrowed;
    }
    for (const int j : neighbours_) {
      PlotHypothesis hypothesis = filter_.hypothesise(predicted_[t], pre_->plots()[j]);
      if (!hypothesis.usable) continue;
      // A plot inside any mode's gate (the union of the modes' gates), or a coasting father's
      // last motion's gate (branching.coast_on_last_motion), is a candidate.
      if (hypothesis.min_nis > gate_threshold_[pre_->plots()[j].model.size()]) continue;
      gated_[j] = 1;
      took_candidates_[t] = 1;
      const double likelihood = hypothesis.likelihood;
      candidates_.push_back({static_cast<int>(t), j, std::move(hypothesis), likelihood});
    }
  }
}

bool PointTracker::starts_from_coast(const PointTrack& track) const {
  return holds_last_motion() && track.branch == BranchType::kFather &&
         track.life.consecutive_misses >= 1 && track.last_detected && track.coasted;
}

void PointTracker::hold_last_motion(PointTrack& track) const {
  const std::optional<ImmEstimate> coast = last_motion(track, track.estimate.time, true);
  if (!coast) return;
  track.coasted = track.life.consecutive_misses >= 1 && track.coasted
                      ? filter_.predict(*track.coasted, track.estimate.time)
                      : track.estimate;
  track.estimate = *coast;
}

bool PointTracker::holds_last_motion() const {
  return branching() && profile_.point.branching.coast_on_last_motion;
}

bool PointTracker::in_dense_clutter(const Innovation& last_motion, int plot) const {
  // Gate volume c_d g^(d/2) sqrt|S| = gate_volume_per_peak_ / N(0; 0, S), the peak density
  // from log N(nu; 0, S) and the NIS (c_d = pi^(d/2) / Gamma(d/2 + 1)).
  const double volume = gate_volume_per_peak_[pre_->plots()[plot].model.size()] *
                        std::exp(-last_motion.log_likelihood - 0.5 * last_motion.nis);
  return pre_->density(pre_->plots()[plot], plot) * volume >=
         profile_.point.branching.last_motion_false_plots;
}

std::optional<ImmEstimate> PointTracker::last_motion(const PointTrack& track, double time,
                                                     bool missing_now) const {
  // A coast son always holds its father's last motion (branching.coast_sons).
  const bool firm_father =
      track.branch == BranchType::kFather && is_reported_as_firm(track.life.status);
  if (!holds_last_motion() || !track.last_detected || !(firm_father || track.coast_son()) ||
      (!track.coast_son() && track.life.consecutive_misses < 1 && !missing_now &&
       profile_.point.branching.non_manoeuvre_gate != config::NonManoeuvreGate::kLastMotion)) {
    return std::nullopt;
  }
  // The likeliest mode at the last detection, predicted alone: IMM mixing would blend in the
  // other modes' diverging predictions.
  ImmEstimate one = *track.last_detected;
  Eigen::Index kept = 0;
  one.probabilities.maxCoeff(&kept);
  for (Gaussian& m : one.modes) m = one.modes[static_cast<std::size_t>(kept)];
  one.probabilities.setZero();
  one.probabilities[kept] = 1.0;
  ImmEstimate predicted = (hold_ ? *hold_ : filter_).predict(one, std::max(time, one.time));
  for (Gaussian& m : predicted.modes) m = predicted.modes[static_cast<std::size_t>(kept)];
  return predicted;
}

double PointTracker::search_radius(const Gaussian& g, const Eigen::Vector3d& centre,
                                   double threshold, const PlotScan& scan) const {
  const double track_sigma = position_spread(g, layout_.dims);
  const double plot_sigma = plot_spread_at(centre, scan);
  return std::sqrt(threshold * (track_sigma * track_sigma + plot_sigma * plot_sigma)) +
         velocity_of(g.mean, layout_.dims).norm() * half_span_;
}

double PointTracker::nearest_time(const Eigen::Vector3d& centre) const {
  int nearest = neighbours_.front();
  double best = std::numeric_limits<double>::infinity();
  for (const int j : neighbours_) {
    const double d = (pre_->positions()[j] - centre).squaredNorm();
    if (d < best) {
      best = d;
      nearest = j;
    }
  }
  return pre_->plots()[nearest].time;
}

}  // namespace skytrack
