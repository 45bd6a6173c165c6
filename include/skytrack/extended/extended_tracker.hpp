#pragma once
// Several extended objects in clutter (issue 27, deliverable 2): per scan, the plots are
// partitioned (the caller's partitions, e.g. the preprocessing's mean shift, or the
// distance partitioning), partitions are gated by each track's extent (floored at a new
// track's) and given to the gating track; a partition several confirmed tracks gate (two
// crossing objects) is split plot by plot, the split refined by moving each track's centre
// to the plots it holds (hard-assignment EM; with two tracks and a Bayesian estimator the split
// exchanged is kept where likelier under the predictions), unless the objects overlap, one track's
// extent has no shape and their velocities part them by the next scan: then both coast (not a
// miss); a tentative track never shares a confirmed one's partition, and tentative tracks sharing
// one leave it whole to the likeliest (one object's pieces); a partition no track gates but whose
// plots lie in the plot gate of a confirmed track that found none of its own goes to that track
// (the object seen off its prediction), the others start tentative tracks; a track keeps a
// second partition only within its object's reach of its best one (a long hull's piece; with
// SMF-EOT, whose inner extent tells no reach, any unshared one), and yields it to a track whose
// missed-scan branch explains it; a plot alone in its
// partition joins a track's update only beside, and within the object's reach of, a partition of
// the track's own; a confirmed track that finds no plots of its own in the scan after one it took
// plots in is weighed against the track it would be had that scan been a miss, and takes that
// branch when its plots are likelier the object's over the two scans; each track is updated by the
// profile's estimator; tentative tracks are confirmed when they keep taking partitions, and tracks
// that stop taking them are deleted. Deterministic: no random numbers, ties broken by track number
// and plot index.
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "skytrack/extended/distance_partitioner.hpp"
#include "skytrack/extended/extended_estimator.hpp"
#include "skytrack/extended/extended_existence.hpp"
#include "skytrack/extended/noise_levels.hpp"
#include "skytrack/measurement/plot_measurement.hpp"

namespace skytrack::extended {

/// Covariance of a point uniform over the ellipse E(0, X): X / 4.
inline constexpr double kUniformScatter = 0.25;

enum class ExtendedTrackStatus : std::uint8_t { kTentative, kConfirmed };

/// A track as it would stand had its last scan been a miss, kept for one scan: a scan's
/// plots taken are weighed again once the next shows where the object is
/// (ExtendedTracker::reconsider_missed_scans, extended_missed_scan.cpp).
struct MissedScan {
  bool kept = false;      // the track took plots in its last scan
  ExtendedObject object;  // its prediction to that scan, coasted as a miss would
  NoiseLevels levels;
  double existence_log_odds = 0.0;  // after that scan as a miss
  double manoeuvre_evidence = 0.0;
  double log_ratio = 0.0;  // those plots: the object seen against clutter (the clutter test)
  int misses = 0;
};

struct ExtendedTrack {
  std::uint64_t id = 0;  // stable track number, from 1, never reused
  ExtendedTrackStatus status = ExtendedTrackStatus::kTentative;
  ExtendedObject object;  // centre state, covariance, extent X
  int hits = 0;           // scans it took plots in
  int misses = 0;         // consecutive scans without plots
  int plots = 0;          // plots it took in the last scan
  /// In the last scan it shared a partition with a crossing neighbour it could not be told
  /// from, and coasted on its prediction: not a miss.
  bool unresolved = false;
  double birth_variance = 0.0;  // [m^2] its first centre's variance per axis
  /// ln(r / (1 - r)), r the probability its object exists (extended_existence.hpp).
  double existence_log_odds = 0.0;
  double manoeuvre_evidence = 0.0;  // CUSUM of log f_manoeuvre - log f_quiet over its scans
  NoiseLevels levels;  // when the tracker mixes the levels (mixes_levels): object is their mixture
  MissedScan missed_scan;

  double existence() const;                                        // r
  Eigen::Vector2d position() const { return object.position(); }   // [m] centre
  Eigen::Vector2d velocity() const { return object.velocity(); }   // [m/s]
  const Eigen::Matrix2d& extent() const { return object.extent; }  // [m^2] shape matrix
};

struct ExtendedScanReport {
  bool skipped = false;    // non-finite or earlier time than the last scan: nothing changed
  int plots = 0;           // usable plots
  int rejected_plots = 0;  // non-finite positions or noise
  int partitions = 0;
  int updated = 0;
  int initiated = 0;
  int confirmed = 0;  // tentative -> confirmed this scan
  int deleted = 0;
  int numeric_failures = 0;
};

class ExtendedTracker {
 public:
  explicit ExtendedTracker(const ExtendedSpec& spec);

  /// One scan of plots (their Cartesian tracking-frame positions and noise are used: polar
  /// plots are placed with approximate_position and their noise is propagated to x, y).
  /// `partitions`: plot-index groups from the preprocessing; empty = distance partitioning.
  ExtendedScanReport process(double time, std::span<const PlotMeasurement> plots,
                             std::span<const std::vector<int>> partitions = {});

  /// The same with positions [m] and noise covariances [m^2] given directly (equal sizes).
  ExtendedScanReport process(double time, std::span<const Eigen::Vector2d> positions,
                             std::span<const Eigen::Matrix2d> noises,
                             std::span<const std::vector<int>> partitions = {});

  /// Live tracks, ordered by number.
  std::span<const ExtendedTrack> tracks() const noexcept { return tracks_; }
  /// Numbers of the tracks deleted by the last scan.
  std::span<const std::uint64_t> deleted() const noexcept { return deleted_; }

