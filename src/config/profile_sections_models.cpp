// The profile sections of what is measured and how it moves: identity, measurement, motion
// models, antenna, association and clutter rejection.
#include <cmath>
#include <numbers>
#include <optional>

#include "profile_sections.hpp"

namespace skytrack::config::detail {

ProfileIdentity read_identity(YamlSection s) {
  ProfileIdentity identity;
  s.text("name", identity.name, true);
  s.text("version", identity.version, true);
  s.text("description", identity.description);
  if (s.has("name") && identity.name.empty()) s.error("name", "expected a non-empty name");
  s.finish();
  return identity;
}

// Physical limits shared by sections: no tracked object flies faster than 20 km/s (re-entry
// is about 8 km/s) or pulls more than 1000 m/s^2 (about 100 g).
MeasurementSpec read_measurement(YamlSection s) {
  MeasurementSpec m;
  read_enum(s, "update", m.update, {MeasurementUpdate::kEkf, MeasurementUpdate::kUnscented});
  // alpha from Wan & van der Merwe's [1e-4, 1]; beta and kappa of a few units in the
  // literature. A smaller alpha or larger kappa collapses the sigma points or spreads them
  // past the double range; a huge beta overflows S.
  YamlSection ut = s.section("unscented");
  ut.number("alpha", m.unscented.alpha, Range{1e-4, 1.0});
  ut.number("beta", m.unscented.beta, Range{0.0, 100.0});
  ut.number("kappa", m.unscented.kappa, Range{0.0, 100.0});
  ut.finish();
  // A millimetre to 100 km, a microradian to a half turn, a millimetre per second to the
  // fastest target: a sigma outside squares to 0 (a singular R) or overflows.
  const Range metres{1e-3, 1e5}, radians{1e-6, std::numbers::pi}, speed{1e-3, kMaxSpeed};
  YamlSection sigma = s.section("default_sigma");
  sigma.number("range", m.default_sigma.range, metres);
  sigma.number("azimuth", m.default_sigma.azimuth, radians);
  sigma.number("elevation", m.default_sigma.elevation, radians);
  sigma.number("range_rate", m.default_sigma.range_rate, speed);
  sigma.number("x", m.default_sigma.x, metres);
  sigma.number("y", m.default_sigma.y, metres);
  sigma.number("z", m.default_sigma.z, metres);
  sigma.number("height", m.default_sigma.height, metres);
  sigma.finish();
  s.finish();
  return m;
}

void read_turn_rate(YamlSection& s, double& turn_rate) {
  s.number("turn_rate", turn_rate, {}, true);
  if (!s.has("turn_rate")) return;
  if (turn_rate == 0.0) {
    s.error("turn_rate", "expected a non-zero rate [rad/s] (zero is constant_velocity), got 0");
  } else if (std::abs(turn_rate) > 1.0) {
    // 1 rad/s is 57 deg/s: a larger value is almost surely degrees per second.
    s.error("turn_rate", "expected |turn_rate| <= 1 rad/s, got " + show(turn_rate) +
                             " (is it in deg/s? the unit is rad/s)");
  }
}

/// Reads the keys of the model's type, each of them required; with an unreadable type it
/// reads every parameter optionally so that only truly unknown keys are reported.
MotionModelSpec read_motion_model(YamlSection& s) {
  using T = MotionModelType;
  MotionModelSpec m;
  s.text("name", m.name, true);
  if (s.has("name") && m.name.empty()) s.error("name", "expected a non-empty name");
  const bool typed = read_enum(s, "type", m.type,
                               {T::kConstantVelocity, T::kConstantAcceleration, T::kCoordinatedTurn,
                                T::kCoordinatedTurnEstimated, T::kSinger},
                               true);
  // Noise sigmas up to kMaxAccel (jerk: that in 0.1 s), turn-rate noise up to 1 rad/s^2; a
  // new turn rate's spread from 1 urad/s (its variance must not vanish: P singular) to 1 rad/s;
  // Singer's tau from 0.1 s to an hour (his 1 s turbulence to 60 s lazy turns; a tiny tau
  // overflows 1/tau^5 in Q). Zero noise stays allowed.
  const Range accel{0.0, kMaxAccel};
  const auto wants = [&](std::initializer_list<T> types) {
    if (!typed) return true;
    for (const T type : types) {
      if (type == m.type) return true;
    }
    return false;
  };
  if (wants(
          {T::kConstantVelocity, T::kCoordinatedTurn, T::kCoordinatedTurnEstimated, T::kSinger})) {
    s.number("accel_sigma", m.accel_sigma, accel, typed);
  }
  if (wants({T::kConstantAcceleration})) {
    s.number("jerk_sigma", m.jerk_sigma, Range{0.0, 10.0 * kMaxAccel}, typed);
  }
  if (wants({T::kCoordinatedTurn})) {
    if (typed) {
      read_turn_rate(s, m.turn_rate);
    } else {
      s.number("turn_rate", m.turn_rate);
    }
  }
  if (wants({T::kCoordinatedTurnEstimated})) {
    s.number("turn_rate_sigma", m.turn_rate_sigma, Range{0.0, 1.0}, typed);
    s.number("initial_turn_rate_sigma", m.initial_turn_rate_sigma, Range{1e-6, 1.0});
  }
  if (wants({T::kSinger})) {
    s.number("time_constant", m.time_constant, Range{0.1, 3600.0}, typed);
  }
  s.number("vertical_accel_sigma", m.vertical_accel_sigma, accel);
  s.finish();
  return m;
}

/// Reads the model list; a given list replaces the default one as a whole.
void read_motion_models(YamlSection& root, std::vector<MotionModelSpec>& models) {
  auto sections = root.sections("motion_models");
  if (!root.has("motion_models")) return;
  if (sections.empty()) {
    if (root.node()["motion_models"].IsSequence()) {
      root.error("motion_models", "expected at least one motion model, got an empty list");
    }
    return;
  }
  models.clear();
  for (std::size_t i = 0; i < sections.size(); ++i) {
    MotionModelSpec model = read_motion_model(sections[i]);
    for (std::size_t j = 0; j < models.size(); ++j) {
      if (!model.name.empty() && models[j].name == model.name) {
        sections[i].error("name", "expected a unique model name, got '" + model.name +
                                      "' again (first at motion_models[" + std::to_string(j) +
                                      "])");
      }
    }
    models.push_back(std::move(model));
  }
}

/// "auto" or a number from one false plot in any radar's coverage to one per square or cubic
/// metre; a smaller density overflows a plot's likelihood ratio L / lambda.
void read_clutter_density(YamlSection& s, std::optional<double>& out) {
  const std::string key = "clutter_density";
  const Range range{1e-20, 1.0};
  if (!s.has(key) || !s.node()[key].IsScalar()) return s.number(key, out, range);
  std::string text;
  s.text(key, text);
  if (text == "auto") return out.reset();
  double value = 0.0;
  if (!YAML::convert<double>::decode(s.node()[key], value) || !range.contains(value)) {
    return s.error(key, "expected auto or a number " + range.describe() +
                            " [1/m^2 in 2-D, 1/m^3 in 3-D], got '" + text + "'");
  }
  out = value;
}

AntennaSpec read_antenna(YamlSection s) {
  AntennaSpec a;
  read_enum(s, "rotation", a.rotation,
            {AntennaRotation::kAuto, AntennaRotation::kRotating, AntennaRotation::kSnapshot});
  const std::string key = "period";
  if (s.has(key) && s.node()[key].IsScalar() && s.node()[key].Scalar() == "auto") {
    std::string ignored;
    s.text(key, ignored);
  } else {
    // 0.1 s (a fast surface-movement radar spins about 1 s) to 10 min (a slow search sweep).
    s.number(key, a.period, Range{0.1, 600.0});
  }
  read_enum(s, "direction", a.direction,
            {RotationDirection::kAuto, RotationDirection::kClockwise,
             RotationDirection::kCounterclockwise});
  s.finish();
  return a;
}

AssociationSpec read_association(YamlSection s) {
  AssociationSpec a;
  read_enum(s, "method", a.method, {AssociationMethod::kJpda, AssociationMethod::kGnn});
  s.number("gate_probability", a.gate_probability, kOpenUnit);
  s.number("detection_probability", a.detection_probability, Range::open_probability());
  read_clutter_density(s, a.clutter_density);
  YamlSection map = s.section("clutter_map");
  // The map refines `auto` only: a fixed density turns its default off, so that a fixed
  // density works without touching the map; asking for both is refused below.
  if (a.clutter_density && !map.has("enabled")) a.clutter_map.enabled = false;
  map.boolean("enabled", a.clutter_map.enabled);
  // Physical bounds: a metre to a thousand kilometres, a hundredth of a degree to a half
  // revolution (finer cells than any radar resolves would only overflow the map's indices).
  map.number("range_cell", a.clutter_map.range_cell, Range{1.0, 1e6});
  map.number("azimuth_cell", a.clutter_map.azimuth_cell, Range{1.7e-4, 3.15});
  map.number("cartesian_cell", a.clutter_map.cartesian_cell, Range{1.0, 1e6});
  if (a.clutter_map.enabled && a.clutter_density) {
    map.error("enabled",
              "the clutter map refines clutter_density: auto; it cannot be on with "
              "a fixed clutter_density");
  }
  map.finish();
  // Joint-event work: a thousand tracks in one cluster, ten thousand events (Murty's
  // solutions and their memory grow with k).
  s.integer("max_exact_cluster_size", a.max_exact_cluster_size, Range{1.0, 1000.0});
  s.integer("k_best", a.k_best, Range{1.0, 1e4});
  s.finish();
  return a;
}

ClutterRejectionSpec read_clutter_rejection(YamlSection s) {
  ClutterRejectionSpec c;
  s.boolean("enabled", c.enabled);
  // Kernels and steps of a metre to 100 km (a tiny h makes 1 / h^2 infinite, a huge one sums
  // every pair), a millimetre's tolerance, a thousand bins and iterations per plot.
  const Range metres{1.0, 1e5};
  s.number("kernel_bandwidth", c.kernel_bandwidth, metres);
  s.integer("beta", c.beta, kAtLeastOne);
  s.integer("n_f", c.n_f, Range{1.0, 1000.0});
  if (c.beta >= c.n_f) {
    s.error("beta", "expected beta < n_f (" + std::to_string(c.n_f) +
                        ") so that tau stays below f_max, got " + std::to_string(c.beta));
  }
  YamlSection ms = s.section("mean_shift");
  ms.number("bandwidth", c.mean_shift.bandwidth, metres);
  ms.number("merge_distance", c.mean_shift.merge_distance, Range{0.0, 1e5});
  ms.integer("max_iterations", c.mean_shift.max_iterations, Range{1.0, 1000.0});
  ms.number("tolerance", c.mean_shift.tolerance, Range{1e-3, 1e5});
  ms.finish();
  s.finish();
  return c;
}

}  // namespace skytrack::config::detail
