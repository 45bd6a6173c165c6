#include "skytrack/sim/simulator.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <Eigen/Cholesky>

#include "scenario_check.hpp"
#include "skytrack/geometry/angles.hpp"
#include "skytrack/geometry/frames.hpp"
#include "skytrack/sim/random_targets.hpp"
#include "transponder_reply.hpp"

namespace skytrack::sim {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// Rotation by a heading (clockwise from north) applied to a shape or offset defined for a
/// northbound object.
Eigen::Matrix2d heading_rotation(const Eigen::Vector3d& velocity) {
  const double heading = std::atan2(velocity.x(), velocity.y());
  const double c = std::cos(heading), s = std::sin(heading);
  Eigen::Matrix2d r;
  r << c, s, -s, c;
  return r;
}

}  // namespace

Simulator::Simulator(Scenario scenario, std::uint64_t seed)
    : scenario_(std::move(scenario)), rng_(seed) {}

Expected<Simulator> Simulator::create(Scenario scenario, std::uint64_t seed) {
  if (auto valid = check_scenario(scenario); !valid) return unexpected(valid.error());
  if (auto added = add_random_targets(scenario, seed); !added) return unexpected(added.error());
  Simulator simulator(std::move(scenario), seed);
  if (auto built = simulator.build_targets(); !built) return unexpected(built.error());
  return simulator;
}

Expected<void> Simulator::build_targets() {
  const int dims = scenario_.dimensions;
  platform_.emplace(scenario_.platform.trajectory, scenario_.start_time, dims);

  // Parents first: a child starts from its parent's state at its birth.
  std::vector<const TargetSpec*> order;
  for (const auto& spec : scenario_.targets) order.push_back(&spec);
  std::stable_sort(order.begin(), order.end(),
                   [](const TargetSpec* a, const TargetSpec* b) { return a->birth < b->birth; });
  for (const TargetSpec* spec : order) {
    KinematicState initial;
    initial.position = spec->trajectory.position;
    initial.velocity = spec->trajectory.velocity;
    if (spec->parent) {
      const auto parent = std::find_if(targets_.begin(), targets_.end(),
                                       [&](const Target& t) { return t.spec.id == *spec->parent; });
      if (parent == targets_.end()) {
        return make_error("targets: target " + std::to_string(spec->id) + " has parent " +
                          std::to_string(*spec->parent) + " that is not born before it");
      }
      const KinematicState at_birth = parent->trajectory.at(spec->birth);
      initial.position = at_birth.position + spec->offset;
      if (spec->velocity_from_parent) initial.velocity = at_birth.velocity;
    }
    Target target{*spec, Trajectory(spec->trajectory, initial, spec->birth, dims), {}};
    if (spec->kind == ObjectKind::kGroup) {
      // Member offsets: uniform in the shape ellipse, fixed for the group's life.
      const Eigen::Matrix2d root = spec->shape.llt().matrixL();
      for (int m = 0; m < spec->members; ++m) {
        target.member_offsets.push_back(root * bounded_noise(2).head<2>());
      }
    }
    targets_.push_back(std::move(target));
  }
  std::stable_sort(targets_.begin(), targets_.end(),
                   [](const Target& a, const Target& b) { return a.spec.id < b.spec.id; });

  // Reported sigmas: only the components this sensor measures, as standard deviations.
  const SensorSpec& sensor = scenario_.sensor;
  const bool three_d = dims == 3;
  const MeasurementSigma& s = sensor.sigma;
  MeasurementSigma& r = reported_sigma_;
  int measured = 0;
  if (sensor.type == SensorSpec::Type::kPolar) {
    r.range = s.range;
    r.azimuth = s.azimuth;
    const bool elevation = three_d && sensor.elevation;
    if (elevation) r.elevation = s.elevation;
    if (sensor.range_rate) r.range_rate = s.range_rate;
    measured = 2 + (elevation ? 1 : 0) + (sensor.range_rate ? 1 : 0);
  } else {
    r.x = s.x;
    r.y = s.y;
    if (three_d) r.z = s.z;
    measured = three_d ? 3 : 2;
  }
  if (sensor.noise == SensorSpec::Noise::kBounded) {
    // Uniform in a d-ball of radius a: per-component standard deviation a / sqrt(d + 2).
    const double scale = 1.0 / std::sqrt(measured + 2.0);
    for (auto* v : {&r.range, &r.azimuth, &r.elevation, &r.range_rate, &r.x, &r.y, &r.z}) {
      if (*v) **v *= scale;
    }
  }
  return {};
}

