// The point tracker's initiation: which plots the tracks leave free, plot clouds, the chains
// of the initiator started as tentative tracks (under the tentative capacity), and a new
// track's estimate and life.
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

ImmEstimate start_estimate(PointLook& look, const Initiation& initiation, TrackLife& life) {
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
  for (std::size_t k = 2; k < initiation.plots.size(); ++k) {
    const PlotMeasurement& plot = initiation.plots[k];
    filter.predict(estimate, std::max(plot.time, estimate.time), predicted);
    look.start_shapes.clear();
    const PlotHypothesis h = filter.hypothesise(predicted, plot, look.start_shapes);
    if (!h.usable) continue;
    const bool in_look = k + 1 == initiation.plots.size() && initiation.last >= 0 &&
                         initiation.last < static_cast<int>(look.initiation_plots.size());
    const double density = look.pre.density(
        plot, in_look ? look.initiation_plots[static_cast<std::size_t>(initiation.last)] : -1);
    update_existence(life, h.likelihood / density, profile.association.detection_probability,
                     profile.association.gate_probability, profile.point.track_life);
    filter.update(predicted, std::span(&h, 1), std::span(&one, 1), 0.0,
                  profile.association.detection_probability, profile.association.gate_probability,
                  density, estimate);
    look.count(estimate);
  }
  return estimate;
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
    ++tentative;
    PointTrack track;
    track.id = store_.provisional();
    track.life = initiated_life(static_cast<int>(initiation.plots.size()), initiation.scans);
    track.life.existence = profile_.point.track_life.initial_existence;
    track.estimate = start_estimate(look, initiation, track.life);
    track.quality = 1.0;
    std::string detail = "from plots";
    for (const PlotMeasurement& p : initiation.plots) {
      detail.append(" ").append(std::to_string(p.plot_id));
    }
    add_event(events_, TrackEventType::kInitiated, track.id, detail);
    const PlotMeasurement& last = initiation.plots.back();
    add_association(frame, track.id, last.plot_id, last.scan, 1.0);
    const int t = store_.add(std::move(track));
    hooks().father_started(t, initiation);
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
