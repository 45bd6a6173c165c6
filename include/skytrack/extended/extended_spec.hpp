#pragma once
// Parameters of extended mode: which extent estimator, its parameters, and the multi-object
// tracker's partitioning, gating, initiation and deletion. Defaults are those of paper 002's
// experiment (Liu et al. 2023, section 3.1) where it prints them; units in brackets.
#include <cstdint>
#include <string_view>

namespace skytrack::extended {

/// The extent estimator a profile chooses (closed set).
enum class EstimatorKind : std::uint8_t {
  kSmf,           // SMF-EOT, the set-membership filter of paper 002
  kRandomMatrix,  // Feldmann, Fraenken & Koch 2011, IEEE Trans. SP 59(4)
  kMemEkf,        // Yang & Baum 2019, IEEE Trans. SP 67(18), MEM-EKF*
};

constexpr std::string_view to_string(EstimatorKind kind) {
  switch (kind) {
    case EstimatorKind::kSmf:
      return "smf";
    case EstimatorKind::kRandomMatrix:
      return "random_matrix";
    case EstimatorKind::kMemEkf:
      return "mem_ekf";
  }
  return "";
}

/// Kinematics of every estimator: state [x, vx, y, vy, ax, ay] (StateLayout{2, acceleration})
/// with paper 002's Singer-like transition (eq. 49) per axis
///   F = [1 T T^2/2; 0 1 T; 0 0 e^{-T/theta}],
/// and the process noise entering through G = [T^2/2, T, 1]' per axis: Q6 = G Q2 G'.
/// SMF-EOT takes Q2 = diag(q^2, q^2) as the bound E(0, Q6) of w_k; the Bayesian filters take
/// it as the covariance of w_k (the paper prints one Q for all filters).
struct MotionSpec {
  double time_constant = 40.0;  // [s] theta
  double accel_noise = 0.5;     // [m/s^2] q
  /// [m/s^2] q of a manoeuvring object (ExtendedTracker, not the estimators). The random
  /// matrix and MEM-EKF* mix the two levels per scan (noise_levels.hpp); SMF-EOT predicts a
  /// scan with it when the plots are likelier under that prediction than under accel_noise's.
  /// The objects' hardest manoeuvre; 0 = one level only.
  double manoeuvre_accel = 0.0;
  /// [s] Mean time an object keeps going straight, and keeps manoeuvring (the levels' mixing
  /// switches between them as a Markov chain: over dt it stays with e^{-dt / duration}).
  double straight_duration = 120.0;
  double manoeuvre_duration = 30.0;
  bool operator==(const MotionSpec&) const = default;
};

struct SmfSpec {
  double scattering = 0.25;  // lambda in C = lambda X (+) U (eq. 2)
  /// The sensor bound U from a plot's noise R when the caller gives R, not U (the tracker):
  /// U = k^2 R, i.e. the k-sigma ellipse. The experiment passes U directly.
  double bound_sigmas = 3.0;
  int boundary_points = 16;  // points per plot ellipse Omega_r given to the Graham scan
  /// Weight of the scan's extent measurement against the predicted extent (1 = the paper's
  /// X_k = measured; < 1 smooths the hull's scan-to-scan jitter).
  double extent_gain = 1.0;
  /// The extent step as printed (B (-) (1 + 1/p) H S H', then (-) U, divided by lambda)
  /// instead of our reading (smf_eot.hpp); for the comparison in docs/extended.md only.
  bool literal_extent = false;
  double min_axis = 1.0;  // [m] floor of an estimated semi-axis (empty Minkowski difference)
  /// Two plots of one object lie at most 2 a + 2 u apart (a its major semi-axis, u the noise
  /// bound's). A plot farther than 2 m a + 2 u, m this margin and a the predicted one, from
  /// at least half of the scan's plots leaves the update (smf_eot.cpp); 0 = all plots.
  /// The margin covers the hull's inner estimate of a on few plots.
  double outlier_margin = 2.0;
  double outlier_min_axis = 50.0;  // [m] floor of that a (an extent collapsed on few plots)
  bool operator==(const SmfSpec&) const = default;
};

struct RandomMatrixSpec {
  double scattering = 0.25;  // z in Y = z X + R (uniform scattering over the ellipse)
  /// [s] tau of the extent's certainty decay, alpha = 2 + e^{-T/tau} (alpha - 2).
  double extent_time_constant = 200.0;
  double initial_dof = 10.0;  // alpha_0
  bool operator==(const RandomMatrixSpec&) const = default;
};

struct MemEkfSpec {
  double scattering = 0.25;              // c_h, variance of the multiplicative noise (uniform)
  double orientation_noise = 0.01;       // [rad^2 per scan] process noise of the orientation
  double axis_noise = 1.0;               // [m^2 per scan] process noise of each semi-axis
  double initial_orientation_var = 0.5;  // [rad^2]
  double initial_axis_var = 2500.0;      // [m^2]
  /// After a scan's update each semi-axis is capped by the spread of that scan's plots along
  /// it (at least 3 plots): u'Xu <= 4 (T_u / chi^2_{n-1} - u'Ru), chi^2_{n-1} its lower
  /// quantile at this many standard normal deviates (2.33: 1 %); 0 = no cap (mem_ekf.cpp).
  double spread_bound_sigmas = 2.33;
  /// [m] floor of a semi-axis after a scan's update: plots spread no wider than their noise
  /// leave the object unresolved along that axis, not of zero size (the extent stays definite).
  double min_axis = 1.0;
  bool operator==(const MemEkfSpec&) const = default;
};

/// Existence probability of a track (extended_existence.hpp). When enabled it decides when a
/// confirmed track is deleted, in place of delete_misses: one that has shown its object many
/// plots a scan coasts through three scans without plots, one built of a few plots a scan
/// (clutter) is dropped after one or two (docs/extended.md, table C).
struct ExistenceSpec {
  bool enabled = true;
  double detection_probability = 0.95;  // P_D: an object gives plots in a scan
  double expected_plots = 8.0;          // gamma: an object's mean plots per scan when seen
  double clutter_density = 1e-6;        // [1/m^2] lambda, clutter plots per unit area
  /// p_s: the object is still there a scan later. It caps r at p_s, so it sets how many
  /// scans without plots the best-seen track survives: 0.99999 and P_D 0.95, three.
  double survival = 0.99999;
  double birth = 0.1;         // r of a new track: its first partition is no evidence yet
  double delete_below = 0.5;  // a confirmed track with r below this is deleted
  bool operator==(const ExistenceSpec&) const = default;
};

/// The whole of extended mode's profile section.
struct ExtendedSpec {
  EstimatorKind kind = EstimatorKind::kSmf;
  MotionSpec motion;
  SmfSpec smf;
  RandomMatrixSpec random_matrix;
  MemEkfSpec mem_ekf;
  ExistenceSpec existence;

