#pragma once
// Fusion of tracks whose errors are correlated by an unknown amount (common process noise,
// common prior): covariance intersection (Julier & Uhlmann 1997) with the fast, non-iterative
// weights of Niehsen 2002 generalised to N tracks (Franken & Hupper 2005):
//   w_i = (1 / tr P_i) / sum_j (1 / tr P_j),  P^-1 = sum_i w_i P_i^-1,  x = P sum_i w_i P_i^-1 x_i
// consistent for any cross-correlation, where the Kalman track fusion assumes none.
#include <span>

#include <Eigen/Core>

namespace skytrack::fusion {

/// A track state in the order [x, vx, y, vy, z, vz] (2-D: z, vz zero and unused), local ENU.
struct StateEstimate {
  using Vec = Eigen::Matrix<double, 6, 1>;
  using Mat = Eigen::Matrix<double, 6, 6>;
  Vec x = Vec::Zero();
  Mat P = Mat::Identity();
  int dims = 2;  // 2 or 3
};

struct FusedEstimate {
  StateEstimate estimate;
  bool ok = false;  // false when a covariance was not positive definite (nothing fused)
};

/// Fast CI over the tracks (at least one). 3-D when every track is; with mixed 2-D and 3-D
/// tracks the horizontal part is fused from all and the height from the 3-D ones only.
FusedEstimate covariance_intersection(std::span<const StateEstimate> tracks) noexcept;

/// Constant-velocity prediction by dt [s] with white-noise acceleration psd q [m^2/s^3].
StateEstimate predict_cv(const StateEstimate& s, double dt, double accel_psd) noexcept;

}  // namespace skytrack::fusion
