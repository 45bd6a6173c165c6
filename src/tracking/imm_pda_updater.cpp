#include "skytrack/tracking/imm_pda_updater.hpp"

#include <algorithm>

#include "point_life.hpp"
#include "point_look.hpp"
#include "point_tracker_support.hpp"

namespace skytrack {

using namespace tracking_detail;

PlotRatios ImmPdaUpdater::update(PointLook& look, int t, std::vector<Candidate>& pool,
                                 std::span<const int> candidates,
                                 std::span<const double> beta_plots, double beta_miss,
                                 std::int64_t number) {
  PointTrack& track = look.store[static_cast<std::size_t>(t)];
  const Preprocessing& pre = look.pre;
  const double pd = look.profile.association.detection_probability;
  if (candidates.empty()) {
    track.estimate =
        look.gater.coast(track, static_cast<std::size_t>(t), look.filter, look.frame.time);
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
    const double plot_density = pre.density(pre.plots()[c.plot], c.plot);
    density += plot_density / static_cast<double>(candidates.size());
    if (c.hypothesis.usable) {
      const double ratio = c.hypothesis.likelihood / plot_density;
      ratios.sum += ratio;
      ratios.best = std::max(ratios.best, ratio);
    }
    if (beta_plots[k] >= kAssociationReportThreshold) {
      add_association(look.frame, number, pre.plots()[c.plot].plot_id, pre.plots()[c.plot].scan,
                      beta_plots[k]);
    }
    if (beta_plots[k] < kNegligibleBeta) continue;
    hypotheses_.push_back(std::move(c.hypothesis));
    kept_beta_.push_back(beta_plots[k]);
    kept += beta_plots[k];
  }
  for (double& b : kept_beta_) b /= kept;
  look.filter.update(look.gater.predicted()[static_cast<std::size_t>(t)], hypotheses_, kept_beta_,
                     beta_miss / kept, pd, look.profile.association.gate_probability, density,
                     track.estimate);
  look.count(track.estimate);
  return ratios;
}

void ImmPdaUpdater::update_track(PointLook& look, int t, std::span<const int> candidates,
                                 std::span<const double> beta_plots, double beta_miss,
                                 BranchHooks& hooks, bool reports_deletion) {
  PointTrack& track = look.store[static_cast<std::size_t>(t)];
  const auto slot = static_cast<std::size_t>(t);
  if (!look.gater.covered(slot) && candidates.empty()) return;  // neither updated nor aged
  const config::TrackingProfile& profile = look.profile;
  const bool valid = valid_association(beta_plots, beta_miss);
  const PlotRatios ratios =
      update(look, t, look.gater.candidates(), candidates, beta_plots, beta_miss, track.id);
  if (!candidates.empty()) hooks.updated(track, valid);
  const double detection = 1.0 - beta_miss;
  track.quality = 0.8 * track.quality + 0.2 * detection;
  // P_D on its detectability chain, as in its support: a target masked in a clutter area
  // is not evidence that there is none (IPDA with a detectability chain).
  weigh_look(profile, track.life, ratios.best, ratios.sum, look.gater.in_clutter_area(slot));
  bool detected = detection > 0.5;
  detected = hooks.detected(t, valid, detected);
  const LifeChange change = advance_life(
      track.life, detected, mode_spread(track.estimate, kLifeSpreadDims), profile.point.track_life);
  if (change.confirmed) {
    add_event(look.events, TrackEventType::kConfirmed, track.id, "");
    hooks.confirmed(t);
  }
  if (change.started_coasting) add_event(look.events, TrackEventType::kCoasting, track.id, "");
  if (change.deleted && reports_deletion) {
    add_event(look.events, TrackEventType::kDeleted, track.id, "");
  }
}

}  // namespace skytrack
