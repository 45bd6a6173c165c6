#pragma once
// The point tracker, the estimator of `mode: point` (estimator.hpp): IMM-JPDA (paper 003 §3)
// with logic-based initiation and track life. One call per look, whose plots the preprocessing
// stage has prepared; it asks that stage for clutter rejection once its gates say which plots
// its confirmed tracks protect, and for the clutter density once they say which are false.
//
// It composes (docs/point-tracker.md, "Components"):
//   TrackStore         the tracks and their numbering (track_store.hpp)
//   Gater              each track's gate round its prediction, the look's candidates
//   ClusterAssociator  clusters of tracks sharing plots, their JPDA (or GNN) weights
//   ImmPdaUpdater      each track's IMM-PDA update and life step (track_life.hpp)
//   Initiator          plot chains from the plots no track explains (initiator.hpp)
//   TrackReporter      the reported tracks at the look's time
//   BranchLayer        with branching on (paper 003 §1-§2.3): sons and grandsons, called at
//                      a few hooks of a look (branch_hooks.hpp, branch_layer.hpp); with
//                      branching off the hooks' base class answers as plain IMM-JPDA.
// Files: point_tracker.cpp (creation, a look's steps), _association (clutter rejection, the
// plain association), _initiation.
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "skytrack/config/profile.hpp"
#include "skytrack/core/expected.hpp"
#include "skytrack/core/look.hpp"
#include "skytrack/core/plot.hpp"
#include "skytrack/core/scan_report.hpp"
#include "skytrack/core/track_report.hpp"
#include "skytrack/filter/imm_filter.hpp"
#include "skytrack/tracking/branch_layer.hpp"
#include "skytrack/tracking/branch_tree.hpp"
#include "skytrack/tracking/cluster_associator.hpp"
#include "skytrack/tracking/estimator.hpp"
#include "skytrack/tracking/gater.hpp"
#include "skytrack/tracking/imm_pda_updater.hpp"
#include "skytrack/tracking/initiator.hpp"
#include "skytrack/tracking/point_track.hpp"
#include "skytrack/tracking/track_life.hpp"
#include "skytrack/tracking/track_reporter.hpp"
#include "skytrack/tracking/track_store.hpp"

namespace skytrack {

struct PointLook;

class PointTracker final : public Estimator {
 public:
  /// Checks the profile's models and matrices; fails with a message naming what is wrong.
  static Expected<PointTracker> create(const config::TrackingProfile& profile, int dims);

  /// Processes one look (estimator.hpp): its plots are `pre`'s.
  void process(const PlotScan& scan, Preprocessing& pre, TrackFrame& frame,
               ScanReport& report) override;

  void report_only(const PlotScan& scan, TrackFrame& frame, ScanReport& report) override;

  /// The search region of every track (its widest gate round its prediction to `time`, for
  /// plots with the sigmas of batch `header`) and of every candidate chain of the initiator:
  /// where this tracker may take a plot.
  void search_regions(const PlotScan& header, double time,
                      std::vector<SearchRegion>& out) const override;

  /// Every track: the fathers (reported) and, with branching, their sons and grandsons.
  const std::vector<PointTrack>& tracks() const { return store_.all(); }
  const BranchTree& branch_tree() const;
  int dims() const { return filter_.layout().dims; }

 private:
  PointTracker(const config::TrackingProfile& profile, ImmFilter filter,
               std::optional<BranchLayer> branches);

  /// Plain IMM-JPDA: JPDA over the clusters, each track's IMM-PDA update and life step.
  void associate_and_update(PointLook& look);
  void reject_clutter(PointLook& look);
  /// True when plot j may feed the initiator: in no gate, or in gates but unexplained.
  bool free_for_initiation(const PointLook& look, std::size_t j) const;
  void initiate(PointLook& look);
  bool confirmed_by_existence(const TrackLife& life) const;
  /// The branch layer, or with branching off the hooks that answer as the plain tracker.
  BranchHooks& hooks() { return branches_ ? static_cast<BranchHooks&>(*branches_) : plain_; }

  config::TrackingProfile profile_;
  ImmFilter filter_;
  TrackStore store_;
  Gater gater_;
  ClusterAssociator associator_;
  ImmPdaUpdater updater_;
  Initiator initiator_;
  std::optional<BranchLayer> branches_;  // branching on
  BranchHooks plain_;                    // branching off: the plain tracker's answers
  std::uint64_t batches_ = 0;
  // A completed chain whose existence is below this waits for its next plot as a chain
  // (existence_to_outlive_a_miss): as a track, a look without that plot would delete it.
  double outlive_miss_existence_ = 0.0;

  // Per-look workspaces (reused).
  std::vector<TrackEvent> events_;                   // held until the look has decided them all
  std::vector<std::uint8_t> used_by_branch_, held_;  // per plot (point_look.hpp)
  std::vector<int> initiation_plots_;                // point_look.hpp
  ImmEstimate start_predicted_;                      // start_estimate's (point_look.hpp)
  HypothesisShapes start_shapes_;
  std::vector<int> start_neighbours_;
  std::vector<PlotHypothesis> start_hypotheses_;
  std::vector<double> start_beta_;
  std::vector<std::pair<std::int64_t, std::int64_t>> renamed_;
  std::vector<int> kind_list_;
};

}  // namespace skytrack
