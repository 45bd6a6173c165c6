#pragma once
// Parameters of the fusion role (docs/fusion.md, config/fusion.yaml). The symbols are paper
// 004's: c (cutoff), p (order), alpha (label penalty), epsilon, gamma (gate).
#include <cstdint>

namespace skytrack::fusion {

enum class Blend : std::uint8_t {
  kAdaptive,  // beta = epsilon * max(Dw, D) / (Dw + D) (eq. 11)
  kFixed,     // the paper's baseline: beta = history_weight
};

/// The base distance d(x, y) of eq. 10 between two tracks' positions.
enum class Metric : std::uint8_t {
  kNormalised,  // Mahalanobis in the pair's summed position covariance: c, alpha, gamma in sigmas
  kEuclidean,   // the paper's metres: c, alpha, gamma in metres
};

struct FusionSpec {
  std::uint32_t output_sensor = 0;  // sensor key of the fused frames
  double cycle = 1.0;               // [s] period of the fused picture, in data time
  double window = 10.0;             // [s] sliding window of the history distance Dw (paper: 10 s)
  Blend blend = Blend::kAdaptive;
  // Adaptive blend: beta lies in [epsilon/2, epsilon]; it is epsilon/2 when history and
  // current distance agree, so 0.4 gives the baseline's history weight 0.2 in steady state.
  double epsilon = 0.4;
  double history_weight = 0.2;  // fixed blend: weight of Dw (the current D gets the rest)
  Metric metric = Metric::kNormalised;
  double cutoff = 10.0;         // c [sigma | m]: a pair farther apart is "different", whatever
  double order = 2.0;           // p of eq. 9-10
  double label_penalty = 2.0;   // alpha in [0, c) [sigma | m]: a pair not last fused together
  double gate = 4.0;            // gamma [sigma | m]: a pair whose MOSPA is below it is one target
  double sensor_timeout = 5.0;  // [s] of data time without a frame: the sensor is dropped
  double coast_time = 5.0;      // [s] a system track without sources is kept, coasting
  bool firm_only = true;        // fuse confirmed and coasting local tracks only
  // Added with the implementation:
  double accel_psd = 10.0;  // [m^2/s^3] CV white-noise acceleration when aligning in time
  double missing_position_sigma = 100.0;  // [m] for a local track that reports no covariance
  double missing_velocity_sigma = 10.0;   // [m/s] likewise
  int max_queued_frames = 256;            // per sensor, frames waiting for slower sensors
};

}  // namespace skytrack::fusion
