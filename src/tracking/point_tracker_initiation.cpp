// The point tracker's initiation: which plots the tracks leave free, plot clouds, the chains
// of the initiator started as tentative tracks (under the tentative capacity), and a new
// track's estimate and life.
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

ImmEstimate PointTracker::start_estimate(const Initiation& initiation, TrackLife& life) const {
  // Two-point start at the second plot, then IMM updates with any further plots.
  const PlotMeasurement& a = initiation.plots[0];
  const PlotMeasurement& b = initiation.plots[1];
  const int dims = layout_.dims;
  const double dt = std::max(b.time - a.time, 1e-3);
  const Eigen::Vector3d pa = approximate_position(a), pb = approximate_position(b);
  const double sa = position_sigma(a), sb = position_sigma(b);
  Gaussian g;
  g.mean = StateVec::Zero(layout_.size());
  g.covariance = StateMat::Zero(layout_.size(), layout_.size());
  for (int axis = 0; axis < dims; ++axis) {
    const int p = StateLayout::position(axis), v = StateLayout::velocity(axis);
    const bool unknown_height = axis == 2 && !(measures_height(a) && measures_height(b));
    g.mean[p] = pb[axis];
    g.mean[v] = unknown_height ? 0.0 : (pb[axis] - pa[axis]) / dt;
    g.covariance(p, p) = unknown_height ? kUnknownHeightSigma * kUnknownHeightSigma : sb * sb;
    g.covariance(v, v) = unknown_height ? 100.0 * 100.0 : (sa * sa + sb * sb) / (dt * dt);
    g.covariance(p, v) = g.covariance(v, p) = unknown_height ? 0.0 : sb * sb / dt;
  }
  if (layout_.acceleration) {
    for (int axis = 0; axis < dims; ++axis) {
      const int i = layout_.acceleration_index(axis);
      g.covariance(i, i) = kInitialAccelerationSigma * kInitialAccelerationSigma;
    }
  }
  if (layout_.turn_rate) {
    double sigma = 0.05;
    for (const auto& spec : profile_.motion_models) {
      if (spec.type == config::MotionModelType::kCoordinatedTurnEstimated) {
        sigma = spec.initial_turn_rate_sigma;
      }
    }
    g.covariance(layout_.turn_rate_index(), layout_.turn_rate_index()) = sigma * sigma;
  }
  const auto& probabilities = profile_.initial_mode_probabilities;
  ImmEstimate estimate =
      filter_.initial(g,
                      Eigen::Map<const Eigen::VectorXd>(
                          probabilities.data(), static_cast<Eigen::Index>(probabilities.size())),
                      b.time);
  const double one = 1.0;
  for (std::size_t k = 2; k < initiation.plots.size(); ++k) {
    const PlotMeasurement& plot = initiation.plots[k];
    const ImmEstimate predicted = filter_.predict(estimate, std::max(plot.time, estimate.time));
    const PlotHypothesis h = filter_.hypothesise(predicted, plot);
    if (!h.usable) continue;
    const double density = pre_->density(plot, -1);
    update_existence(life, h.likelihood / density, profile_.association.detection_probability,
                     profile_.association.gate_probability, profile_.point.track_life);
    estimate = counted(filter_.update(predicted, std::span(&h, 1), std::span(&one, 1), 0.0,
                                      profile_.association.detection_probability,
                                      profile_.association.gate_probability, density));
  }
  return estimate;
}

config::DetectabilitySpec PointTracker::detectability_at(int t) const {
  // Masking is a clutter area's (branching.last_motion_false_plots): elsewhere a miss is
  // independent of the last, as P_D says.
  config::DetectabilitySpec chain = profile_.point.branching.detectability;
  if (static_cast<std::size_t>(t) >= dense_.size() || dense_[t] == 0) chain.hide = 0.0;
  return chain;
}

void PointTracker::add_support(TrackLife& life, const PlotRatios& ratios, int where) const {
  const double pd = support_detection_probability(life, profile_.association.detection_probability,
                                                  detectability_at(where));
  life.support += scan_support(ratios.best, pd, profile_.association.gate_probability);
  update_detectability(life, ratios.sum, where);
}

void PointTracker::update_detectability(TrackLife& life, double likelihood_ratio, int where) const {
  skytrack::update_detectability(life, likelihood_ratio, profile_.association.detection_probability,
                                 profile_.association.gate_probability, detectability_at(where));
}

