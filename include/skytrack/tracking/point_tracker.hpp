#pragma once
// The point tracker: IMM-JPDA (paper 003 §3) with logic-based initiation and track life,
// after optional kernel-density clutter rejection (paper 000 §3.1). One call per plot batch.
//
// Per batch: each track's search region comes from its IMM prediction at the middle of the
// batch; candidate plots from a k-d tree are tested in an ellipsoidal gate at the track's
// own update time (the time of its nearest candidate plot, so a rotating antenna's plots are
// used at the time they were measured); tracks sharing plots form clusters whose JPDA
// marginals (exact, or k-best above a size) weight each track's IMM-PDA update. Plots in no
// gate feed the initiator. Reported states are predicted to the batch time.
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "skytrack/association/cluster_builder.hpp"
#include "skytrack/association/gnn_associator.hpp"
#include "skytrack/association/jpda_solver.hpp"
#include "skytrack/association/plot_index.hpp"
#include "skytrack/clutter/clutter_rejector.hpp"
#include "skytrack/config/profile.hpp"
#include "skytrack/core/expected.hpp"
#include "skytrack/core/plot.hpp"
#include "skytrack/core/track_report.hpp"
#include "skytrack/filter/imm_filter.hpp"
#include "skytrack/measurement/plot_measurement.hpp"
#include "skytrack/tracking/initiator.hpp"
#include "skytrack/tracking/track_life.hpp"

namespace skytrack {

/// Counters and timings of one batch (logged by the daemon, summed by the tools).
struct ScanReport {
  int plots = 0;
  int plots_invalid = 0;           // could not be turned into a measurement
  int plots_rejected_clutter = 0;  // removed by clutter rejection
  int tentative = 0, confirmed = 0, coasting = 0;
  int initiated = 0, deleted = 0;
  int clusters = 0, largest_cluster = 0, approximated_clusters = 0;
  int numeric_failures = 0;
  // Stage timings: gating (predictions), association with the update, track management.
  std::chrono::microseconds predict{}, associate{}, manage{};
};

struct PointTrack {
  std::int64_t id = 0;
  TrackLife life;
  ImmEstimate estimate;  // posterior at estimate.time
  double quality = 0.0;  // running mean of the detection probability, in [0, 1]
};

class PointTracker {
 public:
  /// Checks the profile's models and matrices; fails with a message naming what is wrong.
  static Expected<PointTracker> create(const config::TrackingProfile& profile, int dims);

  /// Processes one batch; fills `frame` (tracks at scan.time, associations, events).
  void process(const PlotScan& scan, TrackFrame& frame, ScanReport& report);

  const std::vector<PointTrack>& tracks() const { return tracks_; }
  int dims() const { return layout_.dims; }

 private:
  PointTracker(const config::TrackingProfile& profile, StateLayout layout, ImmFilter filter);

  struct Candidate {  // a gated track-plot pair
    int track = 0;
    int plot = 0;
    PlotHypothesis hypothesis;
  };

  void make_measurements(const PlotScan& scan, ScanReport& report);
  double plot_spread_at(const Eigen::Vector3d& position, const PlotScan& scan) const;
  /// True when the batch looked at `position` (always, unless it covers only a sector).
  bool covers(const PlotScan& scan, const Eigen::Vector3d& position) const;
  /// True when a search region (centre, radius) reaches into the batch's coverage.
  bool covers_region(const PlotScan& scan, const Eigen::Vector3d& centre, double radius) const;
  void gate(const PlotScan& scan, double batch_mid, double half_span);
  void reject_clutter(ScanReport& report, TrackFrame& frame);
  void associate_and_update(ScanReport& report, TrackFrame& frame);
  void update_track(int t, std::span<const int> candidates, std::span<const double> beta_plots,
                    double beta_miss, TrackFrame& frame);
  void initiate(const PlotScan& scan, ScanReport& report, TrackFrame& frame);
  void report_tracks(double time, ScanReport& report, TrackFrame& frame);
  /// Clutter density for plot `index` of this batch (-1: a plot of an earlier batch).
  double clutter_density(const PlotMeasurement& plot, int index) const;
  void estimate_clutter_density();
  /// The start of a new track's estimate; the chain's plots after the first two also update
  /// its existence.
  ImmEstimate start_estimate(const Initiation& initiation, TrackLife& life) const;

  config::TrackingProfile profile_;
  StateLayout layout_;
  ImmFilter filter_;
  Initiator initiator_;
  clutter::ClutterRejector clutter_;
  ClusterBuilder clusters_;
  JpdaSolver jpda_;
  GnnAssociator gnn_;
  std::vector<PointTrack> tracks_;
  std::int64_t next_id_ = 1;
  std::uint64_t batches_ = 0;
  double gate_threshold_[kMaxMeasurementDim + 1] = {};  // chi-square quantile per dims

  // Per-batch workspaces (reused).
  std::vector<PlotMeasurement> plots_;
  std::vector<Eigen::Vector3d> positions_;
  std::vector<std::uint8_t> rejected_;
  std::vector<std::uint8_t> gated_;
  std::vector<std::uint8_t> covered_;   // per track: inside this batch's coverage
  std::vector<ImmEstimate> predicted_;  // per track, at its update time
  std::vector<Candidate> candidates_;
  std::vector<int> neighbours_;
  std::vector<GatedPair> pairs_;
  std::vector<PlotHypothesis> hypotheses_;  // one track's update
  std::vector<double> kept_beta_;
  std::vector<double> auto_density_;  // per plot, measurement space
  PlotIndex index_;
};

}  // namespace skytrack
