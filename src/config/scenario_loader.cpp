#include "skytrack/config/scenario_loader.hpp"

#include <cmath>
#include <set>

#include "skytrack/config/yaml_section.hpp"
#include "skytrack/core/transponder.hpp"

namespace skytrack::config {
namespace {

using sim::ClutterSpec;
using sim::Scenario;
using sim::SegmentSpec;
using sim::SensorSpec;
using sim::TargetSpec;
using sim::TrajectorySpec;

/// A 2- or 3-component vector (2-D scenarios may omit z).
void read_vector(YamlSection& s, std::string_view key, Eigen::Vector3d& out, int dimensions,
                 bool required = false) {
  std::vector<double> values;
  if (dimensions == 3) {
    s.numbers(key, values, {2, 3}, {}, required);
  } else {
    s.numbers(key, values, {2}, {}, required);
  }
  if (values.empty()) return;
  out = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < values.size(); ++i) out[static_cast<Eigen::Index>(i)] = values[i];
}

void read_interval(YamlSection& s, std::string_view key, Eigen::Vector2d& out) {
  std::vector<double> values;
  s.numbers(key, values, {2});
  if (values.empty()) return;
  if (values[0] > values[1]) return s.error(key, "expected [min, max] with min <= max");
  out = {values[0], values[1]};
}

SegmentSpec read_segment(YamlSection s, int dimensions) {
  SegmentSpec segment;
  std::string type = "cv";
  s.choice("type", type, {"cv", "ct", "ca"}, true);
  s.number("duration", segment.duration, Range::non_negative(), true);
  if (type == "ct") {
    segment.type = SegmentSpec::Type::kCoordinatedTurn;
    s.number("turn_rate", segment.turn_rate);
    s.number("g", segment.g_load, Range::non_negative());
    std::string direction = "left";
    s.choice("direction", direction, {"left", "right"});
    segment.turn_left = direction == "left";
    if (segment.turn_rate.has_value() == segment.g_load.has_value()) {
      s.error("turn_rate", "a ct segment needs exactly one of turn_rate [rad/s] or g");
    }
    if (segment.turn_rate && s.has("direction")) {
      s.error("direction", "the sign of turn_rate gives the direction (positive = left)");
    }
  } else if (type == "ca") {
    segment.type = SegmentSpec::Type::kConstantAcceleration;
    read_vector(s, "acceleration", segment.acceleration, dimensions, true);
  }
  s.finish();
  return segment;
}

TrajectorySpec read_trajectory(YamlSection& s, int dimensions, bool position_required) {
  TrajectorySpec trajectory;
  read_vector(s, "position", trajectory.position, dimensions, position_required);
  read_vector(s, "velocity", trajectory.velocity, dimensions);
  for (auto& segment : s.sections("segments")) {
    trajectory.segments.push_back(read_segment(std::move(segment), dimensions));
  }
  return trajectory;
}

Eigen::Matrix2d read_shape(YamlSection& s, std::string_view key) {
  std::vector<std::vector<double>> rows;
  s.matrix(key, rows, true);
  if (rows.empty()) return Eigen::Matrix2d::Identity();
  if (rows.size() != 2 || rows[0].size() != 2) {
    s.error(key, "expected a 2x2 matrix [[a, b], [b, c]]");
    return Eigen::Matrix2d::Identity();
  }
  Eigen::Matrix2d m;
  m << rows[0][0], rows[0][1], rows[1][0], rows[1][1];
  if (std::abs(m(0, 1) - m(1, 0)) > 1e-9 * (1.0 + m.cwiseAbs().maxCoeff()) || !(m(0, 0) > 0.0) ||
      !(m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0) > 0.0)) {
    s.error(key, "expected a symmetric positive-definite shape matrix [m^2]");
  }
  return m;
}

void read_transponder(YamlSection& s, TargetSpec& target) {
  std::string code;
  s.text("mode3a", code);
  if (s.has("mode3a")) {
    target.mode3a = parse_mode3a(code);
    if (!target.mode3a) s.error("mode3a", "expected 4 octal digits as a string (\"2270\")");
  }
  s.text("mode_s", code);
  if (s.has("mode_s")) {
    target.mode_s = parse_mode_s(code);
    if (!target.mode_s) s.error("mode_s", "expected 6 hex digits as a string (\"4CA2D7\")");
  }
  s.boolean("reports_altitude", target.reports_altitude);
}

