#pragma once
// Analytic piecewise motion: constant velocity, horizontal coordinated turn (constant rate,
// vertical velocity kept) and constant acceleration, evaluated exactly at any time.
#include <vector>

#include <Eigen/Core>

#include "skytrack/sim/scenario.hpp"

namespace skytrack::sim {

/// Position, velocity and turn rate at one time.
struct KinematicState {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  double turn_rate = 0.0;  // [rad/s] of the active segment, positive = left
};

/// Standard gravity [m/s^2], for load-factor turns.
inline constexpr double kGravity = 9.80665;

/// Moves a state `dt` seconds with a turn rate (0: straight) and an acceleration.
KinematicState propagate(const KinematicState& start, double dt, double turn_rate,
                         const Eigen::Vector3d& acceleration);

class Trajectory {
 public:
  /// Starts at `start_time` in `spec`'s initial state; 2-D trajectories keep z = 0.
  Trajectory(const TrajectorySpec& spec, double start_time, int dimensions);
  Trajectory(const TrajectorySpec& spec, const KinematicState& initial, double start_time,
             int dimensions);

  KinematicState at(double time) const;
  double start_time() const { return start_time_; }

 private:
  struct Piece {
    double start = 0.0;
    KinematicState state;
    double turn_rate = 0.0;
    Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();
  };
  void build(const TrajectorySpec& spec, const KinematicState& initial, int dimensions);

  double start_time_ = 0.0;
  std::vector<Piece> pieces_;
};

/// Heading (clockwise from north), pitch and coordinated-turn roll of a platform in flight.
Eigen::Vector3d attitude_from_motion(const KinematicState& state);

}  // namespace skytrack::sim
