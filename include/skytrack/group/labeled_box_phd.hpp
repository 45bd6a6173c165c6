#pragma once
// Labeled box-particle PHD filter for unresolvable groups, paper 000 §3.2 (LBP-PHD):
// births at the previous scan's measurement boxes and group estimates (§3.2.2), interval
// prediction (eq. 14-16), PHD update with the box likelihood and Poisson clutter
// (eq. 18-22), contraction (eq. 23-27), group count (eq. 28), the two-part label rules
// (§3.2.7, eq. 29-30), per-label state extraction (eq. 31-32) and per-label resampling with
// re-inflation (§3.2.9). docs/group.md lists every choice the paper leaves open.
// 2-D, tracking frame, SI units; state [x vx y vy].
#include <cstdint>
#include <random>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "skytrack/group/box_particle.hpp"
#include "skytrack/group/group_spec.hpp"

namespace skytrack::group {

/// One measurement partition (cell) as the filter sees it.
struct GroupCell {
  PlaneBox box;                                       // interval hull (eq. 11), padded [m]
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();     // mean of its plots [m]
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();  // covariance of its plots (1/n) [m^2]
  int plots = 0;
};

/// One group (label) after a scan.
struct GroupEstimate {
  std::uint32_t label = 0;                             // l1: stable while the group lives
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // centroid (eq. 32) [m]
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();  // [m/s]
  Eigen::Matrix2d extent = Eigen::Matrix2d::Zero();    // spread covariance of its members [m^2]
  double members = 0.0;  // estimated member count (plots per scan / member Pd, smoothed)
  double weight = 0.0;   // W_j of eq. 31 (the label's share of N-hat)
  int missed_scans = 0;  // l2: 0 = detected this scan; > 0 = coasting (double label only)
};

class LabeledBoxPhd {
 public:
  /// Startup: the spec is taken as given (GroupTracker checks it).
  explicit LabeledBoxPhd(const GroupSpec& spec);

  /// One scan at `time` [s] with its cells. Returns every live label: detected ones
  /// (missed_scans == 0) first, in label order, then coasting ones. A non-finite time skips
  /// the scan; a time going backwards is taken as dt = 0. noexcept, deterministic per seed.
  const std::vector<GroupEstimate>& step(double time, std::span<const GroupCell> cells) noexcept;

  const std::vector<GroupEstimate>& estimates() const noexcept { return estimates_; }
  /// N-hat of eq. 28 after the last update (before the label rules and resampling).
  double group_count() const noexcept { return group_count_; }
  std::span<const BoxParticle> particles() const noexcept { return particles_; }
  const GroupSpec& spec() const noexcept { return spec_; }

 private:
  struct LabelState {
    std::uint32_t label = 0;
    int missed = 0;
    bool detected = false;  // in the last scan
    BoxVec state = BoxVec::Zero();
    Eigen::Matrix2d extent = Eigen::Matrix2d::Zero();
    double members = 0.0;
    bool has_shape = false;
    double weight = 0.0;
    int slot = -1;  // this scan's slot (see labeled_box_phd.cpp)
  };

  void add_births() noexcept;
  void predict(double dt) noexcept;
  void update(std::span<const GroupCell> cells) noexcept;
  void apply_label_rules(std::span<const GroupCell> cells) noexcept;
  void extract(std::span<const GroupCell> cells) noexcept;
  void resample() noexcept;
  void shape_update(LabelState& ls, int slot, std::span<const GroupCell> cells) noexcept;
  double uniform(double lo, double hi) noexcept;

  GroupSpec spec_;
  std::mt19937_64 rng_;
  std::vector<BoxParticle> particles_;
  std::vector<LabelState> labels_;  // ascending label
  std::vector<PlaneBox> previous_cells_;
  std::uint32_t next_label_ = 1;
  bool has_time_ = false;
  double last_time_ = 0.0;
  double group_count_ = 0.0;
  BoxMat F_ = BoxMat::Identity();
  std::vector<GroupEstimate> estimates_;
  // Workspaces.
  std::vector<BoxVec> prior_centre_;
  std::vector<BoxVec> prior_half_;
  std::vector<PlaneBox> cell_boxes_;
  std::vector<double> clutter_;
  PhdUpdateResult update_;
  std::vector<double> slot_mass_;
  std::vector<int> owner_;                 // per cell: the slot that took the largest share, or -1
  std::vector<std::uint32_t> slot_label_;  // per slot after the label rules (0 = dropped)
  std::vector<BoxParticle> next_;
  std::vector<double> weights_;
  std::vector<int> members_of_label_;
  std::vector<int> picks_;
  std::vector<BoxVec> slot_sum_;    // per slot: sum of w * centre
  std::vector<BoxVec> slot_plain_;  // per slot: sum of centres (a label whose weights are 0)
  std::vector<int> slot_count_;
  std::vector<int> bucket_start_;  // per slot: first index in members_of_label_
  std::vector<double> credit_;     // per slot: the weight the label rules test against chi'
};

}  // namespace skytrack::group
