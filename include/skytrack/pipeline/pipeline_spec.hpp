#pragma once
// What the Pipeline itself reads from a profile: the antenna (`antenna`) and the physical
// input limits (`input_limits`).
// Plain structs in skytrack::config, the profile's namespace (profile.hpp gathers them);
// defaults and ranges in config/README.md.
#include <optional>
#include <string_view>

namespace skytrack::config {

enum class AntennaRotation { kAuto, kRotating, kSnapshot };
enum class RotationDirection { kAuto, kClockwise, kCounterclockwise };

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