PlatformState Simulator::platform_at(double time) const {
  const KinematicState state = platform_->at(time);
  PlatformState platform;
  platform.position = state.position;
  platform.velocity = state.velocity;
  platform.attitude = scenario_.platform.attitude_follows_velocity ? attitude_from_motion(state)
                                                                   : scenario_.platform.attitude;
  return platform;
}

double Simulator::batch_time_of(double time) const {
  const SensorSpec& sensor = scenario_.sensor;
  if (sensor.antenna == SensorSpec::Antenna::kSnapshot) return time;
  const double sector = sensor.scan_period / sensor.sectors;
  const double since = time - scenario_.start_time;
  // The end of the sector the plot falls in.
  return scenario_.start_time + (std::floor(since / sector + 1e-12) + 1.0) * sector;
}

bool Simulator::alive(const Target& target, double time) const {
  return time >= target.spec.birth && time < target.spec.death;
}

Eigen::Matrix2d Simulator::shape_at(const Target& target, const KinematicState& state) const {
  if (!target.spec.shape_follows_heading) return target.spec.shape;
  const Eigen::Matrix2d r = heading_rotation(state.velocity);
  return r * target.spec.shape * r.transpose();
}

template <class PositionAt>
double Simulator::illumination_time(PositionAt position_at, double begin) const {
  // The beam is at body azimuth 2 pi (t - begin) / T; the target moves little in one sweep,
  // so a few fixed-point steps find when beam and target azimuth meet.
  const double period = scenario_.sensor.scan_period;
  double time = begin;
  for (int i = 0; i < 4; ++i) {
    const double azimuth = enu_to_polar(position_at(time), platform_at(time)).azimuth;
    time = begin + wrap_angle_positive(azimuth) / kTwoPi * period;
  }
  return std::min(time, begin + period * (1.0 - 1e-12));
}

Eigen::VectorXd Simulator::bounded_noise(int dims) {
  // Uniform in the unit d-ball: a Gaussian direction and a radius U^(1/d).
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform;
  Eigen::VectorXd direction(dims);
  for (int i = 0; i < dims; ++i) direction[i] = normal(rng_);
  const double norm = direction.norm();
  if (norm == 0.0) return Eigen::VectorXd::Zero(dims);
  return direction / norm * std::pow(uniform(rng_), 1.0 / dims);
}

std::optional<Plot> Simulator::measure(const Eigen::Vector3d& position,
                                       const Eigen::Vector3d& velocity, double time) {
  const SensorSpec& sensor = scenario_.sensor;
  // A plot is expressed relative to the platform state its batch carries (the signal
  // processor compensates its own motion), while the target is seen where it is at `time`.
  const PlatformState platform = platform_at(batch_time_of(time));
  const bool three_d = scenario_.dimensions == 3;
  const bool elevation = three_d && sensor.elevation;
  const bool bounded = sensor.noise == SensorSpec::Noise::kBounded;
  std::normal_distribution<double> normal;
  const PolarPoint polar = enu_to_polar(position, platform);
  if (polar.range < sensor.min_range || polar.range > sensor.max_range) return std::nullopt;

  Plot plot;
  if (sensor.type == SensorSpec::Type::kPolar) {
    const int dims = 2 + (elevation ? 1 : 0) + (sensor.range_rate ? 1 : 0);
    Eigen::VectorXd unit = bounded ? bounded_noise(dims) : Eigen::VectorXd(dims);
    if (!bounded) {
      for (int i = 0; i < dims; ++i) unit[i] = normal(rng_);
    }
    int k = 0;
    plot.form = PlotForm::kPolar;
    plot.range = std::max(0.0, polar.range + *sensor.sigma.range * unit[k++]);
    plot.azimuth = wrap_angle(polar.azimuth + *sensor.sigma.azimuth * unit[k++]);
    if (elevation) {
      // Noise past the zenith is the same direction seen from the other side.
      double elevation = polar.elevation + *sensor.sigma.elevation * unit[k++];
      if (std::abs(elevation) > std::numbers::pi / 2) {
        elevation = std::copysign(std::numbers::pi, elevation) - elevation;
        plot.azimuth = wrap_angle(plot.azimuth + std::numbers::pi);
      }
      plot.elevation = elevation;
    }
    if (sensor.range_rate) {
      plot.range_rate =
          range_rate(position, velocity, platform) + *sensor.sigma.range_rate * unit[k++];
    }
  } else {
    const int dims = three_d ? 3 : 2;
    Eigen::VectorXd unit = bounded ? bounded_noise(dims) : Eigen::VectorXd(dims);
    if (!bounded) {
      for (int i = 0; i < dims; ++i) unit[i] = normal(rng_);
    }
    plot.form = PlotForm::kCartesian;
    plot.x = position.x() + *sensor.sigma.x * unit[0];
    plot.y = position.y() + *sensor.sigma.y * unit[1];
    if (three_d) plot.z = position.z() + *sensor.sigma.z * unit[2];
  }
  return plot;
}

