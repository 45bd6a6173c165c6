// The point tracker's initiation: which plots the tracks leave free, plot clouds, the chains
// of the initiator started as tentative tracks (under the tentative capacity) or, too weak to
// outlive a missed look, held for their next plot, and a new track's estimate and life.
#include "point_life.hpp"
#include "point_look.hpp"
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

namespace {

/// A held chain's last plot, weighed as its track's first look would weigh it: an IMM-PDA
/// update over every plot of the look in the gate of `predicted`, each plot's likelihood
/// against the clutter density round it, in the existence and the support (the plot nearest
/// the chain's line, picked among many, is no evidence of a target in a crowd of plots).
/// False, with the existence updated, when that leaves the existence below `hold_below`.
bool held_chain_look(PointLook& look, const ImmEstimate& predicted, TrackLife& life,
                     double hold_below, ImmEstimate& estimate) {
  const config::TrackingProfile& profile = look.profile;
  const double pd = profile.association.detection_probability;
  const double pg = profile.association.gate_probability;
  const Gaussian combined = look.filter.combine(predicted);
  const Eigen::Vector3d centre = position_of(combined.mean, look.filter.layout().dims);
  const double radius = look.gater.search_radius(
      combined, centre, look.gater.threshold(kMaxMeasurementDim), look.scan);
  look.pre.index().within(centre, radius, look.start_neighbours);
  look.start_shapes.clear();
  look.start_hypotheses.clear();
  look.start_beta.clear();
  PlotRatios ratios;
  double density = 0.0;
  for (const int j : look.start_neighbours) {
    const PlotMeasurement& plot = look.pre.plots()[static_cast<std::size_t>(j)];
    const double threshold = look.gater.threshold(static_cast<int>(plot.model.size()));
    if (look.pre.rejected(static_cast<std::size_t>(j)) ||
        look.filter.min_nis(predicted, plot, look.start_shapes) > threshold) {
      continue;
    }
    PlotHypothesis h = look.filter.hypothesise(predicted, plot, look.start_shapes);
    if (!h.usable || h.min_nis > threshold) continue;
    const double plot_density = look.pre.density(plot, j);
    const double ratio = h.likelihood / plot_density;
    ratios.sum += ratio;
    ratios.best = std::max(ratios.best, ratio);
    density += plot_density;
    look.start_hypotheses.push_back(std::move(h));
    look.start_beta.push_back(pd * ratio);
  }
  // As the gater marks a new track: in a clutter area unless the profile tells those apart
  // (branching.last_motion_false_plots), where a tentative track is not in one.
  const bool clutter_area = !(profile.point.branching.last_motion_false_plots > 0.0);
  weigh_look(profile, life, ratios.best, ratios.sum, clutter_area);
  if (life.existence < hold_below) return false;
  look.start_valid = false;
  if (look.start_hypotheses.empty()) {
    estimate = predicted;
    return true;
  }
  // A lone track's PDA weights: each plot pd L_i / lambda_i, the miss 1 - pd pg.
  const double miss = 1.0 - pd * pg;
  const double total = miss + pd * ratios.sum;
  for (double& beta : look.start_beta) beta /= total;
  look.start_valid = valid_association(look.start_beta, miss / total);
  look.filter.update(predicted, look.start_hypotheses, look.start_beta, miss / total, pd, pg,
                     density / static_cast<double>(look.start_hypotheses.size()), estimate);
  look.count(estimate);
  return true;
}

}  // namespace

