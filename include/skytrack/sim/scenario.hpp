#pragma once
// A simulated scenario: targets on piecewise manoeuvres, a (possibly airborne) sensor
// platform, a polar or Cartesian sensor and Poisson clutter. Plain data; the YAML schema is in
// docs/scenarios.md and the loader in config/scenario_loader.hpp.
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "skytrack/core/plot.hpp"
#include "skytrack/core/truth.hpp"

namespace skytrack::sim {

/// One manoeuvre of a trajectory. Turns are horizontal; the vertical velocity is kept.
struct SegmentSpec {
  enum class Type : std::uint8_t { kConstantVelocity, kCoordinatedTurn, kConstantAcceleration };
  Type type = Type::kConstantVelocity;
  double duration = 0.0;  // [s]
  /// Coordinated turn: signed rate [rad/s], positive = left (anticlockwise from above), or a
  /// load factor [g] turned into a rate with the speed at the start of the segment.
  std::optional<double> turn_rate;
  std::optional<double> g_load;
  bool turn_left = true;                                   // with g_load
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();  // [m/s^2] constant acceleration
};

/// Initial state and manoeuvres; after the last segment the motion is constant velocity.
struct TrajectorySpec {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // [m]
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // [m/s]
  std::vector<SegmentSpec> segments;
};

/// A time window [from, to) in which a target's detection probability is overridden, e.g. to
/// script consecutive missed detections.
struct DetectionWindow {
  double from = 0.0;  // [s]
  double to = 0.0;    // [s]
  double probability = 0.0;
};

struct TargetSpec {
  std::int64_t id = 0;
  ObjectKind kind = ObjectKind::kPoint;
  double birth = 0.0;                                      // [s]
  double death = std::numeric_limits<double>::infinity();  // [s]
  TrajectorySpec trajectory;
  /// Born at the parent's position (plus offset) at `birth`: a split or a spawned target.
  std::optional<std::int64_t> parent;
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  bool velocity_from_parent = false;  // a child without its own velocity keeps the parent's
  std::optional<double> detection_probability;     // overrides the sensor's
  std::vector<DetectionWindow> detection_windows;  // override both within their windows
  /// False for scripted false plots (a decoy or a planted false alarm): the object makes plots
  /// but never appears in the truth.
  bool in_truth = true;
  // Groups: `members` targets at fixed offsets drawn uniformly in the `shape` ellipse.
  // Extended objects: plots scattered uniformly over the `shape` ellipse.
  int members = 0;
  Eigen::Matrix2d shape = Eigen::Matrix2d::Identity();  // [m^2] SPD shape matrix X
  enum class PlotModel : std::uint8_t { kMembers, kPoisson };
  PlotModel plot_model = PlotModel::kMembers;  // groups: each member detected, or Poisson
  double plot_rate = 0.0;  // Poisson mean of plots per scan (extended, or group kPoisson)
  bool shape_follows_heading = false;  // rotate the shape with the velocity heading
  // Transponder: identities written on every plot of the target, and whether its replies
  // carry its altitude (with a sensor that reports flight levels).
  std::optional<std::uint16_t> mode3a;
  std::optional<std::uint32_t> mode_s;
  bool reports_altitude = true;
};

struct PlatformSpec {
  TrajectorySpec trajectory;
  Eigen::Vector3d attitude = Eigen::Vector3d::Zero();  // [rad] heading, pitch, roll
  /// Heading and pitch from the velocity, roll from the turn rate (coordinated bank angle).
  bool attitude_follows_velocity = false;
};

struct SensorSpec {
  std::uint32_t id = 0;
  enum class Type : std::uint8_t { kPolar, kCartesian };
  Type type = Type::kPolar;
  double scan_period = 1.0;  // [s]
  enum class Antenna : std::uint8_t { kSnapshot, kRotating };
  Antenna antenna = Antenna::kSnapshot;
  int sectors = 1;  // rotating antenna: batches per revolution
  double detection_probability = 1.0;
  double min_range = 0.0;                                      // [m]
  double max_range = std::numeric_limits<double>::infinity();  // [m]
  bool range_rate = false;                                     // polar sensors: report range-rate
  bool elevation = true;  // 3-D polar sensors: report elevation (false: a secondary radar)
  /// > 0: target plots carry their altitude as a flight level rounded to this step [100 ft]
  /// (1: Mode C, 0.25: Mode S), and clutter plots the altitude of their false position.
  double flight_level_step = 0.0;
  MeasurementSigma sigma;  // noise standard deviations (or ellipsoid semi-axes if bounded)
  enum class Noise : std::uint8_t { kGaussian, kBounded };
  Noise noise = Noise::kGaussian;
  bool write_sigma = true;  // put `sigma` in each scan line
};

struct ClutterSpec {
  double mean = 0.0;  // Poisson mean of clutter plots per revolution / snapshot
  enum class Region : std::uint8_t { kPolar, kBox };
  Region region = Region::kPolar;
  // Polar region in the platform body frame [min, max]: range [m], azimuth, elevation [rad].
  Eigen::Vector2d range{0.0, 0.0};
  Eigen::Vector2d azimuth{-3.141592653589793, 3.141592653589793};
  Eigen::Vector2d elevation{0.0, 0.0};
  // Box region in the tracking frame [min, max] per axis [m].
  Eigen::Vector2d x{0.0, 0.0}, y{0.0, 0.0}, z{0.0, 0.0};
};

/// A population drawn at simulation time from the run's seed (so `--seed` draws another):
/// `count` point targets born at the start, positions uniform in the box, velocities zero-mean
/// normal per axis, and a random acceleration held constant over each `step` with variance
/// q / step per axis, so that the velocity diffuses as under white-noise acceleration of
/// spectral density q (the constant-velocity truth of a nearly-constant-velocity model).
struct RandomTargetsSpec {
  int count = 0;
  Eigen::Vector2d x{0.0, 0.0}, y{0.0, 0.0}, z{0.0, 0.0};  // [m] box [min, max] per axis
  double velocity_sigma = 0.0;                            // [m/s] per axis
  double acceleration_noise = 0.0;                        // q [m^2/s^3]
  double step = 1.0;                                      // [s]
  std::int64_t first_id = 1;                              // ids first_id, first_id + 1, ...
};

struct Scenario {
  std::string name;
  std::string description;
  int dimensions = 2;
  double start_time = 0.0;  // [s]
  double duration = 0.0;    // [s]
  std::uint64_t seed = 1;
  PlatformSpec platform;
  SensorSpec sensor;
  ClutterSpec clutter;                       // background clutter
  std::vector<ClutterSpec> clutter_patches;  // extra Poisson regions, e.g. a dense patch
  std::vector<TargetSpec> targets;
  std::optional<RandomTargetsSpec> random_targets;  // added to `targets` by the simulator
};

}  // namespace skytrack::sim
