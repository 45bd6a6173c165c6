#pragma once
// Parameters of the multiple-model Bernoulli particle filter (paper 001, Yang & Zhang 2017,
// "Multiple model Bernoulli particle filter for maneuvering target tracking", JEIT 39(3))
// and of its IMMBPF baseline. Defaults are the paper's experiment (§4); where the paper is
// silent or ambiguous the choice is stated on the field (docs/bernoulli.md lists them).
// State: 2-D [x, vx, y, vy] in the local ENU tracking frame (DESIGN.md), m and m/s.
#include <array>
#include <cstdint>
#include <string_view>

namespace skytrack::bernoulli {

inline constexpr int kMaxModels = 8;

/// One motion model: constant velocity (turn_rate 0) or a coordinated turn at a known rate.
/// The process noise is discrete white noise acceleration, v = G a with G = [T^2/2, T] per
/// axis and a ~ N(0, accel_sigma^2 I2): the paper gives v_k ~ N(0, sigma^2) with sigma in
/// m/s^2, which we read as this standard form (Bar-Shalom et al. 2001, §6.3.3).
struct BernoulliModelSpec {
  double turn_rate = 0.0;    // [rad/s] positive = anticlockwise (motion/coordinated_turn.hpp)
  double accel_sigma = 5.0;  // [m/s^2]
  int particles = 300;       // MMBPF: fixed posterior particles of this model (paper §3.2)
  bool operator==(const BernoulliModelSpec&) const = default;
};

/// Where birth particles come from (paper eq. 22, the proposal q_b(.|Z)). Both place the
/// newborn target on a plot of the previous scan, so the current scan's plots test it
/// (adaptive birth, Ristic et al. 2012; a plot never supports its own birth).
enum class BirthProposal : std::uint8_t {
  /// Position: a plot of scan k-1 with its measurement noise; velocity: the prior
  /// N(birth_velocity, birth_velocity_sigma^2) (the paper's m_b, Q_b velocity part).
  kVelocityPrior,
  /// Position and velocity from a pair of plots of scans k-2 and k-1 no faster than
  /// max_birth_speed apart (two-point initiation), with both plots' noise: no velocity
  /// prior is needed, a target born anywhere at any heading is found.
  kPlotPairs,
};

struct BernoulliSpec {
  /// Paper §4: CV (sigma 5), CT clockwise 0.1 rad/s (sigma 7.5), CT anticlockwise 0.07 rad/s
  /// (sigma 40); particles 300/700/700 (the paper's cheaper configuration).
  std::array<BernoulliModelSpec, kMaxModels> models{
      {{0.0, 5.0, 300}, {-0.1, 7.5, 700}, {0.07, 40.0, 700}}};
  int model_count = 3;
  /// Markov matrix pi_ij = P(model j at k | model i at k-1), rows sum to 1 (eq. 2).
  std::array<std::array<double, kMaxModels>, kMaxModels> transition{
      {{0.96, 0.02, 0.02}, {0.02, 0.96, 0.02}, {0.02, 0.02, 0.96}}};
  /// Model probabilities of a newborn target, gamma (eq. 6): the paper's initial
  /// model probabilities.
  std::array<double, kMaxModels> birth_model_probabilities{0.96, 0.02, 0.02};

  double survival_probability = 0.99;   // p_s
  double birth_probability = 0.01;      // p_b
  double detection_probability = 0.98;  // p_d
  /// Clutter intensity lambda c(z) in polar measurement space [1/(m rad)]: 20 plots per scan
  /// uniform over [0, pi] rad x [0, 25000] m (the paper's lambda_k = 2.5465e-4).
  double clutter_intensity = 20.0 / (3.14159265358979323846 * 25000.0);
  /// q above this: the target is reported (paper step 4, tau).
  double existence_threshold = 0.5;

  BirthProposal birth_proposal = BirthProposal::kVelocityPrior;
  int birth_particles = 200;  // per model per scan (paper: N_j^Gamma = 200)
  /// The paper's m_b velocity and the square root of Q_b's velocity entries (10 (m/s)^2).
  /// m_b's position (21690, 10850) m lies 14 km from the paper's target; birth positions
  /// come from the plots instead (the "proposal round the measurements").
  std::array<double, 2> birth_velocity{-8.0, -400.0};  // [m/s] (vx, vy)
  double birth_velocity_sigma = 3.1622776601683795;    // [m/s] per axis
  double max_birth_speed = 1000.0;                     // [m/s] kPlotPairs only

  /// A plot's likelihood is taken as 0 beyond this squared Mahalanobis distance: at 50 it is
  /// exp(-25) of its peak, far below the 1 - p_d floor of l(x) (eq. 16).
  double gate_distance_squared = 50.0;
  std::uint64_t seed = 1;
  bool operator==(const BernoulliSpec&) const = default;
};

constexpr std::string_view to_string(BirthProposal proposal) {
  return proposal == BirthProposal::kPlotPairs ? "plot_pairs" : "velocity_prior";
}

}  // namespace skytrack::bernoulli
