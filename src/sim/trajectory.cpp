#include "skytrack/sim/trajectory.hpp"

#include <algorithm>
#include <cmath>

namespace skytrack::sim {

KinematicState propagate(const KinematicState& start, double dt, double turn_rate,
                         const Eigen::Vector3d& acceleration) {
  KinematicState out = start;
  out.turn_rate = turn_rate;
  if (std::abs(turn_rate) > 1e-12) {
    // Horizontal velocity rotates anticlockwise by w*dt; position integrates it exactly.
    const double w = turn_rate, s = std::sin(w * dt), c = std::cos(w * dt);
    const double vx = start.velocity.x(), vy = start.velocity.y();
    out.position.x() += (vx * s - vy * (1.0 - c)) / w;
    out.position.y() += (vx * (1.0 - c) + vy * s) / w;
    out.position.z() += start.velocity.z() * dt;
    out.velocity.x() = vx * c - vy * s;
    out.velocity.y() = vx * s + vy * c;
  } else {
    out.position += start.velocity * dt + 0.5 * acceleration * dt * dt;
    out.velocity += acceleration * dt;
  }
  return out;
}

Trajectory::Trajectory(const TrajectorySpec& spec, double start_time, int dimensions)
    : start_time_(start_time) {
  KinematicState initial;
  initial.position = spec.position;
  initial.velocity = spec.velocity;
  build(spec, initial, dimensions);
}

Trajectory::Trajectory(const TrajectorySpec& spec, const KinematicState& initial, double start_time,
                       int dimensions)
    : start_time_(start_time) {
  build(spec, initial, dimensions);
}

void Trajectory::build(const TrajectorySpec& spec, const KinematicState& initial, int dimensions) {
  KinematicState state = initial;
  state.turn_rate = 0.0;
  if (dimensions == 2) {
    state.position.z() = 0.0;
    state.velocity.z() = 0.0;
  }
  double time = start_time_;
  for (const SegmentSpec& segment : spec.segments) {
    Piece piece;
    piece.start = time;
    piece.state = state;
    using Type = SegmentSpec::Type;
    if (segment.type == Type::kCoordinatedTurn) {
      if (segment.turn_rate) {
        piece.turn_rate = *segment.turn_rate;
      } else {
        // Load factor n: centripetal acceleration n g = w v.
        const double speed = state.velocity.head<2>().norm();
        const double rate = speed > 0.0 ? segment.g_load.value_or(0.0) * kGravity / speed : 0.0;
        piece.turn_rate = segment.turn_left ? rate : -rate;
      }
    } else if (segment.type == Type::kConstantAcceleration) {
      piece.acceleration = segment.acceleration;
      if (dimensions == 2) piece.acceleration.z() = 0.0;
    }
    pieces_.push_back(piece);
    state = propagate(state, segment.duration, piece.turn_rate, piece.acceleration);
    state.turn_rate = 0.0;
    time += segment.duration;
  }
  Piece tail;  // constant velocity after the last manoeuvre
  tail.start = time;
  tail.state = state;
  pieces_.push_back(tail);
}

KinematicState Trajectory::at(double time) const {
  // The last piece starting at or before `time` (the first one for earlier times).
  auto it = std::upper_bound(pieces_.begin(), pieces_.end(), time,
                             [](double t, const Piece& p) { return t < p.start; });
  const Piece& piece = it == pieces_.begin() ? pieces_.front() : *std::prev(it);
  return propagate(piece.state, time - piece.start, piece.turn_rate, piece.acceleration);
}

Eigen::Vector3d attitude_from_motion(const KinematicState& state) {
  const double horizontal = state.velocity.head<2>().norm();
  if (horizontal == 0.0 && state.velocity.z() == 0.0) return Eigen::Vector3d::Zero();
  const double heading = std::atan2(state.velocity.x(), state.velocity.y());
  const double pitch = std::atan2(state.velocity.z(), horizontal);
  // A left turn (positive rate) banks the left wing down: negative roll.
  const double roll = -std::atan(state.turn_rate * horizontal / kGravity);
  return {heading, pitch, roll};
}

}  // namespace skytrack::sim