void PointTracker::note_explained(const std::vector<Candidate>& pool, std::span<const int> mine,
                                  std::span<const double> beta) {
  // A track whose most likely plot has more than gated_seed_beta of its weight explains that
  // plot alone: the others in its gate are more than it can explain (one plot per target)
  // and stay free for initiation. A track without such a plot (its own plot missed, or its
  // target manoeuvring away from its prediction) may be explained by any of them: it holds
  // its whole gate, so a chain cannot start on its target's plots while it lags.
  int best = -1;
  double best_beta = -1.0;
  for (std::size_t k = 0; k < mine.size(); ++k) {
    if (beta[k] > best_beta) {
      best_beta = beta[k];
      best = pool[mine[k]].plot;
    }
  }
  if (best < 0) return;
  if (best_beta > profile_.point.initiation.gated_seed_beta) {
    held_[best] = 1;
    return;
  }
  for (const int k : mine) held_[pool[k].plot] = 1;
}

bool PointTracker::free_for_initiation(std::size_t j) const {
  if (pre_->rejected(j) || used_by_branch_[j]) return false;
  // In no gate, or in the gates of tracks that each explain another plot: a target of its
  // own, such as a formation member inside its neighbour's gate.
  return gated_[j] == 0 || held_[j] == 0;
}

void PointTracker::initiate(const PlotScan& scan, ScanReport& report, TrackFrame& frame) {
  std::vector<PlotMeasurement> unused;
  int clouded = 0;
  for (std::size_t j = 0; j < pre_->plots().size(); ++j) {
    if (!free_for_initiation(j)) continue;
    if (pre_->in_cloud(j)) {
      ++clouded;
      continue;
    }
    unused.push_back(pre_->plots()[j]);
  }
  if (clouded > 0) {
    report.plots_in_clouds += clouded;
    add_event(events_, TrackEventType::kPlotCloud, 0,
              std::to_string(clouded) + " plots in clouds start no track (more than " +
                  std::to_string(kCloudPlots) + " plots within " +
                  std::to_string(static_cast<int>(kCloudSigmas)) + " position sigmas)");
  }
  const auto covered = [&](const Eigen::Vector3d& p) { return covers(scan, p); };
  if (branching()) {
    find_lost_fathers(scan);
    continue_lost_fathers(report);
  }
  int tentative = static_cast<int>(std::count_if(tracks_.begin(), tracks_.end(), [](const auto& t) {
    return t.branch == BranchType::kFather && t.life.status == TrackStatus::kTentative;
  }));
  int refused = 0;
  for (const Initiation& initiation :
       initiator_.step(batches_, scan.time, pre_->sensor(), pre_->sweep(), unused, covered)) {
    if (branching()) {
      const int father = lost_father_of(initiation.plots.back());
      if (father >= 0 && start_chain_branch(father, initiation, report, frame)) continue;
    }
    if (tentative >= profile_.point.initiation.max_tentative) {
      ++refused;
      continue;
    }
    ++tentative;
    PointTrack track;
    track.id = next_provisional_++;
    track.life = initiated_life(static_cast<int>(initiation.plots.size()), initiation.scans);
    track.life.existence = profile_.point.track_life.initial_existence;
    track.estimate = start_estimate(initiation, track.life);
    track.quality = 1.0;
    if (branching()) {
      track.last_plot = initiation.plots.back();
      track.last_plot_batch = batches_;
      tree_.add_father(track.id);
      slots_[track.id] = static_cast<int>(tracks_.size());
    }
    std::string detail = "from plots";
    for (const PlotMeasurement& p : initiation.plots) {
      detail.append(" ").append(std::to_string(p.plot_id));
    }
    add_event(events_, TrackEventType::kInitiated, track.id, detail);
    const PlotMeasurement& last = initiation.plots.back();
    add_association(frame, track.id, last.plot_id, last.scan, 1.0);
    tracks_.push_back(std::move(track));
    ++report.initiated;
  }
  if (refused > 0) {
    report.initiations_refused += refused;
    add_event(events_, TrackEventType::kOverload, 0,
              std::to_string(refused) + " chains start no track: " +
                  std::to_string(profile_.point.initiation.max_tentative) +
                  " tentative tracks held (initiation.max_tentative)");
  }
}

}  // namespace skytrack
