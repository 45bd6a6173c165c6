// Profile loader: one reader per section (each calls finish(), so unknown keys are errors),
// then the checks that span keys and sections. Schema and ranges: config/README.md.
#include "skytrack/config/profile_loader.hpp"

#include <cmath>
#include <initializer_list>
#include <numbers>
#include <optional>
#include <sstream>

#include "skytrack/config/yaml_section.hpp"

#include "profile_sections.hpp"

namespace skytrack::config {
namespace {

using namespace detail;

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
  p.input_limits = read_input_limits(root.section("input_limits"));
  read_mode_sections(root, errors, p);
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
  const auto node = parse_yaml_text(yaml_text, errors);
  if (!node) return make_error(errors.joined());
  return build(*node, errors);
}

}  // namespace skytrack::config
