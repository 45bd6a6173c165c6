// The point tracker's plain association: clutter rejection on the gates, then JPDA over the
// clusters of candidates and each track's IMM-PDA update (the branch layer replaces the
// latter with its pair kinds, whose fathers' kind is the same association).
#include <algorithm>
#include <string>

#include "point_look.hpp"
#include "point_tracker_support.hpp"
#include "skytrack/tracking/point_tracker.hpp"

namespace skytrack {

using namespace tracking_detail;

void PointTracker::reject_clutter(PointLook& look) {
  Preprocessing& pre = look.pre;
  if (!pre.rejects_clutter() || pre.plots().empty()) return;
  // Plots in the gate of a confirmed track are kept whatever their density.
  std::vector<std::uint8_t> protect(pre.plots().size(), 0);
  for (const Candidate& c : gater_.candidates()) {
    const TrackStatus status = store_[static_cast<std::size_t>(c.track)].life.status;
    if (status == TrackStatus::kConfirmed || status == TrackStatus::kCoasting) {
      protect[c.plot] = 1;
    }
  }
  const clutter::ClutterRejectionResult& result = pre.reject_clutter(protect);
  // The manoeuvre gates (branch layer) are made after this, from the plots kept.
  std::erase_if(gater_.candidates(), [&](const Candidate& c) { return pre.rejected(c.plot); });
  look.report.plots_rejected_clutter = result.rejected;
  add_event(
      events_, TrackEventType::kClutterRejected, 0,
      std::to_string(result.rejected) + " of " + std::to_string(pre.plots().size()) + " plots");
}

void PointTracker::associate_and_update(PointLook& look) {
  std::vector<Candidate>& candidates = gater_.candidates();
  associator_.estimate_clutter_density(look.pre, store_.all(), candidates);
  kind_list_.resize(candidates.size());
  for (std::size_t k = 0; k < candidates.size(); ++k) kind_list_[k] = static_cast<int>(k);
  associator_.solve(
      look.association(), candidates, kind_list_, profile_.association.gate_probability,
      [&](int t, std::span<const int> mine, std::span<const double> beta, double miss) {
        note_explained(look, candidates, mine, beta);
        updater_.update_track(look, t, mine, beta, miss, hooks());
      });
}

void note_explained(PointLook& look, const std::vector<Candidate>& pool, std::span<const int> mine,
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
  if (best_beta > look.profile.point.initiation.gated_seed_beta) {
    look.held[best] = 1;
    return;
  }
  for (const int k : mine) look.held[pool[k].plot] = 1;
}

}  // namespace skytrack
