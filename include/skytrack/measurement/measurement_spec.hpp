#pragma once
// The measurement update and the default sigmas as a profile gives them (`measurement`).
// Plain structs in skytrack::config, the profile's namespace (profile.hpp gathers them);
// defaults and ranges in config/README.md.
#include <string_view>

namespace skytrack::config {

enum class MeasurementUpdate { kEkf, kUnscented };

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

constexpr std::string_view to_string(MeasurementUpdate update) {
  return update == MeasurementUpdate::kEkf ? "ekf" : "unscented";
}

}  // namespace skytrack::config