std::optional<ImmEstimate> start_estimate(PointLook& look, const Initiation& initiation,
                                          TrackLife& life, double hold_below) {
  const config::TrackingProfile& profile = look.profile;
  const ImmFilter& filter = look.filter;
  const StateLayout& layout = look.filter.layout();
  // Two-point start at the second plot, then IMM updates with any further plots.
  const PlotMeasurement& a = initiation.plots[0];
  const PlotMeasurement& b = initiation.plots[1];
  const int dims = layout.dims;
  const double dt = std::max(b.time - a.time, 1e-3);
  const Eigen::Vector3d pa = approximate_position(a), pb = approximate_position(b);
  const double sa = position_sigma(a), sb = position_sigma(b);
  Gaussian g;
  g.mean = StateVec::Zero(layout.size());
  g.covariance = StateMat::Zero(layout.size(), layout.size());
  for (int axis = 0; axis < dims; ++axis) {
    const int p = StateLayout::position(axis), v = StateLayout::velocity(axis);
    const bool unknown_height = axis == 2 && !(measures_height(a) && measures_height(b));
    g.mean[p] = pb[axis];
    g.mean[v] = unknown_height ? 0.0 : (pb[axis] - pa[axis]) / dt;
    g.covariance(p, p) = unknown_height ? kUnknownHeightSigma * kUnknownHeightSigma : sb * sb;
    g.covariance(v, v) = unknown_height ? 100.0 * 100.0 : (sa * sa + sb * sb) / (dt * dt);
    g.covariance(p, v) = g.covariance(v, p) = unknown_height ? 0.0 : sb * sb / dt;
  }
  if (layout.acceleration) {
    for (int axis = 0; axis < dims; ++axis) {
      const int i = layout.acceleration_index(axis);
      g.covariance(i, i) = kInitialAccelerationSigma * kInitialAccelerationSigma;
    }
  }
  if (layout.turn_rate) {
    double sigma = 0.05;
    for (const auto& spec : profile.motion_models) {
      if (spec.type == config::MotionModelType::kCoordinatedTurnEstimated) {
        sigma = spec.initial_turn_rate_sigma;
      }
    }
    g.covariance(layout.turn_rate_index(), layout.turn_rate_index()) = sigma * sigma;
  }
  const auto& probabilities = profile.initial_mode_probabilities;
  ImmEstimate estimate =
      filter.initial(g,
                     Eigen::Map<const Eigen::VectorXd>(
                         probabilities.data(), static_cast<Eigen::Index>(probabilities.size())),
                     b.time);
  const double one = 1.0;
  ImmEstimate& predicted = look.start_predicted;
  const std::size_t n = initiation.plots.size();
  for (std::size_t k = 2; k < n; ++k) {
    const PlotMeasurement& plot = initiation.plots[k];
    const bool last = k + 1 == n;
    const bool in_look = last && initiation.last >= 0 &&
                         initiation.last < static_cast<int>(look.initiation_plots.size());
    filter.predict(estimate, std::max(plot.time, estimate.time), predicted);
    if (initiation.held && in_look) {
      if (!held_chain_look(look, predicted, life, hold_below, estimate)) return std::nullopt;
      continue;
    }
    look.start_shapes.clear();
    const PlotHypothesis h = filter.hypothesise(predicted, plot, look.start_shapes);
    if (!h.usable) continue;
    const double density = look.pre.density(
        plot, in_look ? look.initiation_plots[static_cast<std::size_t>(initiation.last)] : -1);
    // A held chain's plots but the last were weighed in their own looks, against the clutter
    // round them then (Initiation::existence).
    if (!initiation.held) {
      update_existence(life, h.likelihood / density, profile.association.detection_probability,
                       profile.association.gate_probability, profile.point.track_life);
    }
    if (last && life.existence < hold_below) return std::nullopt;
    filter.update(predicted, std::span(&h, 1), std::span(&one, 1), 0.0,
                  profile.association.detection_probability, profile.association.gate_probability,
                  density, estimate);
    look.count(estimate);
  }
  return estimate;
}

bool PointTracker::confirmed_by_existence(const TrackLife& life) const {
  const config::TrackLifeSpec& spec = profile_.point.track_life;
  return spec.confirmation == config::ConfirmationMethod::kExistence &&
         life.existence >= spec.confirm_existence;
}