void Simulator::add_target_plots(const Target& target, double begin, std::vector<TimedPlot>& out) {
  const TargetSpec& spec = target.spec;
  const bool rotating = scenario_.sensor.antenna == SensorSpec::Antenna::kRotating;
  const double time =
      rotating
          ? illumination_time([&](double t) { return target.trajectory.at(t).position; }, begin)
          : begin;
  if (!alive(target, time)) return;
  const KinematicState state = target.trajectory.at(time);
  double pd = spec.detection_probability.value_or(scenario_.sensor.detection_probability);
  for (const DetectionWindow& window : spec.detection_windows) {
    if (time >= window.from && time < window.to) pd = window.probability;
  }
  std::bernoulli_distribution detected(pd);
  const auto emit = [&](const Eigen::Vector3d& position) {
    if (auto plot = measure(position, state.velocity, time)) {
      stamp_reply(*plot, position, scenario_.sensor, &spec);
      out.push_back({*plot, time});
    }
  };

  if (spec.kind == ObjectKind::kPoint) {
    if (detected(rng_)) emit(state.position);
    return;
  }
  if (spec.kind == ObjectKind::kGroup && spec.plot_model == TargetSpec::PlotModel::kMembers) {
    const Eigen::Matrix2d r =
        spec.shape_follows_heading ? heading_rotation(state.velocity) : Eigen::Matrix2d::Identity();
    for (const Eigen::Vector2d& offset : target.member_offsets) {
      if (!detected(rng_)) continue;
      Eigen::Vector3d position = state.position;
      position.head<2>() += r * offset;
      emit(position);
    }
    return;
  }
  // Extended objects (and Poisson groups): if detected, a Poisson number of plots scattered
  // uniformly over the shape ellipse.
  if (!detected(rng_)) return;
  std::poisson_distribution<int> count(spec.plot_rate);
  const Eigen::Matrix2d root = shape_at(target, state).llt().matrixL();
  for (int n = count(rng_); n > 0; --n) {
    Eigen::Vector3d position = state.position;
    position.head<2>() += root * bounded_noise(2);
    emit(position);
  }
}

void Simulator::add_clutter(const ClutterSpec& clutter, double begin, double end,
                            std::vector<TimedPlot>& out) {
  if (!(clutter.mean > 0.0)) return;
  const bool rotating = scenario_.sensor.antenna == SensorSpec::Antenna::kRotating;
  const bool three_d = scenario_.dimensions == 3;
  std::poisson_distribution<int> count(clutter.mean);
  const auto uniform_in = [&](const Eigen::Vector2d& interval) {
    return std::uniform_real_distribution<double>(interval[0], interval[1])(rng_);
  };
  for (int n = count(rng_); n > 0; --n) {
    Eigen::Vector3d position;
    double time = begin;
    if (clutter.region == ClutterSpec::Region::kPolar) {
      // Uniform in measurement space (range, azimuth, elevation) around the platform.
      const PolarPoint polar{uniform_in(clutter.range), uniform_in(clutter.azimuth),
                             three_d ? uniform_in(clutter.elevation) : 0.0};
      if (rotating) time = begin + wrap_angle_positive(polar.azimuth) / kTwoPi * (end - begin);
      position = polar_to_enu(polar, platform_at(time));
      if (!three_d) position.z() = 0.0;
    } else {
      position = {uniform_in(clutter.x), uniform_in(clutter.y),
                  three_d ? uniform_in(clutter.z) : 0.0};
      if (rotating) time = illumination_time([&](double) { return position; }, begin);
    }
    // Clutter comes from stationary scatterers: its range-rate is the platform's own motion.
    if (auto plot = measure(position, Eigen::Vector3d::Zero(), time)) {
      stamp_reply(*plot, position, scenario_.sensor, nullptr);
      out.push_back({*plot, time});
    }
  }
}

