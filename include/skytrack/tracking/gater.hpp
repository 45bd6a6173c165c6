#pragma once
// The point tracker's gater: each track's validation gate round its IMM prediction, giving the
// look's track-plot candidates (paper 003 §3.2). A track's search region comes from its
// prediction at the middle of the batch; the look's plots in it (Preprocessing::index) are
// tested in the ellipsoidal gate at the track's own update time, the time of its nearest
// candidate plot, so a rotating antenna's plots are used at the time they were measured.
// Also the cheap search regions the pipeline cuts looks with (core/look.hpp).
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "skytrack/config/profile.hpp"
#include "skytrack/core/look.hpp"
#include "skytrack/core/plot.hpp"
#include "skytrack/filter/imm_filter.hpp"
#include "skytrack/measurement/plot_measurement.hpp"
#include "skytrack/preprocess/preprocessing.hpp"
#include "skytrack/tracking/branch_hooks.hpp"
#include "skytrack/tracking/point_track.hpp"

namespace skytrack {

/// A gated track-plot pair.
struct Candidate {
  int track = 0;
  int plot = 0;
  PlotHypothesis hypothesis;  // against the track's IMM prediction (its update)
  double likelihood = 0.0;    // what JPDA weighs it with (the gate's own model set)
};

class Gater {
 public:
  Gater(const config::TrackingProfile& profile, int dims);

  /// Gates every track's candidates among the look's plots. The look's plot times span
  /// batch_mid -+ half_span.
  void gate(const PlotScan& scan, Preprocessing& pre, std::vector<PointTrack>& tracks,
            const ImmFilter& filter, double batch_mid, double half_span, BranchHooks& hooks);

  // The look's gating.
  std::vector<Candidate>& candidates() { return candidates_; }
  const std::vector<Candidate>& candidates() const { return candidates_; }
  /// Per track, its IMM prediction at its update time (its estimate if it gated nothing).
  std::vector<ImmEstimate>& predicted() { return predicted_; }
  /// Track t (slot) predicted to `time` without a plot: the gater's own prediction when it
  /// made that one from the same estimate (a track with no plot round it; handed over once),
  /// else a new one.
  ImmEstimate coast(const PointTrack& track, std::size_t t, const ImmFilter& filter, double time);
  /// Per track: inside this look's coverage (the look ages it).
  bool covered(std::size_t t) const { return t >= covered_.size() || covered_[t] != 0; }
  /// Per track: a plot of this look in its gate.
  bool took_candidates(std::size_t t) const { return took_candidates_[t] != 0; }
  /// Per plot: in some track's gate.
  bool gated(std::size_t j) const { return gated_[j] != 0; }
  /// Per track: a plot round it in a clutter area (branching.last_motion_false_plots).
  bool in_clutter_area(std::size_t t) const {
    return t < clutter_area_.size() && clutter_area_[t] != 0;
  }
  double batch_mid() const { return batch_mid_; }
  double half_span() const { return half_span_; }

  /// Chi-square gate threshold for a measurement of `d` components.
  double threshold(int d) const { return gate_threshold_[d]; }
  /// The gate's volume times N(nu; 0, S)'s peak for `d` components, (g/2)^(d/2) / Gamma(d/2 + 1).
  double volume_per_peak(int d) const { return gate_volume_per_peak_[d]; }
  double region_accel() const { return region_accel_; }

  /// Radius of the region around `centre` holding g's gate at `threshold` (chi-square), plus
  /// the motion over half the look's time span.
  double search_radius(const Gaussian& g, const Eigen::Vector3d& centre, double threshold,
                       const PlotScan& scan) const;
  /// Time of the plot among `neighbours` nearest to `centre`.
  static double nearest_time(const Preprocessing& pre, std::span<const int> neighbours,
                             const Eigen::Vector3d& centre);
  /// True when the batch looked at `position` (always, unless it covers only a sector).
  static bool covers(const PlotScan& scan, const Eigen::Vector3d& position);
  /// True when a search region (centre, radius) reaches into the batch's coverage.
  static bool covers_region(const PlotScan& scan, const Eigen::Vector3d& centre, double radius);
  /// A region holding track t's gate at `threshold` (chi-square) round its prediction to
  /// `time`, for a target accelerating up to `accel` [m/s^2]: cheap, never smaller than the
  /// gate's own search region.
  SearchRegion region_bound(const std::vector<PointTrack>& tracks, int t, const ImmFilter& filter,
                            const PlotScan& header, double time, double threshold,
                            double accel) const;
  double seed_speed(int t) const {
    return region_seeds_[static_cast<std::size_t>(t)].velocity.norm();
  }
  /// The search region of every live track (its widest gate round its prediction to `time`).
  void search_regions(const std::vector<PointTrack>& tracks, const ImmFilter& filter,
                      const PlotScan& header, double time, std::vector<SearchRegion>& out) const;

 private:
  double plot_spread_at(const Eigen::Vector3d& position, const PlotScan& scan) const;

  config::MeasurementSigmas default_sigma_;
  int dims_ = 2;
  double last_motion_false_plots_ = 0.0;
  double gate_threshold_[kMaxMeasurementDim + 1] = {};  // chi-square quantile per dims
  double gate_volume_per_peak_[kMaxMeasurementDim + 1] = {};
  double region_accel_ = 0.0;   // [m/s^2]
  double max_turn_rate_ = 0.0;  // [rad/s]
  struct RegionSeed {           // a track's combined estimate at its own time (search_regions)
    std::int64_t id = -1;
    double time = 0.0;
    Eigen::Vector3d position = Eigen::Vector3d::Zero(), velocity = Eigen::Vector3d::Zero();
    double spread = 0.0, velocity_spread = 0.0;  // [m], [m/s]
  };
  mutable std::vector<RegionSeed> region_seeds_;  // per track slot
  double batch_mid_ = 0.0, half_span_ = 0.0;      // this look's plot times

  std::vector<Candidate> candidates_;
  std::vector<ImmEstimate> predicted_;
  std::vector<ImmEstimate> coasted_;  // per track: its prediction to the middle, if no plot
  std::vector<std::uint8_t> covered_, took_candidates_, clutter_area_;  // per track
  std::vector<std::uint8_t> gated_;                                     // per plot
  std::vector<int> neighbours_;
  HypothesisShapes shapes_;  // of one track's prediction, across its neighbours
};

}  // namespace skytrack
