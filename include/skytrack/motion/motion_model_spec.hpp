#pragma once
// One IMM mode as a profile gives it (`motion_models[]`, config/README.md).
// Plain structs in skytrack::config, the profile's namespace (profile.hpp gathers them);
// defaults and ranges in config/README.md.
#include <string>
#include <string_view>

namespace skytrack::config {

enum class MotionModelType {
  kConstantVelocity,
  kConstantAcceleration,
  kCoordinatedTurn,           // fixed turn rate
  kCoordinatedTurnEstimated,  // turn rate is a state
  kSinger,
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

}  // namespace skytrack::config
