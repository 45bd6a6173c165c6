#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "skytrack/sim/trajectory.hpp"

namespace skytrack::sim {
namespace {

TEST(Trajectory, LoadFactorTurnHasRadiusVSquaredOverNG) {
  // GIVEN 300 m/s eastbound entering a 4 g left turn (paper 003's manoeuvre)
  TrajectorySpec spec;
  spec.velocity = {300.0, 0.0, 0.0};
  SegmentSpec turn;
  turn.type = SegmentSpec::Type::kCoordinatedTurn;
  turn.duration = 60.0;
  turn.g_load = 4.0;
  turn.turn_left = true;
  spec.segments = {turn};
  const Trajectory trajectory(spec, 0.0, 2);
  // THEN every point lies on the circle of radius v^2 / (n g) centred left of the entry
  const double radius = 300.0 * 300.0 / (4.0 * kGravity);
  const Eigen::Vector2d centre(0.0, radius);
  for (double t = 0.0; t < 60.0; t += 1.5) {
    const KinematicState s = trajectory.at(t);
    EXPECT_NEAR((s.position.head<2>() - centre).norm(), radius, 1e-6) << "t=" << t;
    EXPECT_NEAR(s.velocity.head<2>().norm(), 300.0, 1e-9);
    EXPECT_NEAR(s.turn_rate, 4.0 * kGravity / 300.0, 1e-12);
  }
}

TEST(Trajectory, RightTurnRateIsNegativeAndPositiveRateTurnsAnticlockwise) {
  TrajectorySpec spec;
  spec.velocity = {0.0, 100.0, 0.0};  // northbound
  SegmentSpec turn;
  turn.type = SegmentSpec::Type::kCoordinatedTurn;
  turn.duration = 10.0;
  turn.turn_rate = std::numbers::pi / 20.0;  // 90 deg in 10 s, to the left
  spec.segments = {turn};
  const KinematicState s = Trajectory(spec, 0.0, 2).at(10.0);
  EXPECT_NEAR(s.velocity.x(), -100.0, 1e-9);  // now westbound
  EXPECT_NEAR(s.velocity.y(), 0.0, 1e-9);
}

TEST(Trajectory, SegmentsChainAndEndInConstantVelocity) {
  TrajectorySpec spec;
  spec.position = {10.0, 20.0, 1000.0};
  spec.velocity = {100.0, 0.0, 0.0};
  SegmentSpec cv;
  cv.duration = 10.0;
  SegmentSpec ca;
  ca.type = SegmentSpec::Type::kConstantAcceleration;
  ca.duration = 5.0;
  ca.acceleration = {2.0, 0.0, 1.0};
  spec.segments = {cv, ca};
  const Trajectory trajectory(spec, 100.0, 3);  // starts at t = 100 s
  EXPECT_NEAR(trajectory.at(110.0).position.x(), 1010.0, 1e-9);
  const KinematicState end = trajectory.at(115.0);
  EXPECT_NEAR(end.position.x(), 1010.0 + 100.0 * 5 + 0.5 * 2.0 * 25, 1e-9);
  EXPECT_NEAR(end.position.z(), 1000.0 + 0.5 * 1.0 * 25, 1e-9);
  EXPECT_NEAR(end.velocity.x(), 110.0, 1e-9);
  const KinematicState later = trajectory.at(125.0);  // constant velocity after
  EXPECT_NEAR(later.position.x(), end.position.x() + 1100.0, 1e-9);
  EXPECT_NEAR(later.velocity.z(), 5.0, 1e-9);
}

TEST(Trajectory, AttitudeFollowsHeadingAndBanksIntoTheTurn) {
  KinematicState s;
  s.velocity = {200.0, 0.0, 0.0};  // east
  s.turn_rate = 0.05;              // left
  const Eigen::Vector3d attitude = attitude_from_motion(s);
  EXPECT_NEAR(attitude[0], std::numbers::pi / 2, 1e-12);
  EXPECT_NEAR(attitude[1], 0.0, 1e-12);
  EXPECT_NEAR(attitude[2], -std::atan(0.05 * 200.0 / kGravity), 1e-12);
}

}  // namespace
}  // namespace skytrack::sim
