// The profile sections of track management: initiation, input limits, track life, branching,
// and the checks across the IMM's keys.
#include <cmath>
#include <numbers>
#include <optional>

#include "profile_sections.hpp"

namespace skytrack::config::detail {

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

/// Where each clutter-area key was read: its sub-block `branching.clutter_area`, or the flat
/// key of profiles written before it (config/README.md gives the mapping).
struct ClutterAreaKeys {
  struct Key {
    YamlSection* section = nullptr;
    const char* name = "";
    bool given() const { return section->has(name); }
    std::string path() const { return section->path() + "." + name; }
  };
  Key hold_last_motion, gate, held_accel_sigma, false_plots, coast_sons, coast_son_doubt,
      coast_son_looks;
};

/// The keys that keep a track's number through looks missed in clutter (paper 003 §4.2),
/// from `area` (branching.clutter_area) or their flat names in `s` (branching).
ClutterAreaKeys read_clutter_area(YamlSection& s, YamlSection& area, BranchingSpec& b) {
  const auto pick = [&](const char* key, const char* flat) {
    if (s.has(flat)) {
      if (area.has(key)) {
        area.error(key, std::string("given twice: also as ") + s.path() + "." + flat +
                            " (its name before clutter_area)");
      }
      return ClutterAreaKeys::Key{&s, flat};
    }
    return ClutterAreaKeys::Key{&area, key};
  };
  ClutterAreaKeys k;
  k.false_plots = pick("false_plots", "last_motion_false_plots");
  k.hold_last_motion = pick("hold_last_motion", "coast_on_last_motion");
  k.gate = pick("gate", "non_manoeuvre_gate");
  k.held_accel_sigma = pick("held_accel_sigma", "last_motion_accel_sigma");
  k.coast_sons = pick("coast_sons", "coast_sons");
  k.coast_son_doubt = pick("coast_son_doubt", "coast_son_doubt");
  k.coast_son_looks = pick("coast_son_looks", "coast_son_looks");
  k.false_plots.section->number(k.false_plots.name, b.last_motion_false_plots,
                                Range::non_negative());
  k.hold_last_motion.section->boolean(k.hold_last_motion.name, b.coast_on_last_motion);
  read_enum(*k.gate.section, k.gate.name, b.non_manoeuvre_gate,
            {NonManoeuvreGate::kUnion, NonManoeuvreGate::kLastMotion});
  k.held_accel_sigma.section->number(k.held_accel_sigma.name, b.last_motion_accel_sigma,
                                     Range{0.0, kMaxAccel});
  k.coast_sons.section->integer(k.coast_sons.name, b.coast_sons, Range{0.0, 100.0});
  k.coast_son_doubt.section->number(k.coast_son_doubt.name, b.coast_son_doubt, kOpenUnit);
  k.coast_son_looks.section->integer(k.coast_son_looks.name, b.coast_son_looks, Range{0.0, 1000.0});
  const bool flat_chain = s.has("detectability");
  if (flat_chain && area.has("detectability")) {
    area.error("detectability", "given twice: also as " + s.path() +
                                    ".detectability (its place before clutter_area)");
  }
  YamlSection chain = flat_chain ? s.section("detectability") : area.section("detectability");
  chain.number("hide", b.detectability.hide, Range::probability());
  chain.number("reveal", b.detectability.reveal, Range::open_probability());
  chain.finish();
  area.finish();
  return k;
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
  read_enum(s, "confirmation", b.confirmation,
            {ConfirmationMethod::kMOfN, ConfirmationMethod::kExistence});
  YamlSection clutter_area = s.section("clutter_area");
  const ClutterAreaKeys area = read_clutter_area(s, clutter_area, b);
  s.integer("max_branches_per_father", b.max_branches_per_father, Range{1.0, 1e4});
  s.integer("max_total_branches", b.max_total_branches, Range{1.0, 1e5});
  s.finish();

  // The held last motion's options do nothing without it: set in the file with it off, they
  // are a mistake (taken from the defaults, they are simply inert).
  if (!b.coast_on_last_motion) {
    const std::pair<const ClutterAreaKeys::Key*, bool> uses[] = {
        {&area.gate, b.non_manoeuvre_gate == NonManoeuvreGate::kLastMotion},
        {&area.held_accel_sigma, b.last_motion_accel_sigma > 0.0},
        {&area.coast_sons, b.coast_sons > 0},
        {&area.false_plots, b.last_motion_false_plots > 0.0}};
    for (const auto& [key, used] : uses) {
      if (used && key->given()) {
        key->section->error(key->name, "needs " + area.hold_last_motion.path() + ": true");
      }
    }
  }
  if (b.coast_son_looks > 0 && b.coast_sons == 0 && area.coast_son_looks.given()) {
    area.coast_son_looks.section->error(area.coast_son_looks.name,
                                        "needs " + area.coast_sons.path() + " > 0");
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

}  // namespace skytrack::config::detail
