#pragma once
// Parameters of group tracking with the labeled box-particle PHD filter (paper 000,
// LBP-PHD). Defaults are the paper's experiment 1 (§4.1) where it gives a value; the others
// are this implementation's choices, each marked "(ours)" and explained in docs/group.md.
// 2-D: boxes are intervals over the state [x vx y vy] in the tracking frame, SI units.
#include <cstdint>
#include <string_view>

#include "skytrack/clutter/clutter_rejection_spec.hpp"

namespace skytrack::group {

/// Motion model of the box prediction (eq. 14): the interval hull of F [x].
enum class GroupMotion : std::uint8_t {
  kConstantVelocity,  // experiment 2
  kCoordinatedTurn,   // experiment 1: known turn rate `turn_rate`
};

/// Label rules of §3.2.7.
enum class LabelModel : std::uint8_t {
  kDouble,  // (l1, l2): a group survives up to `max_missed` scans without detection
  kSingle,  // l1 only: a group not detected in one scan dies (the paper's LBP-PHD-single)
};

constexpr std::string_view to_string(GroupMotion motion) {
  return motion == GroupMotion::kConstantVelocity ? "constant_velocity" : "coordinated_turn";
}
constexpr std::string_view to_string(LabelModel labels) {
  return labels == LabelModel::kDouble ? "double" : "single";
}

struct GroupSpec {
  // Motion (eq. 14).
  GroupMotion motion = GroupMotion::kCoordinatedTurn;
  double turn_rate = 0.0523598775598;  // [rad/s] w = 3 deg/s (the paper prints "3 rad/s")

  // Boxes. Position width Delta = [24, 24] m is the paper's; the velocity width (ours).
  int boxes_per_group = 30;              // N_box, boxes kept per label after resampling
  double position_width = 24.0;          // [m] box side in x and y after re-inflation
  double velocity_width = 10.0;          // [m/s] box side in vx and vy after re-inflation (ours)
  double jitter = 0.5;                   // centre jitter after resampling, +- this fraction of
                                         // the half-width, uniform (ours)
  double measurement_box_padding = 2.5;  // [m] added on each side of a cell's interval hull, so
                                         // a one-plot cell has an area (ours: one sigma)

  // Births (§3.2.2).
  int births_per_box = 6;           // n1, at each measurement box of the previous scan
  int births_per_estimate = 1;      // n2, at each group estimate of the previous scan
  double birth_mass_per_box = 0.2;  // summed weight of the n1 boxes of one cell (ours)
  double birth_speed = 60.0;        // [m/s] newborn velocity interval [-v, v]^2 (ours)

  // PHD update (eq. 15, 18-20).
  double survival_probability = 0.99;  // Ps
  double detection_probability = 1.0;  // Pd of a group (the paper's exp. 1: 1; exp. 2: 0.98)
  // lambda of eq. 20: mean clutter plots per scan that reach the filter. The paper's 10 is
  // its raw rate; after the preprocessing fewer survive, so this is an upper bound there.
  double clutter_rate = 10.0;
  double surveillance_area = 4.0e6;  // [m^2] |A|, clutter intensity lambda |[z]| / |A|

  // Labels (§3.2.7).
  LabelModel labels = LabelModel::kDouble;
  double extraction_threshold = 0.5;  // chi'
  int max_missed = 3;                 // chi: a label dies when l2 > chi
  // A cell counts as a detection of only the label (or newborn set) that took the largest
  // share of it, credited with the cell's whole target mass (ours): without it two labels on
  // one merged group keep ~0.5 each, both below chi', or both above it forever.
  bool exclusive_cells = true;

  // Extent and member count from the cells a label took (ours; docs/group.md).
  double shape_smoothing = 0.3;               // exponential smoothing factor per detected scan
  double measurement_sigma = 2.5;             // [m] subtracted (as sigma^2) from the plot spread
  double member_detection_probability = 1.0;  // plots per member per scan

  // Eq. 8 always rejects the lowest-density plots, which without clutter are a group's
  // outermost ones: a rejected plot within this distance of a cell's interval hull rejoins
  // the nearest such cell (ours; 0 = off), so boxes, extent and member count are not shrunk.
  double readmit_distance = 10.0;  // [m]

  // Preprocessing (§3.1): kernel-density clutter rejection and mean-shift cells.
  config::ClutterRejectionSpec preprocessing = default_preprocessing();

  std::uint64_t seed = 1;  // the filter's std::mt19937_64
  bool operator==(const GroupSpec&) const = default;

  static config::ClutterRejectionSpec default_preprocessing() {
    config::ClutterRejectionSpec spec;
    spec.enabled = true;
    spec.kernel_bandwidth = 10.0;  // [m] h, the scale of one group's plot spacing (ours)
    spec.beta = 1;
    spec.n_f = 10;
    spec.mean_shift.bandwidth = 10.0;       // [m]
    spec.mean_shift.merge_distance = 10.0;  // [m]
    spec.mean_shift.max_iterations = 50;
    spec.mean_shift.tolerance = 0.5;  // [m]
    return spec;
  }
};

}  // namespace skytrack::group