 private:
  struct Gated {
    int track = -1;
    double distance = 0.0;  // d^2
  };
  /// d^2 of z from track t's centre with G = H P H' + extent_weight X + noise, X its
  /// association extent.
  double gate_distance(int t, const Eigen::Vector2d& z, const Eigen::Matrix2d& noise,
                       double extent_weight, double* log_det) const noexcept;
  /// Gates this scan's partitions (groups_) and gives each track its plots.
  void associate(ExtendedScanReport& report);
  Eigen::Matrix2d association_extent(const ExtendedTrack& track) const noexcept;
  bool crossing_unresolved() const noexcept;
  // Tentative tracks only gate a partition: gated_ keeps the one likeliest to give its mean.
  void keep_likeliest_tentative(const Eigen::Vector2d& mean, const Eigen::Matrix2d& noise);
  void split_shared(const std::vector<int>& group);
  // A two-track split's shares and each track's model of its object's plots.
  void plots_models(const std::vector<int>& group, std::vector<Eigen::Vector2d> (&share)[2],
                    PlotsModel (&model)[2]) const;
  // The split's other labelling, where likelier (the shares follow).
  void exchange_if_likelier(std::vector<Eigen::Vector2d> (&share)[2], const PlotsModel (&model)[2]);
  // A split where one object is all.
  void one_object_only(const std::vector<Eigen::Vector2d> (&share)[2],
                       const PlotsModel (&model)[2]);
  bool claim_by_confirmed(const std::vector<int>& group);
  void keep_missed_scan(int t, const ExtendedObject& quiet, double evidence_before,
                        double log_ratio);
  void reconsider_missed_scans();  // before the claims: a track's last scan as a miss
  void initiate(const std::vector<int>& group, ExtendedScanReport& report);
  void drop_lone_plots(int t);  // lone plots away from the track's cluster of this scan
  // A partition beyond the object's extent from the track's best one: not its object's.
  void keep_partitions_within_reach(int t);
  // The next two read the track's plots of this scan from plot_buffer_ (buffer_track_plots)
  // with their mean noise.
  // ln of the plots as the object's against clutter (below 0: clutter); NaN: the test is off.
  double clutter_log_ratio(int t, const Eigen::Matrix2d& noise) const;
  // True: predicted again with manoeuvre_accel (turning_ then holds the quiet prediction).
  bool predict_manoeuvre_if_likelier(int t, const Eigen::Matrix2d& noise);
  Eigen::Matrix2d buffer_track_plots(int t);  // into plot_buffer_; returns their mean noise
  void two_point_velocity(ExtendedTrack& track) const noexcept;
  bool mixes_levels() const noexcept;    // noise_levels.hpp: the Bayesian estimators, two levels
  bool chooses_levels() const noexcept;  // SMF-EOT with two levels: one a scan (CUSUM)
  // After the track's prediction this scan; SMF-EOT with two levels: also predicts it at
  // manoeuvre_accel into manoeuvre_predictions_.
  Eigen::Matrix2d gate_centre_cov(int t);
  // A confirmed track that lost its object to a track born beside it last scan (a turn's
  // split plots) takes that track's state and keeps its number.
  void hand_over_split_objects();
  void manage(ExtendedScanReport& report);

  ExtendedSpec spec_;
  ExtendedEstimator estimator_;
  DistancePartitioner partitioner_;
  std::vector<ExtendedTrack> tracks_;
  std::vector<std::uint64_t> deleted_;
  std::uint64_t next_id_ = 1;
  double last_time_ = 0.0;
  double scan_dt_ = 0.0;  // [s] since the previous scan
  bool started_ = false;
  // Per-scan buffers, reused.
  std::vector<Eigen::Vector2d> positions_, plot_buffer_;
  std::vector<Eigen::Matrix2d> noises_;
  std::vector<std::vector<int>> groups_;
  std::vector<std::vector<int>> track_plots_;
  std::vector<Gated> gated_;
  std::vector<Eigen::Matrix2d> association_extents_;   // per track, this scan
  std::vector<Eigen::Matrix2d> gate_centre_covs_;      // per track, this scan: its gates' HPH'
  std::vector<char> was_unresolved_;                   // per track, the last scan's flag
  std::vector<ExtendedObject> priors_;                 // per track, the object before predict
  std::vector<int> weighed_, best_weighed_;            // workspaces of reconsider_missed_scans
  ExtendedObject turning_;                             // workspace of predict_manoeuvre_if_likelier
  std::vector<ExtendedObject> manoeuvre_predictions_;  // per track, SMF-EOT with two levels
  std::vector<Eigen::Vector2d> split_centre_;          // per gating track, its centre in the split
  std::vector<Eigen::Matrix2d> split_cov_;
  std::vector<int> split_owner_;  // per plot of the partition, its index into gated_
  std::vector<const std::vector<int>*> unassigned_;
  std::vector<Eigen::Vector2d> plane_positions_;  // PlotMeasurements in the tracking plane
  std::vector<Eigen::Matrix2d> plane_noises_;
  std::vector<double> gate_areas_;     // [m^2] per track, its plot gate's area this scan
  std::vector<int> partition_of_;      // per plot, its index into groups_ this scan (-1: none)
  std::vector<char> partition_split_;  // per partition, shared by a split this scan
  struct Piece {                       // a track's plots of one partition
    int partition = -1;
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    Eigen::Matrix2d noise = Eigen::Matrix2d::Zero();
    int count = 0;
  };
  std::vector<Piece> pieces_;  // workspace of keep_partitions_within_reach
  struct Yieldable {           // a partition a track took beside a likelier one of its own
    int track = -1;
    int partition = -1;
  };
  std::vector<Yieldable> yieldable_;  // this scan's, for reconsider_missed_scans
  int partition_size(int i) const {
    return partition_of_[i] < 0 ? 0 : static_cast<int>(groups_[partition_of_[i]].size());
  }
};

}  // namespace skytrack::extended
