#pragma once
// The tracking profile: what a tracker reads from a YAML profile, as plain structs. Each
// section's struct lives with its family (motion/, measurement/, association/, clutter/,
// pipeline/, tracking/point_spec.hpp, and one per mode); this header gathers them. The member
// defaults are the shipped config/profiles/default.yaml (a test keeps them equal);
// config/README.md documents every key with its range. SI units, angles in radians, the
// local ENU tracking frame of DESIGN.md.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "skytrack/association/association_spec.hpp"
#include "skytrack/bernoulli/bernoulli_spec.hpp"
#include "skytrack/clutter/clutter_rejection_spec.hpp"
#include "skytrack/extended/extended_spec.hpp"
#include "skytrack/group/group_spec.hpp"
#include "skytrack/measurement/measurement_spec.hpp"
#include "skytrack/motion/motion_model_spec.hpp"
#include "skytrack/pipeline/pipeline_spec.hpp"
#include "skytrack/tracking/point_spec.hpp"

namespace skytrack::config {

enum class TrackingMode { kPoint, kGroup, kExtended, kBernoulli };

struct ProfileIdentity {
  std::string name;     // required; shown in logs, status and check-profile
  std::string version;  // required; free text ("3", "2024-06a")
  std::string description;
  bool operator==(const ProfileIdentity&) const = default;
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

}  // namespace skytrack::config