bool PointTracker::free_for_initiation(const PointLook& look, std::size_t j) const {
  if (look.pre.rejected(j) || look.used_by_branch[j]) return false;
  // In no gate, or in the gates of tracks that each explain another plot: a target of its
  // own, such as a formation member inside its neighbour's gate.
  return !gater_.gated(j) || look.held[j] == 0;
}

void PointTracker::initiate(PointLook& look) {
  const PlotScan& scan = look.scan;
  Preprocessing& pre = look.pre;
  ScanReport& report = look.report;
  TrackFrame& frame = look.frame;
  std::vector<PlotMeasurement> unused;
  std::vector<Eigen::Vector3d> unused_positions;
  look.initiation_plots.clear();
  int clouded = 0;
  for (std::size_t j = 0; j < pre.plots().size(); ++j) {
    if (!free_for_initiation(look, j)) continue;
    if (pre.in_cloud(j)) {
      ++clouded;
      continue;
    }
    unused.push_back(pre.plots()[j]);
    unused_positions.push_back(pre.positions()[j]);
    look.initiation_plots.push_back(static_cast<int>(j));
  }
  if (clouded > 0) {
    report.plots_in_clouds += clouded;
    add_event(events_, TrackEventType::kPlotCloud, 0,
              std::to_string(clouded) + " plots in clouds start no track (more than " +
                  std::to_string(kCloudPlots) + " plots within " +
                  std::to_string(static_cast<int>(kCloudSigmas)) + " position sigmas)");
  }
  const auto covered = [&](const Eigen::Vector3d& p) { return Gater::covers(scan, p); };
  hooks().before_initiation(scan, report);
  int tentative =
      static_cast<int>(std::count_if(store_.all().begin(), store_.all().end(), [](const auto& t) {
        return t.branch == BranchType::kFather && t.life.status == TrackStatus::kTentative;
      }));
  int refused = 0;
  for (const Initiation& initiation : initiator_.step(
           batches_, scan.time, pre.sensor(), pre.sweep(), unused, covered, unused_positions)) {
    if (hooks().take_chain(initiation, report, frame)) continue;
    if (tentative >= profile_.point.initiation.max_tentative) {
      ++refused;
      continue;
    }
    PointTrack track;
    track.life = initiated_life(static_cast<int>(initiation.plots.size()), initiation.scans);
    track.life.existence =
        initiation.held ? initiation.existence : profile_.point.track_life.initial_existence;
    // A track that its next look would delete unless it takes a plot is no more than its
    // chain: the chain waits for that plot, without a filter to predict and gate. Held, a
    // chain whose plot leaves it below delete_existence is dropped, as its track would be.
    std::optional<ImmEstimate> estimate =
        start_estimate(look, initiation, track.life, outlive_miss_existence_);
    if (!estimate) {
      if (!initiation.held || track.life.existence >= profile_.point.track_life.delete_existence) {
        initiator_.hold(initiation, track.life.existence);
        ++report.chains_held;
      }
      continue;
    }
    track.estimate = std::move(*estimate);
    ++tentative;
    track.id = store_.provisional();
    track.quality = 1.0;
    std::string detail = "from plots";
    for (const PlotMeasurement& p : initiation.plots) {
      detail.append(" ").append(std::to_string(p.plot_id));
    }
    add_event(events_, TrackEventType::kInitiated, track.id, detail);
    const PlotMeasurement& last = initiation.plots.back();
    add_association(frame, track.id, last.plot_id, last.scan, 1.0);
    // A held chain's plot came in the look that would have been its track's first: as that
    // track, it is confirmed in this look if its existence says so.
    const bool confirmed = initiation.held && confirmed_by_existence(track.life);
    if (confirmed) track.life.status = TrackStatus::kConfirmed;
    const std::int64_t id = track.id;
    const int t = store_.add(std::move(track));
    hooks().father_started(t, initiation);
    if (initiation.held) hooks().updated(store_[static_cast<std::size_t>(t)], look.start_valid);
    if (confirmed) {
      add_event(events_, TrackEventType::kConfirmed, id, "");
      hooks().confirmed(t);
    }
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
