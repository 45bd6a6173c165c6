#pragma once
// The tracking profile: what a tracker reads from a YAML profile, as plain structs.
// The member defaults are the shipped config/profiles/default.yaml (a test keeps them equal);
// config/README.md documents every key with its range. SI units, angles in radians, the
// local ENU tracking frame of DESIGN.md.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "skytrack/bernoulli/bernoulli_spec.hpp"
#include "skytrack/clutter/clutter_rejection_spec.hpp"
#include "skytrack/extended/extended_spec.hpp"
#include "skytrack/group/group_spec.hpp"

namespace skytrack::config {

enum class TrackingMode { kPoint, kGroup, kExtended, kBernoulli };
enum class MotionModelType {
  kConstantVelocity,
  kConstantAcceleration,
  kCoordinatedTurn,           // fixed turn rate
  kCoordinatedTurnEstimated,  // turn rate is a state
  kSinger,
};
enum class MeasurementUpdate { kEkf, kUnscented };
enum class AssociationMethod { kJpda, kGnn };
enum class ConfirmationMethod { kMOfN, kExistence };
enum class NonManoeuvreGate { kUnion, kLastMotion };
enum class AntennaRotation { kAuto, kRotating, kSnapshot };
enum class RotationDirection { kAuto, kClockwise, kCounterclockwise };

struct ProfileIdentity {
  std::string name;     // required; shown in logs, status and check-profile
  std::string version;  // required; free text ("3", "2024-06a")
  std::string description;
  bool operator==(const ProfileIdentity&) const = default;
};

/// Standard deviations used when neither the scan nor the plot gives its own (CONTRACTS §1).
struct MeasurementSigmas {
  double range = 30.0;       // [m]
  double azimuth = 0.003;    // [rad]
  double elevation = 0.006;  // [rad]
  double range_rate = 2.0;   // [m/s]
  double x = 50.0;           // [m] Cartesian plots
  double y = 50.0;           // [m]
  double z = 100.0;          // [m]
  double height = 30.0;      // [m] altitude from a flight level (ICAO: +-300 ft at 3 sigma)
  bool operator==(const MeasurementSigmas&) const = default;
};

/// Sigma-point scaling of the unscented update (Wan & van der Merwe 2000).
struct UnscentedSpec {
  double alpha = 1.0;  // spread, in [1e-4, 1]
  double beta = 2.0;   // prior knowledge; 2 is optimal for Gaussians
  double kappa = 0.0;  // >= 0 keeps every weight set valid whatever the state size
  bool operator==(const UnscentedSpec&) const = default;
};

struct MeasurementSpec {
  MeasurementUpdate update = MeasurementUpdate::kEkf;
  UnscentedSpec unscented;  // used when update is kUnscented
  MeasurementSigmas default_sigma;
  bool operator==(const MeasurementSpec&) const = default;
};

/// One IMM mode. Only the parameters of `type` are read from the file; the others keep their
/// defaults and mean nothing. In 3-D the vertical channel of every type is nearly constant
/// velocity with `vertical_accel_sigma`.
struct MotionModelSpec {
  std::string name;  // unique; the mode's name in outputs ("modes") and in branching
  MotionModelType type = MotionModelType::kConstantVelocity;
  double accel_sigma = 1.0;  // [m/s^2] white acceleration (cv, ct, ct-estimated); Singer sigma_m
  double jerk_sigma = 1.0;   // [m/s^3] white jerk (constant_acceleration)
  double turn_rate = 0.0;    // [rad/s] coordinated_turn; positive = left (anticlockwise)
  double turn_rate_sigma = 0.005;         // [rad/s^2] white turn acceleration (ct-estimated)
  double initial_turn_rate_sigma = 0.05;  // [rad/s] turn-rate spread at start or mode entry
  double time_constant = 20.0;            // [s] Singer manoeuvre time constant
  double vertical_accel_sigma = 1.0;      // [m/s^2] z channel, 3-D only
  bool operator==(const MotionModelSpec&) const = default;
};

/// Local clutter density (a clutter map) on top of the batch-wide `auto` estimate.
struct ClutterMapSpec {
  bool enabled = true;
  double range_cell = 5000.0;      // [m] polar plots
  double azimuth_cell = 0.05;      // [rad] polar plots
  double cartesian_cell = 5000.0;  // [m] x and y of Cartesian plots
  bool operator==(const ClutterMapSpec&) const = default;
};

/// A target's detectability as a two-state Markov chain per scan (Musicki, Evans & Stankovic
/// 1994, IEEE Trans. AC-39(6), "Markov chain two"): detectable, seen with P_D, or hidden
/// (masked by clutter, faded, shadowed), seen with 0.
struct DetectabilitySpec {
  double hide = 0.05;   // P(detectable -> hidden) per scan; 0: misses independent at 1 - P_D
  double reveal = 0.3;  // P(hidden -> detectable) per scan
  bool operator==(const DetectabilitySpec&) const = default;
};

struct AssociationSpec {
  AssociationMethod method = AssociationMethod::kJpda;
  double gate_probability = 0.999;     // P_G of the (non-manoeuvre) validation gate, in (0, 1)
  double detection_probability = 0.9;  // P_D, in (0, 1]
  // Clutter spatial density in the tracking frame [1/m^2 in 2-D, 1/m^3 in 3-D]; empty means
  // "auto": estimated from each scan.
  std::optional<double> clutter_density;
  ClutterMapSpec clutter_map;       // with auto only
  int max_exact_cluster_size = 32;  // [tracks] exact JPDA marginals up to this cluster size
  int k_best = 100;                 // joint events from Murty's k-best above it
  bool operator==(const AssociationSpec&) const = default;
};

/// M-of-N plot-to-plot initiation with a speed gate.
struct InitiationSpec {
  int m = 3;                 // plots needed ...
  int n = 4;                 // ... within this many consecutive scans
  double min_speed = 0.0;    // [m/s] slower plot pairs are taken as stationary clutter
  double max_speed = 700.0;  // [m/s] faster plot pairs cannot be one target
  // A track whose most likely plot has an association probability above this explains that
  // plot alone; the other plots in its gate may still seed (or extend) chains, e.g. a
  // formation member inside its neighbour's gate. A track without such a plot holds its
  // whole gate. 1: only plots in no gate seed chains.
  double gated_seed_beta = 0.7;
  // The track capacity for tentative tracks: a chain completed while this many are held
  // starts none (counted, reported as an overload event), so a batch of random plots (a
  // jammer, a broken extractor) cannot grow the tracker without bound.
  int max_tentative = 5000;
  bool operator==(const InitiationSpec&) const = default;
};

/// tentative -> confirmed -> coasting -> deleted.
struct TrackLifeSpec {
  // m_of_n: confirmed on M plots in the last N scans. existence: on the probability that
  // the track is a target (IPDA, Musicki et al. 1994), which weighs each plot's likelihood
  // against the clutter density, so chains of clutter plots rarely confirm.
  ConfirmationMethod confirmation = ConfirmationMethod::kExistence;
  int confirm_m = 3;                      // confirmed when M of the last N scans had a plot
  int confirm_n = 4;                      // (counted from the track's first plot)
  double initial_existence = 0.05;        // of a new track, before its chain's later plots
  double confirm_existence = 0.95;        // confirmed at or above
  double delete_existence = 0.02;         // deleted below (tentative or confirmed)
  double survival_probability = 0.98;     // a target is still there one scan later
  int delete_tentative_misses = 2;        // consecutive misses that delete a tentative track
  int delete_confirmed_misses = 5;        // K consecutive misses that delete a confirmed track
  double delete_position_sigma = 2000.0;  // [m] or when sqrt(max eig of P_pos) exceeds this
  bool operator==(const TrackLifeSpec&) const = default;
};

/// Branch ("filiation") tracking, paper 003.
struct BranchingSpec {
  bool enabled = true;
  int max_children = 3;  // sons per father, grandsons per son (paper: 3)
  // The manoeuvre gate is the union of the gates of these models' predictions at this
  // probability; the non-manoeuvre gate uses association.gate_probability.
  double manoeuvre_gate_probability = 0.9999;
  std::vector<std::string> manoeuvre_models = {"cv", "ct_left", "ct_right"};
  // [m/s^2] the manoeuvre gate's models take at least this white acceleration (their own
  // accel_sigma if larger): the range of manoeuvres a target may start between two looks.
  double manoeuvre_accel_sigma = 20.0;
  // A firm father whose non-manoeuvre update weighs two plots each at least this much (and
  // more than a miss), neither the likeliest plot of another father, cannot decide in one
  // frame: the plots start its sons, which decide, while it is still reported. 1: never
  // (the father takes the likelier plot, rule 5).
  double ambiguity_beta = 0.3;
  // A firm father with no valid association in a scan (no plot likelier than its miss)
  // coasts on the motion it was last seen in: its likeliest mode at its latest valid
  // association, predicted alone (IMM mixing blends in the other modes' diverging
  // predictions), and gates non-manoeuvre pairs on it; plots off that motion lie in its
  // manoeuvre gate only and start sons (paper 003 §4.2), whose gate starts from its IMM's
  // own coast. false: the IMM-JPDA update and the union of all modes' gates, and the
  // options below that need it are inert. On by default with them (paper 003 exp. 2 in
  // clutter areas, docs/branch-tracker.md).
  bool coast_on_last_motion = true;
  // A firm father's non-manoeuvre gate: union, the union of its IMM modes' gates; last_motion
  // (needs coast_on_last_motion), its last motion's gate in every scan, not only after a
  // miss (paper 003 §1: a non-manoeuvre association keeps the motion unchanged), so that a
  // plot only a turn mode reaches starts a son instead of turning the father.
  NonManoeuvreGate non_manoeuvre_gate = NonManoeuvreGate::kLastMotion;
  // Where the last motion applies (needs coast_on_last_motion; 0: everywhere): only where its
  // gate expects at least this many false plots (the clutter density at a plot times the
  // gate's volume there), in a clutter area. Elsewhere the father gates on the union and
  // coasts on its IMM, whose turn modes follow a manoeuvre through a missed look.
  double last_motion_false_plots = 0.3;
  // [m/s^2] White acceleration of a held last motion (its gate and its coast), at most each
  // model's own accel_sigma; 0: the model's own. A motion held unchanged over missed looks
  // spreads along the range, which the radar measures to tens of metres, by the model's
  // noise alone (2 m/s^2: 290 m after 40 s), and a wider gate holds more false alarms.
  double last_motion_accel_sigma = 0.5;
  // How a son or grandson started from a manoeuvre pair confirms (rule 10): m_of_n on one
  // more plot (the paper's examples); existence as track_life does (IPDA), from
  // track_life.initial_existence, weighing each later plot against the clutter density
  // round it, so that a clutter area's plots confirm branches slowly.
  ConfirmationMethod confirmation = ConfirmationMethod::kExistence;
  // Coast sons (needs coast_on_last_motion; 0: none): when a firm father takes a plot that
  // may be a false alarm (its clutter density is at least coast_son_doubt of the plot's
  // density under the father and the clutter together), its last motion before that plot
  // stays as a hidden son that rule 5 does not cut: the hypothesis that its target was
  // missed. It coasts and gates on that motion, takes non-manoeuvre pairs, and replaces the
  // father in a look where it takes a plot and its TrackLife::support passes the father's
  // and the father's sons' and grandsons'. At most this many per father (the oldest
  // untouched goes); deleted after track_life.delete_confirmed_misses misses in a row.
  int coast_sons = 5;
  double coast_son_doubt = 0.1;
  // The coast sons' decision window (0: none): a coast son that has not replaced its father
  // within this many looks of its split is pruned, the father's plots then standing (the
  // N-scan pruning of a multi-hypothesis tracker, on the miss-or-false-alarm question).
  int coast_son_looks = 8;
  // The chain by which TrackLife::support, and the branches' scores, count misses where the
  // last motion's gate expects last_motion_false_plots or more (a clutter area, where a
  // target is masked for looks on end): a run of misses there costs less than independent
  // misses at 1 - P_D, so that a coast son that took the target's returning plot can pass a
  // father that took false plots meanwhile. Elsewhere, and in JPDA, existence and the
  // filter everywhere, P_D alone.
  DetectabilitySpec detectability;
  int max_branches_per_father = 12;  // sons + grandsons of one father (3 + 9 at 3 children)
  int max_total_branches = 2000;     // in the whole tracker: bounds time and memory
  bool operator==(const BranchingSpec&) const = default;
};

/// The radar's antenna, for batches that do not say what they looked at (no `coverage`): a
/// rotating antenna's plots are regrouped into looks by the azimuth swept, so that a target is
/// looked at once per revolution however the feed batches its plots (a revolution, a sector,
/// a few plots); a snapshot sensor's batch is one look at everything.
struct AntennaSpec {
  // auto: rotating when the plots' own times advance with their azimuths at a steady rate.
  AntennaRotation rotation = AntennaRotation::kAuto;
  std::optional<double> period;  // [s] one revolution; absent (auto): measured from the plots
  RotationDirection direction = RotationDirection::kAuto;  // seen from above; auto: measured
  bool operator==(const AntennaSpec&) const = default;
};

/// Physical limits on what a sensor reports: a plot or a batch beyond them is corrupt (or
/// hostile) and is rejected, counted by reason, before it reaches the tracks.
struct InputLimitsSpec {
  // [m] slant range of a polar plot, distance from the radar of a Cartesian one: far beyond
  // any radar's instrumented range, so only garbage is refused.
  double max_range = 2.0e6;
  // [s] the forward step from a sensor's latest batch (and a plot's time from its batch's):
  // a sensor silent longer has lost its tracks anyway; its next batches restart its clock
  // (batch_clock.hpp).
  double max_time_jump = 600.0;
  bool operator==(const InputLimitsSpec&) const = default;
};

/// The point tracker's own sections (mode: point): logic-based initiation, track life and
/// branch tracking (paper 003).
struct PointSpec {
  InitiationSpec initiation;
  TrackLifeSpec track_life;
  BranchingSpec branching;
  bool operator==(const PointSpec&) const = default;
};

/// A tracking profile: the sections every mode reads (identity, mode, measurement, antenna,
/// motion models, association basics, preprocessing, input limits), then each mode's own.
struct TrackingProfile {
  ProfileIdentity identity;
  TrackingMode mode = TrackingMode::kPoint;
  int dimension = 0;  // 2: state [x vx y vy]; 3: adds [z vz]; 0 = auto (from the plots)
  MeasurementSpec measurement;
  AntennaSpec antenna;
  std::vector<MotionModelSpec> motion_models = {
      {.name = "cv", .type = MotionModelType::kConstantVelocity, .accel_sigma = 2.0},
      {.name = "ct_left",
       .type = MotionModelType::kCoordinatedTurn,
       .accel_sigma = 6.0,
       .turn_rate = 0.15},  // 8.6 deg/s: 4 g at 300 m/s
      {.name = "ct_right",
       .type = MotionModelType::kCoordinatedTurn,
       .accel_sigma = 6.0,
       .turn_rate = -0.15},
  };
  // Markov matrix per scan: row i gives P(mode j now | mode i before); rows sum to 1.
  std::vector<std::vector<double>> mode_transition = {
      {0.90, 0.05, 0.05},
      {0.18, 0.80, 0.02},
      {0.18, 0.02, 0.80},
  };
  // [s] the interval mode_transition is given for: a prediction over dt applies it
  // dt / interval times (P^k (I + f (P - I)), k + f = dt / interval), so a rotating
  // antenna's plots, seconds apart within one batch, are not each given a whole scan's
  // switching. 0: once per prediction whatever its length (paper 003's per-scan form).
  double mode_transition_interval = 4.0;
  std::vector<double> initial_mode_probabilities = {0.8, 0.1, 0.1};
  AssociationSpec association;
  ClutterRejectionSpec clutter_rejection;
  InputLimitsSpec input_limits;
  PointSpec point;  // mode: point
  // mode: bernoulli. Its models, their transition matrix and a newborn target's model
  // probabilities are the common motion_models, mode_transition (per scan) and
  // initial_mode_probabilities: the loader copies them in.
  bernoulli::BernoulliSpec bernoulli;
  // mode: group. Its preprocessing is the common clutter_rejection section (the loader
  // copies it in).
  group::GroupSpec group;
  extended::ExtendedSpec extended;  // mode: extended
  bool operator==(const TrackingProfile&) const = default;
};

// The names used in profile files.
constexpr std::string_view to_string(TrackingMode mode) {
  switch (mode) {
    case TrackingMode::kPoint:
      return "point";
    case TrackingMode::kGroup:
      return "group";
    case TrackingMode::kExtended:
      return "extended";
    case TrackingMode::kBernoulli:
      return "bernoulli";
  }
  return "?";
}

constexpr std::string_view to_string(MotionModelType type) {
  switch (type) {
    case MotionModelType::kConstantVelocity:
      return "constant_velocity";
    case MotionModelType::kConstantAcceleration:
      return "constant_acceleration";
    case MotionModelType::kCoordinatedTurn:
      return "coordinated_turn";
    case MotionModelType::kCoordinatedTurnEstimated:
      return "coordinated_turn_estimated";
    case MotionModelType::kSinger:
      return "singer";
  }
  return "?";
}

constexpr std::string_view to_string(MeasurementUpdate update) {
  return update == MeasurementUpdate::kEkf ? "ekf" : "unscented";
}

constexpr std::string_view to_string(AssociationMethod method) {
  return method == AssociationMethod::kJpda ? "jpda" : "gnn";
}

constexpr std::string_view to_string(ConfirmationMethod method) {
  return method == ConfirmationMethod::kMOfN ? "m_of_n" : "existence";
}

constexpr std::string_view to_string(NonManoeuvreGate gate) {
  return gate == NonManoeuvreGate::kUnion ? "union" : "last_motion";
}

constexpr std::string_view to_string(AntennaRotation rotation) {
  switch (rotation) {
    case AntennaRotation::kAuto:
      return "auto";
    case AntennaRotation::kRotating:
      return "rotating";
    case AntennaRotation::kSnapshot:
      return "snapshot";
  }
  return "?";
}

constexpr std::string_view to_string(RotationDirection direction) {
  switch (direction) {
    case RotationDirection::kAuto:
      return "auto";
    case RotationDirection::kClockwise:
      return "clockwise";
    case RotationDirection::kCounterclockwise:
      return "counterclockwise";
  }
  return "?";
}

}  // namespace skytrack::config
