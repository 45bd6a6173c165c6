// The branch layer's last motion (branching.coast_on_last_motion, paper 003 §1 and §4.2): a
// firm father that missed coasts and gates on the motion it was last seen in, where its
// last motion's gate expects false plots (a clutter area); its sons follow a turn.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "point_look.hpp"
#include "point_tracker_support.hpp"
#include "skytrack/tracking/branch_layer.hpp"

namespace skytrack {

using namespace tracking_detail;

bool BranchLayer::starts_from_coast(const PointTrack& track) const {
  return holds_last_motion() && track.branch == BranchType::kFather &&
         track.life.consecutive_misses >= 1 && track.last_detected && track.coasted;
}

void BranchLayer::hold_last_motion(PointTrack& track) const {
  const std::optional<ImmEstimate> coast = last_motion(track, track.estimate.time, true);
  if (!coast) return;
  track.coasted = track.life.consecutive_misses >= 1 && track.coasted
                      ? filter().predict(*track.coasted, track.estimate.time)
                      : track.estimate;
  track.estimate = *coast;
}

double BranchLayer::last_motion_log_det(const PlotMeasurement& plot) const {
  const Gaussian& motion = narrowed_.modes.front();
  if (profile_.measurement.update != config::MeasurementUpdate::kUnscented) {
    return innovation_log_det(motion, filter().layout(), plot.model);
  }
  // The unscented S from its log-likelihood: log N(nu; 0, S) = -(m log 2 pi + log|S| + NIS) / 2.
  const Innovation in = innovate(motion, filter().layout(), plot, profile_.measurement);
  if (!in.ok) return std::numeric_limits<double>::quiet_NaN();
  const double m = static_cast<double>(plot.model.size());
  return -2.0 * in.log_likelihood - in.nis - m * std::log(2.0 * std::numbers::pi);
}

bool BranchLayer::in_dense_clutter(double log_det, int plot) const {
  // Gate volume c_d g^(d/2) sqrt|S| = gate_volume_per_peak_ / N(0; 0, S), the peak density
  // (c_d = pi^(d/2) / Gamma(d/2 + 1)).
  const int m = pre().plots()[plot].model.size();
  const double volume =
      gater().volume_per_peak(m) * std::exp(0.5 * (m * std::log(2.0 * std::numbers::pi) + log_det));
  return pre().density(pre().plots()[plot], plot) * volume >=
         profile_.point.branching.last_motion_false_plots;
}

std::optional<ImmEstimate> BranchLayer::last_motion(const PointTrack& track, double time,
                                                    bool missing_now) const {
  ImmEstimate out;
  if (!last_motion(track, time, missing_now, out)) return std::nullopt;
  return out;
}

bool BranchLayer::last_motion(const PointTrack& track, double time, bool missing_now,
                              ImmEstimate& out) const {
  // A coast son always holds its father's last motion (branching.coast_sons).
  const bool firm_father =
      track.branch == BranchType::kFather && is_reported_as_firm(track.life.status);
  if (!holds_last_motion() || !track.last_detected || !(firm_father || track.coast_son()) ||
      (!track.coast_son() && track.life.consecutive_misses < 1 && !missing_now &&
       profile_.point.branching.non_manoeuvre_gate != config::NonManoeuvreGate::kLastMotion)) {
    return false;
  }
  // The likeliest mode at the last detection, predicted alone: IMM mixing would blend in the
  // other modes' diverging predictions.
  const ImmEstimate& last = *track.last_detected;
  Eigen::Index kept = 0;
  last.probabilities.maxCoeff(&kept);
  (hold_ ? *hold_ : filter())
      .predict_certain(last, static_cast<int>(kept), std::max(time, last.time), out);
  return true;
}

}  // namespace skytrack
