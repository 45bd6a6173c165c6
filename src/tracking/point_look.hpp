#pragma once
// One look of the point tracker as its components see it: the tracker's parts and the look's
// plots, outputs and per-plot marks (built by PointTracker::process; not installed).
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "skytrack/config/profile.hpp"
#include "skytrack/core/look.hpp"
#include "skytrack/core/scan_report.hpp"
#include "skytrack/core/track_report.hpp"
#include "skytrack/filter/imm_filter.hpp"
#include "skytrack/preprocess/preprocessing.hpp"
#include "skytrack/tracking/cluster_associator.hpp"
#include "skytrack/tracking/gater.hpp"
#include "skytrack/tracking/imm_pda_updater.hpp"
#include "skytrack/tracking/initiator.hpp"
#include "skytrack/tracking/track_store.hpp"

namespace skytrack {

struct PointLook {
  const config::TrackingProfile& profile;
  const ImmFilter& filter;
  TrackStore& store;
  Gater& gater;
  ClusterAssociator& associator;
  ImmPdaUpdater& updater;
  const PlotScan& scan;
  Preprocessing& pre;
  TrackFrame& frame;
  ScanReport& report;
  std::uint64_t batch = 0;  // looks processed, this one included
  // This look's events, held until it has decided them all (process emits them into the
  // frame): a later decision may supersede one, which then never appears.
  std::vector<TrackEvent>& events;
  // Per plot: taken by a confirmed branch pair (branching); held by a non-manoeuvre gate,
  // i.e. the most likely plot of a track that explains it, or any plot of a track that
  // explains none (initiation.gated_seed_beta).
  std::vector<std::uint8_t>& used_by_branch;
  std::vector<std::uint8_t>& held;
  // The index in pre.plots() of each plot given to the initiator in this look.
  std::vector<int>& initiation_plots;
  // start_estimate's prediction, innovation shapes, and a held chain's plots round its
  // prediction with their hypotheses and weights, whose storage every start reuses.
  ImmEstimate& start_predicted;
  HypothesisShapes& start_shapes;
  std::vector<int>& start_neighbours;
  std::vector<PlotHypothesis>& start_hypotheses;
  std::vector<double>& start_beta;
  bool start_valid = false;  // the held chain's look had a valid association (paper 003 §2.2)
  // Updates with failed modes and clusters whose association failed.
  int numeric_failures = 0;

  ClusterAssociator::Look association() {
    return {pre, static_cast<int>(store.size()), report, events, numeric_failures};
  }
  /// An update, its failed modes (which kept their prediction) counted for the report.
  ImmEstimate counted(ImmEstimate update) {
    count(update);
    return update;
  }
  void count(const ImmEstimate& update) { numeric_failures += update.numeric_failure() ? 1 : 0; }
};

/// The start of a new track's estimate (two-point, then IMM updates with the chain's further
/// plots, which also update its existence: the chain's last plot, from this look, is weighed
/// against the clutter density estimated round it, as a track's plots are; a held chain's last
/// plot as its track's first look would weigh it, over every plot in its gate). None, with
/// the existence updated but no estimate made, when the existence ends below `hold_below`.
std::optional<ImmEstimate> start_estimate(PointLook& look, const Initiation& initiation,
                                          TrackLife& life, double hold_below = 0.0);

/// Marks in look.held the plots a track's non-manoeuvre association holds back from
/// initiation (initiation.gated_seed_beta).
void note_explained(PointLook& look, const std::vector<Candidate>& pool, std::span<const int> mine,
                    std::span<const double> beta);

}  // namespace skytrack
