#pragma once
// The point tracker's IMM-PDA updater (paper 003 eq. 3-7 with the JPDA weights of eq. 8-10):
// each mode's PDA over the miss and the track's weighted plots, moment-matched; then the
// track's life step (existence, support, confirmation, deletion) from the same look.
#include <cstdint>
#include <span>
#include <vector>

#include "skytrack/filter/imm_filter.hpp"
#include "skytrack/tracking/branch_hooks.hpp"
#include "skytrack/tracking/gater.hpp"

namespace skytrack {

struct PointLook;

/// Likelihood over clutter density, L_i / lambda_i, of a track's gated plots.
struct PlotRatios {
  double sum = 0.0;   // over the plots: the existence update's likelihood ratio
  double best = 0.0;  // the likeliest plot's: its support (TrackLife::support)
};

class ImmPdaUpdater {
 public:
  /// IMM-PDA update of track t from its prediction with its weighted candidates from
  /// `pool` (no candidate: predicted to the frame's time); reports the associations under
  /// `number`.
  PlotRatios update(PointLook& look, int t, std::vector<Candidate>& pool,
                    std::span<const int> candidates, std::span<const double> beta_plots,
                    double beta_miss, std::int64_t number);

  /// A track's update and life step in the look (unless the look neither covers it nor gave
  /// it a candidate). `hooks`: the branch layer's for a father (branch_hooks.hpp).
  /// reports_deletion false: the caller turns a deletion into a suspension.
  void update_track(PointLook& look, int t, std::span<const int> candidates,
                    std::span<const double> beta_plots, double beta_miss, BranchHooks& hooks,
                    bool reports_deletion = true);

 private:
  std::vector<PlotHypothesis> hypotheses_;  // one track's update
  std::vector<double> kept_beta_;
};

}  // namespace skytrack