void Simulator::generate(double begin, double end, std::vector<TimedPlot>& out) {
  for (const Target& target : targets_) add_target_plots(target, begin, out);
  add_clutter(scenario_.clutter, begin, end, out);
  for (const ClutterSpec& patch : scenario_.clutter_patches) add_clutter(patch, begin, end, out);
}

TruthFrame Simulator::truth_at(double time) const {
  TruthFrame frame;
  frame.time = time;
  for (const Target& target : targets_) {
    if (!target.spec.in_truth || !alive(target, time)) continue;
    const KinematicState state = target.trajectory.at(time);
    TruthObject object;
    object.id = target.spec.id;
    object.kind = target.spec.kind;
    object.dims = scenario_.dimensions;
    object.position = state.position;
    object.velocity = state.velocity;
    if (target.spec.kind != ObjectKind::kPoint) object.extent = shape_at(target, state);
    if (target.spec.kind == ObjectKind::kGroup) object.members = target.spec.members;
    frame.objects.push_back(object);
  }
  return frame;
}

SimulatedBatch Simulator::make_batch(std::uint64_t number, double time,
                                     std::vector<TimedPlot> plots) {
  SimulatedBatch batch;
  PlotScan& scan = batch.plots;
  scan.sensor = scenario_.sensor.id;
  scan.scan = number;
  scan.time = time;
  scan.platform = platform_at(time);
  if (scenario_.dimensions == 2) {
    scan.platform.position.z() = 0.0;
    scan.platform.velocity.z() = 0.0;
  }
  if (scenario_.sensor.write_sigma) scan.sigma = reported_sigma_;
  // Shuffle so that plot order and ids say nothing about which plots are targets.
  std::shuffle(plots.begin(), plots.end(), rng_);
  const bool rotating = scenario_.sensor.antenna == SensorSpec::Antenna::kRotating;
  scan.plots.reserve(plots.size());
  for (std::size_t i = 0; i < plots.size(); ++i) {
    Plot plot = plots[i].plot;
    plot.id = static_cast<std::int64_t>(i);
    if (rotating) plot.time = plots[i].time;
    scan.plots.push_back(std::move(plot));
  }
  batch.truth = truth_at(time);
  return batch;
}

std::optional<SimulatedBatch> Simulator::next() {
  if (!pending_.empty()) {
    SimulatedBatch batch = std::move(pending_.front());
    pending_.pop_front();
    return batch;
  }
  const SensorSpec& sensor = scenario_.sensor;
  const double period = sensor.scan_period;
  const double stop = scenario_.start_time + scenario_.duration + 1e-9;
  const double begin = scenario_.start_time + static_cast<double>(period_) * period;
  std::vector<TimedPlot> plots;
  if (sensor.antenna == SensorSpec::Antenna::kSnapshot) {
    if (begin > stop) return std::nullopt;
    ++period_;
    generate(begin, begin, plots);
    return make_batch(next_scan_++, begin, std::move(plots));
  }
  const double end = begin + period;
  if (end > stop) return std::nullopt;
  ++period_;
  generate(begin, end, plots);
  // Split the revolution into sectors by plot time; each batch is stamped with its end.
  const double sector = period / sensor.sectors;
  std::vector<std::vector<TimedPlot>> by_sector(static_cast<std::size_t>(sensor.sectors));
  for (TimedPlot& plot : plots) {
    const int index =
        std::clamp(static_cast<int>((plot.time - begin) / sector), 0, sensor.sectors - 1);
    by_sector[static_cast<std::size_t>(index)].push_back(std::move(plot));
  }
  for (int s = 0; s < sensor.sectors; ++s) {
    const double time = s + 1 == sensor.sectors ? end : begin + (s + 1) * sector;
    SimulatedBatch batch =
        make_batch(next_scan_++, time, std::move(by_sector[static_cast<std::size_t>(s)]));
    if (sensor.sectors > 1) {  // the beam swept [s, s + 1) / sectors of a turn from the nose
      batch.plots.coverage = AzimuthSector{wrap_angle(kTwoPi * s / sensor.sectors),
                                           wrap_angle(kTwoPi * (s + 1) / sensor.sectors)};
    }
    pending_.push_back(std::move(batch));
  }
  return next();
}

}  // namespace skytrack::sim