TargetSpec read_target(YamlSection s, const Scenario& scenario) {
  TargetSpec target;
  s.integer("id", target.id, Range::non_negative(), true);
  std::string kind = "point";
  s.choice("kind", kind, {"point", "group", "extended"});
  target.kind = *parse_object_kind(kind);
  s.number("birth", target.birth);
  s.number("death", target.death);
  if (target.death <= target.birth) s.error("death", "must be after birth");
  std::int64_t parent = -1;
  s.integer("parent", parent, Range::non_negative());
  if (parent >= 0) target.parent = parent;
  read_vector(s, "offset", target.offset, scenario.dimensions);
  if (!target.parent && s.has("offset")) s.error("offset", "an offset needs a parent");
  target.velocity_from_parent = target.parent && !s.has("velocity");
  target.trajectory = read_trajectory(s, scenario.dimensions, !target.parent);
  if (target.parent && s.has("position")) {
    s.error("position", "a target with a parent starts at the parent's position; use offset");
  }
  s.number("detection_probability", target.detection_probability, Range::probability());
  for (auto& w : s.sections("detection_windows")) {
    sim::DetectionWindow window;
    w.number("from", window.from, {}, true);
    w.number("to", window.to, {}, true);
    w.number("probability", window.probability, Range::probability(), true);
    if (!(window.to > window.from)) w.error("to", "must be after from");
    w.finish();
    target.detection_windows.push_back(window);
  }
  s.boolean("truth", target.in_truth);
  read_transponder(s, target);
  if (target.kind != ObjectKind::kPoint) {
    target.shape = read_shape(s, "shape");
    s.boolean("shape_follows_heading", target.shape_follows_heading);
  }
  if (target.kind == ObjectKind::kGroup) {
    std::string plots = "members";
    s.choice("plots", plots, {"members", "poisson"});
    target.plot_model =
        plots == "members" ? TargetSpec::PlotModel::kMembers : TargetSpec::PlotModel::kPoisson;
    // With Poisson plots the member count is only reported in the truth.
    s.integer("members", target.members, Range{1.0},
              target.plot_model == TargetSpec::PlotModel::kMembers);
    s.number("plot_rate", target.plot_rate, Range::non_negative(),
             target.plot_model == TargetSpec::PlotModel::kPoisson);
  } else if (target.kind == ObjectKind::kExtended) {
    s.number("plot_rate", target.plot_rate, Range::non_negative(), true);
  }
  s.finish();
  return target;
}

void read_sigma(YamlSection s, MeasurementSigma& sigma) {
  s.number("range", sigma.range, Range::positive());
  s.number("azimuth", sigma.azimuth, Range::positive());
  s.number("elevation", sigma.elevation, Range::positive());
  s.number("range_rate", sigma.range_rate, Range::positive());
  s.number("x", sigma.x, Range::positive());
  s.number("y", sigma.y, Range::positive());
  s.number("z", sigma.z, Range::positive());
  s.finish();
}

SensorSpec read_sensor(YamlSection s) {
  SensorSpec sensor;
  std::int64_t id = 0;
  s.integer("id", id, Range{0.0, 4294967295.0});
  sensor.id = static_cast<std::uint32_t>(id);
  std::string type = "polar";
  s.choice("type", type, {"polar", "cartesian"});
  sensor.type = type == "polar" ? SensorSpec::Type::kPolar : SensorSpec::Type::kCartesian;
  s.number("scan_period", sensor.scan_period, Range::positive(), true);
  std::string antenna = "snapshot";
  s.choice("antenna", antenna, {"snapshot", "rotating"});
  sensor.antenna =
      antenna == "snapshot" ? SensorSpec::Antenna::kSnapshot : SensorSpec::Antenna::kRotating;
  s.integer("sectors", sensor.sectors, Range{1.0, 360.0});
  if (sensor.sectors > 1 && sensor.antenna != SensorSpec::Antenna::kRotating) {
    s.error("sectors", "sector batches need antenna: rotating");
  }
  s.number("detection_probability", sensor.detection_probability, Range::probability());
  s.number("min_range", sensor.min_range, Range::non_negative());
  s.number("max_range", sensor.max_range, Range::positive());
  if (!(sensor.max_range > sensor.min_range)) s.error("max_range", "must exceed min_range");
  s.boolean("range_rate", sensor.range_rate);
  s.boolean("elevation", sensor.elevation);
  s.number("flight_level_step", sensor.flight_level_step, Range::non_negative());
  read_sigma(s.section("sigma", true), sensor.sigma);
  std::string noise = "gaussian";
  s.choice("noise", noise, {"gaussian", "bounded"});
  sensor.noise = noise == "gaussian" ? SensorSpec::Noise::kGaussian : SensorSpec::Noise::kBounded;
  s.boolean("write_sigma", sensor.write_sigma);
  s.finish();
  return sensor;
}

