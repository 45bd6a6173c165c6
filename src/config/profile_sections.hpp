#pragma once
// The profile loader's section readers and their shared helpers (not installed): ranges,
// enum names, order checks. Schema and ranges: config/README.md.
#include <initializer_list>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "skytrack/config/profile.hpp"
#include "skytrack/config/yaml_section.hpp"

namespace skytrack::config::detail {

inline constexpr double kSumTolerance = 1e-6;
inline const Range kOpenUnit{0.0, 1.0, true, true};  // gate probabilities: 0 and 1 make no gate
inline const Range kAtLeastOne{1.0};

inline std::string show(double value, int precision = 6) {
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

inline constexpr double kMaxSpeed = 2e4;  // [m/s]
inline constexpr double kMaxAccel = 1e3;  // [m/s^2]

/// "expected a <= b" (or a < b when strict) on `key_a` when it is not so.
void check_order(YamlSection& s, std::string_view key_a, double a, std::string_view key_b, double b,
                 bool strict);

// One reader per section; each calls finish(), so unknown keys are errors.
ProfileIdentity read_identity(YamlSection s);
MeasurementSpec read_measurement(YamlSection s);
void read_motion_models(YamlSection& root, std::vector<MotionModelSpec>& models);
AntennaSpec read_antenna(YamlSection s);
AssociationSpec read_association(YamlSection s);
ClutterRejectionSpec read_clutter_rejection(YamlSection s);
InitiationSpec read_initiation(YamlSection s);
InputLimitsSpec read_input_limits(YamlSection s);
TrackLifeSpec read_track_life(YamlSection s);
BranchingSpec read_branching(YamlSection s, ErrorList& errors, const TrackingProfile& p);
/// Each mode's own section (point, bernoulli, ...): the profile's mode's is read, another
/// mode's is refused.
void read_mode_sections(YamlSection& root, ErrorList& errors, TrackingProfile& p);
/// The checks that span the IMM's keys: models, transition matrix, initial probabilities.
void check_imm(YamlSection& root, ErrorList& errors, const TrackingProfile& p, bool transition_ok,
               bool initial_ok);

}  // namespace skytrack::config::detail