  // Multi-object tracker (ExtendedTracker).
  double partition_distance = 100.0;  // [m] plots closer than this share a partition
  /// A partition gates with a track when its mean has d^2 = nu' G^-1 nu <= gate,
  /// G = HPH' + X + R: the track's extent enters, so a large object gates its whole plot
  /// cloud; 4 = within twice the ellipse G (a mean inside the object has d^2 <= 1).
  double gate = 4.0;
  /// A plot of a gated partition enters the track's update when d^2 <= plot_gate with
  /// G = HPH' + X/4 + R (X/4: the spread of scatterers uniform over the ellipse; its
  /// outline is at d^2 = 4), which keeps clutter beside the object out [chi^2, 2 dof].
  double plot_gate = 13.8;
  /// A partition of fewer plots starts no track; its plots (lone plots) update a track only
  /// beside a partition of at least this many the track takes, and near it (extended_tracker).
  int min_partition_plots = 2;
  int confirm_hits = 3;               // a tentative track is confirmed after this many updates...
  int tentative_max_misses = 1;       // ...and deleted after this many consecutive misses
  int delete_misses = 3;              // ...a confirmed one after this many (existence off)
  double initial_speed_sigma = 20.0;  // [m/s] a new track's velocity prior (starts at 0)
  double initial_accel_sigma = 0.5;   // [m/s^2] the process noise: more is fitted to noise
  /// [m] floor of a new track's semi-axes, and of the semi-axes association uses (gate,
  /// split of a shared partition), so a collapsed estimate does not shrink the gate.
  double initial_extent_axis = 50.0;
  /// A track that takes no plots in a scan coasts at constant velocity: its prediction
  /// over that scan is redone with the acceleration state's mean at zero (covariance kept),
  /// so an acceleration estimated before the miss does not carry the coast off the object.
  bool coast_constant_velocity = true;
  /// A track's plots of a scan update it only when they are likelier its object seen than
  /// clutter in a scan that missed it (object_plots_log_ratio, with the existence model's
  /// P_D, gamma and lambda); otherwise the scan is a miss and the track coasts. Two stray
  /// plots in a coasting track's wide gate otherwise pull its centre and velocity off.
  bool clutter_scan_test = true;
  /// Two tracks' split of a shared partition is kept only when likelier than all its plots
  /// being one of the two objects with the other missed (P_D, gamma of the existence
  /// model; ExtendedTracker::one_object_only): as a crossing's objects part and one is
  /// missed, its coasting track took some of the other object's plots and turned onto it.
  bool one_object_split_test = true;
  bool operator==(const ExtendedSpec&) const = default;
};

}  // namespace skytrack::extended
