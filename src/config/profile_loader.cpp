// Profile loader: one reader per section (each calls finish(), so unknown keys are errors),
// then the checks that span keys and sections. Schema and ranges: config/README.md.
#include "skytrack/config/profile_loader.hpp"

#include <cmath>
#include <initializer_list>
#include <numbers>
#include <optional>
#include <sstream>

#include "skytrack/config/yaml_section.hpp"

namespace skytrack::config {
namespace {

constexpr double kSumTolerance = 1e-6;
const Range kOpenUnit{0.0, 1.0, true, true};  // gate probabilities: 0 and 1 make no gate
const Range kAtLeastOne{1.0};

std::string show(double value, int precision = 6) {
  std::ostringstream out;
  out.precision(precision);
  out << value;
  return out.str();
}

/// A closed set of names, spelled as to_string() spells them. Returns false when the key is
/// absent or wrong, leaving `out` unchanged.
template <class E>
bool read_enum(YamlSection& s, std::string_view key, E& out, std::initializer_list<E> values,
               bool required = false) {
  std::string name(to_string(out));
  s.text(key, name, required);
  if (!s.has(key)) return false;
  for (const E value : values) {
    if (to_string(value) == name) {
      out = value;
      return true;
    }
  }
  std::string list;
  for (const E value : values) list += (list.empty() ? "" : ", ") + std::string(to_string(value));
  s.error(key, "expected one of " + list + ", got '" + name + "'");
  return false;
}

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
constexpr double kMaxSpeed = 2e4;  // [m/s]
constexpr double kMaxAccel = 1e3;  // [m/s^2]

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

/// "expected a <= b" on `key_a` when a > b.
void check_order(YamlSection& s, std::string_view key_a, double a, std::string_view key_b, double b,
                 bool strict) {
  if (strict ? a < b : a <= b) return;
  s.error(key_a, "expected " + std::string(key_a) + (strict ? " < " : " <= ") + std::string(key_b) +
                     " (" + show(b) + "), got " + show(a));
}

InitiationSpec read_initiation(YamlSection s) {
  InitiationSpec in;
  // A plot pair is the least that gives a velocity; chains live n scans, at most 100. Speeds
  // up to kMaxSpeed, and a speed gate of at least 0.1 m/s (a drifting iceberg).
  s.integer("m", in.m, Range{2.0, 100.0});
  s.integer("n", in.n, Range{2.0, 100.0});
  s.number("min_speed", in.min_speed, Range{0.0, kMaxSpeed});
  s.number("max_speed", in.max_speed, Range{0.1, kMaxSpeed});
  s.number("gated_seed_beta", in.gated_seed_beta, Range::probability());
  s.integer("max_tentative", in.max_tentative, Range{1.0, 1e6});
  check_order(s, "m", in.m, "n", in.n, false);
  check_order(s, "min_speed", in.min_speed, "max_speed", in.max_speed, true);
  s.finish();
  return in;
}

InputLimitsSpec read_input_limits(YamlSection s) {
  InputLimitsSpec in;
  // A kilometre (a bound below any radar's range would refuse its plots) to the geostationary
  // orbit and beyond; a second (a bound below a batch interval would refuse every batch) to a
  // week.
  s.number("max_range", in.max_range, Range{1e3, 1e8});
  s.number("max_time_jump", in.max_time_jump, Range{1.0, 604800.0});
  s.finish();
  return in;
}

TrackLifeSpec read_track_life(YamlSection s) {
  TrackLifeSpec t;
  read_enum(s, "confirmation", t.confirmation,
            {ConfirmationMethod::kMOfN, ConfirmationMethod::kExistence});
  // A track's plot history holds 32 scans (TrackLife::history); a thousand missed scans; a
  // spread of a metre to 1000 km (beyond, a track covers any radar's whole coverage).
  s.integer("confirm_m", t.confirm_m, Range{1.0, 32.0});
  s.integer("confirm_n", t.confirm_n, Range{1.0, 32.0});
  s.integer("delete_tentative_misses", t.delete_tentative_misses, Range{1.0, 1000.0});
  s.integer("delete_confirmed_misses", t.delete_confirmed_misses, Range{1.0, 1000.0});
  s.number("delete_position_sigma", t.delete_position_sigma, Range{1.0, 1e6});
  s.number("initial_existence", t.initial_existence, kOpenUnit);
  s.number("confirm_existence", t.confirm_existence, kOpenUnit);
  s.number("delete_existence", t.delete_existence, kOpenUnit);
  s.number("survival_probability", t.survival_probability, Range{0.0, 1.0, true, false});
  check_order(s, "confirm_m", t.confirm_m, "confirm_n", t.confirm_n, false);
  check_order(s, "delete_existence", t.delete_existence, "confirm_existence", t.confirm_existence,
              true);
  s.finish();
  return t;
}

BranchingSpec read_branching(YamlSection s, ErrorList& errors, const TrackingProfile& p) {
  BranchingSpec b;
  s.boolean("enabled", b.enabled);
  // Branch counts bound time and memory per scan (a branch is a whole IMM track): 100 sons,
  // 10 000 per father, 100 000 in all, 100 coast sons kept 1000 looks; accelerations up to
  // kMaxAccel.
  s.integer("max_children", b.max_children, Range{1.0, 100.0});
  s.number("manoeuvre_gate_probability", b.manoeuvre_gate_probability, kOpenUnit);
  const std::size_t before = errors.messages().size();
  s.texts("manoeuvre_models", b.manoeuvre_models);
  const bool names_ok = errors.messages().size() == before;
  s.number("manoeuvre_accel_sigma", b.manoeuvre_accel_sigma, Range{0.0, kMaxAccel, true});
  s.number("ambiguity_beta", b.ambiguity_beta, Range::open_probability());
  s.boolean("coast_on_last_motion", b.coast_on_last_motion);
  read_enum(s, "non_manoeuvre_gate", b.non_manoeuvre_gate,
            {NonManoeuvreGate::kUnion, NonManoeuvreGate::kLastMotion});
  s.number("last_motion_accel_sigma", b.last_motion_accel_sigma, Range{0.0, kMaxAccel});
  s.number("last_motion_false_plots", b.last_motion_false_plots, Range::non_negative());
  read_enum(s, "confirmation", b.confirmation,
            {ConfirmationMethod::kMOfN, ConfirmationMethod::kExistence});
  s.integer("coast_sons", b.coast_sons, Range{0.0, 100.0});
  s.number("coast_son_doubt", b.coast_son_doubt, kOpenUnit);
  s.integer("coast_son_looks", b.coast_son_looks, Range{0.0, 1000.0});
  YamlSection chain = s.section("detectability");
  chain.number("hide", b.detectability.hide, Range::probability());
  chain.number("reveal", b.detectability.reveal, Range::open_probability());
  chain.finish();
  s.integer("max_branches_per_father", b.max_branches_per_father, Range{1.0, 1e4});
  s.integer("max_total_branches", b.max_total_branches, Range{1.0, 1e5});
  s.finish();

  // The held last motion's options do nothing without it: set in the file with it off, they
  // are a mistake (taken from the defaults, they are simply inert).
  if (!b.coast_on_last_motion) {
    const std::pair<const char*, bool> uses[] = {
        {"non_manoeuvre_gate", b.non_manoeuvre_gate == NonManoeuvreGate::kLastMotion},
        {"last_motion_accel_sigma", b.last_motion_accel_sigma > 0.0},
        {"coast_sons", b.coast_sons > 0},
        {"last_motion_false_plots", b.last_motion_false_plots > 0.0}};
    for (const auto& [key, used] : uses) {
      if (used && s.has(key)) s.error(key, "needs coast_on_last_motion: true");
    }
  }
  if (b.coast_son_looks > 0 && b.coast_sons == 0 && s.has("coast_son_looks")) {
    s.error("coast_son_looks", "needs coast_sons > 0");
  }
  // The manoeuvre gate is the wider of the two (paper 003 §1).
  if (b.manoeuvre_gate_probability < p.association.gate_probability) {
    s.error("manoeuvre_gate_probability", "expected >= association.gate_probability (" +
                                              show(p.association.gate_probability) +
                                              ") as the manoeuvre gate is the wider one, got " +
                                              show(b.manoeuvre_gate_probability));
  }
  check_order(s, "max_branches_per_father", b.max_branches_per_father, "max_total_branches",
              b.max_total_branches, false);
  const bool given = s.has("manoeuvre_models");
  if (!names_ok || (!b.enabled && !given)) return b;  // disabled: the defaults need not fit
  if (b.manoeuvre_models.empty() && b.enabled) {
    s.error("manoeuvre_models", "expected at least one model name, got an empty list");
  }
  for (std::size_t i = 0; i < b.manoeuvre_models.size(); ++i) {
    const std::string& name = b.manoeuvre_models[i];
    bool known = false;
    std::string names;
    for (const auto& model : p.motion_models) {
      known = known || model.name == name;
      names += (names.empty() ? "" : ", ") + model.name;
    }
    if (known) continue;
    errors.add(given ? s.node()["manoeuvre_models"][i] : s.node(),
               s.path() + ".manoeuvre_models[" + std::to_string(i) + "]",
               "expected the name of a motion model (" + names + "), got '" + name + "'" +
                   (given ? "" : " (the default; set manoeuvre_models for these models)"));
  }
  return b;
}

/// The Markov matrix and the initial probabilities against the model list.
void check_imm(YamlSection& root, ErrorList& errors, const TrackingProfile& p, bool transition_ok,
               bool initial_ok) {
  const std::size_t n = p.motion_models.size();
  const std::string size = std::to_string(n);
  const auto& t = p.mode_transition;
  const bool t_given = root.has("mode_transition");
  const std::string t_default = t_given ? "" : " (the default; set mode_transition)";
  if (transition_ok && (t.size() != n || t.front().size() != n)) {
    root.error("mode_transition", "expected a " + size + "x" + size +
                                      " matrix (a row and a column per motion model), got " +
                                      std::to_string(t.size()) + "x" +
                                      std::to_string(t.front().size()) + t_default);
  } else if (transition_ok) {
    for (std::size_t i = 0; i < n; ++i) {
      const std::string path = "mode_transition[" + std::to_string(i) + "]";
      const YAML::Node where = t_given ? root.node()["mode_transition"][i] : YAML::Node();
      double sum = 0.0;
      std::optional<double> outside;
      for (const double value : t[i]) {
        sum += value;
        if (!(value >= 0.0 && value <= 1.0)) outside = value;
      }
      if (outside) {
        errors.add(where, path, "expected probabilities in [0, 1], got " + show(*outside));
      } else if (std::abs(sum - 1.0) > kSumTolerance) {
        errors.add(where, path, "expected a row summing to 1 (within 1e-6), got " + show(sum, 10));
      }
    }
  }
  const auto& q = p.initial_mode_probabilities;
  const std::string q_default = root.has("initial_mode_probabilities")
                                    ? ""
                                    : " (the default; set initial_mode_probabilities)";
  if (!initial_ok) return;
  if (q.size() != n) {
    root.error("initial_mode_probabilities", "expected one probability per motion model (" + size +
                                                 "), got " + std::to_string(q.size()) + q_default);
    return;
  }
  double sum = 0.0;
  for (const double value : q) sum += value;
  if (std::abs(sum - 1.0) > kSumTolerance) {
    root.error("initial_mode_probabilities",
               "expected probabilities summing to 1 (within 1e-6), got " + show(sum, 10));
  }
}

TrackingProfile read_profile(const YAML::Node& node, ErrorList& errors) {
  TrackingProfile p;
  YamlSection root(node, "", errors);
  p.identity = read_identity(root.section("profile"));
  read_enum(root, "mode", p.mode,
            {TrackingMode::kPoint, TrackingMode::kGroup, TrackingMode::kExtended,
             TrackingMode::kBernoulli});
  if (root.has("dimension") && root.node()["dimension"].IsScalar() &&
      root.node()["dimension"].Scalar() == "auto") {
    std::string ignored;
    root.text("dimension", ignored);
    p.dimension = 0;
  } else {
    root.integer("dimension", p.dimension, Range{2.0, 3.0});
  }
  p.measurement = read_measurement(root.section("measurement"));
  p.antenna = read_antenna(root.section("antenna"));
  read_motion_models(root, p.motion_models);

  std::size_t before = errors.messages().size();
  root.matrix("mode_transition", p.mode_transition);
  const bool transition_ok = errors.messages().size() == before;
  root.number("mode_transition_interval", p.mode_transition_interval, Range::non_negative());
  before = errors.messages().size();
  root.numbers("initial_mode_probabilities", p.initial_mode_probabilities, {},
               Range::probability());
  const bool initial_ok = errors.messages().size() == before;
  check_imm(root, errors, p, transition_ok, initial_ok);

  p.association = read_association(root.section("association"));
  p.clutter_rejection = read_clutter_rejection(root.section("clutter_rejection"));
  p.initiation = read_initiation(root.section("initiation"));
  p.track_life = read_track_life(root.section("track_life"));
  p.branching = read_branching(root.section("branching"), errors, p);
  p.input_limits = read_input_limits(root.section("input_limits"));
  root.finish();
  return p;
}

Expected<TrackingProfile> build(const YAML::Node& node, ErrorList& errors) {
  try {
    TrackingProfile profile = read_profile(node, errors);
    if (errors.empty()) return profile;
  } catch (const YAML::Exception& e) {  // a reader missed a case; still no crash
    errors.add(YAML::Node(), "", std::string("unexpected YAML error: ") + e.what());
  }
  return make_error(errors.joined());
}

}  // namespace

Expected<TrackingProfile> load_profile(const std::string& path) {
  ErrorList errors(path);
  const auto node = load_yaml_file(path, errors);
  if (!node) return make_error(errors.joined());
  return build(*node, errors);
}

Expected<TrackingProfile> parse_profile(const std::string& yaml_text,
                                        const std::string& name_for_messages) {
  ErrorList errors(name_for_messages);
  YAML::Node node;
  try {
    node = YAML::Load(yaml_text);
  } catch (const YAML::ParserException& e) {  // same form as load_yaml_file
    errors.add(YAML::Node(), "", "line " + std::to_string(e.mark.line + 1) + ": " + e.msg);
    return make_error(errors.joined());
  }
  return build(node, errors);
}

}  // namespace skytrack::config