ClutterSpec read_clutter(YamlSection s, const SensorSpec& sensor, int dimensions) {
  ClutterSpec clutter;
  s.number("mean", clutter.mean, Range::non_negative());
  std::string region = "polar";
  s.choice("region", region, {"polar", "box"});
  if (region == "polar") {
    clutter.region = ClutterSpec::Region::kPolar;
    clutter.range = {sensor.min_range, sensor.max_range};
    read_interval(s, "range", clutter.range);
    read_interval(s, "azimuth", clutter.azimuth);
    read_interval(s, "elevation", clutter.elevation);
    if (clutter.mean > 0.0 && !std::isfinite(clutter.range[1])) {
      s.error("range", "a polar clutter region needs a range interval (or sensor.max_range)");
    }
    if (clutter.mean > 0.0 && dimensions == 3 && !s.has("elevation")) {
      s.error("elevation", "a 3-D polar clutter region needs an elevation interval [rad]");
    }
  } else {
    clutter.region = ClutterSpec::Region::kBox;
    read_interval(s, "x", clutter.x);
    read_interval(s, "y", clutter.y);
    read_interval(s, "z", clutter.z);
  }
  s.finish();
  return clutter;
}

sim::RandomTargetsSpec read_random_targets(YamlSection s, int dimensions) {
  sim::RandomTargetsSpec spec;
  s.integer("count", spec.count, Range{1.0, 1000000.0}, true);
  for (const char* axis : {"x", "y"}) {
    if (!s.has(axis)) s.error(axis, "missing required key: the box [min, max] [m]");
  }
  read_interval(s, "x", spec.x);
  read_interval(s, "y", spec.y);
  read_interval(s, "z", spec.z);
  if (dimensions == 3 && !s.has("z")) s.error("z", "missing required key in a 3-D scenario");
  if (dimensions == 2 && s.has("z")) s.error("z", "only in a 3-D scenario");
  s.number("velocity_sigma", spec.velocity_sigma, Range::non_negative());
  s.number("acceleration_noise", spec.acceleration_noise, Range::non_negative());
  s.number("step", spec.step, Range::positive());
  s.integer("first_id", spec.first_id, Range::non_negative());
  s.finish();
  return spec;
}

Expected<Scenario> read_scenario(const YAML::Node& root, ErrorList& errors) {
  YamlSection top(root, "", errors);
  Scenario scenario;
  {
    YamlSection s = top.section("scenario", true);
    s.text("name", scenario.name, true);
    s.text("description", scenario.description);
    s.integer("dimensions", scenario.dimensions, Range{2.0, 3.0});
    s.number("start_time", scenario.start_time);
    s.number("duration", scenario.duration, Range::non_negative(), true);
    std::int64_t seed = 1;
    s.integer("seed", seed, Range::non_negative());
    scenario.seed = static_cast<std::uint64_t>(seed);
    s.finish();
  }
  {
    YamlSection s = top.section("platform");
    scenario.platform.trajectory = read_trajectory(s, scenario.dimensions, false);
    std::vector<double> attitude;
    s.numbers("attitude", attitude, {3});
    if (!attitude.empty()) scenario.platform.attitude = {attitude[0], attitude[1], attitude[2]};
    s.boolean("attitude_follows_velocity", scenario.platform.attitude_follows_velocity);
    if (!attitude.empty() && scenario.platform.attitude_follows_velocity) {
      s.error("attitude", "give attitude or attitude_follows_velocity, not both");
    }
    s.finish();
  }
  scenario.sensor = read_sensor(top.section("sensor", true));
  scenario.clutter = read_clutter(top.section("clutter"), scenario.sensor, scenario.dimensions);
  for (auto& patch : top.sections("clutter_patches")) {
    scenario.clutter_patches.push_back(
        read_clutter(std::move(patch), scenario.sensor, scenario.dimensions));
  }
  std::set<std::int64_t> ids;
  for (auto& section : top.sections("targets")) {
    const std::string path = section.path();
    scenario.targets.push_back(read_target(std::move(section), scenario));
    if (!ids.insert(scenario.targets.back().id).second) {
      errors.add(root["targets"], path + ".id",
                 "duplicate target id " + std::to_string(scenario.targets.back().id));
    }
  }
  if (top.has("random_targets")) {
    scenario.random_targets =
        read_random_targets(top.section("random_targets"), scenario.dimensions);
  }
  for (const auto& target : scenario.targets) {
    if (target.parent && !ids.count(*target.parent)) {
      errors.add(root["targets"], "targets",
                 "target " + std::to_string(target.id) + " names parent " +
                     std::to_string(*target.parent) + " that is not in the list");
    }
  }
  top.finish();
  if (!errors.empty()) return make_error(errors.joined());
  return scenario;
}

}  // namespace

Expected<sim::Scenario> load_scenario(const std::string& path) {
  ErrorList errors(path);
  const auto root = load_yaml_file(path, errors);
  if (!root) return make_error(errors.joined());
  return read_scenario(*root, errors);
}

Expected<sim::Scenario> parse_scenario(const std::string& yaml_text, const std::string& name) {
  ErrorList errors(name);
  try {
    return read_scenario(YAML::Load(yaml_text), errors);
  } catch (const YAML::ParserException& e) {
    errors.add(YAML::Node(), "", "line " + std::to_string(e.mark.line + 1) + ": " + e.msg);
    return make_error(errors.joined());
  }
}

}  // namespace skytrack::config
