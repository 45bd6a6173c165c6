// The fusion role's YAML section (include/skytrack/config/fusion_section.hpp).
#include "skytrack/config/fusion_section.hpp"

#include <cstdint>
#include <limits>

#include "profile_sections.hpp"

namespace skytrack::config {

std::string_view to_string(fusion::Blend blend) {
  return blend == fusion::Blend::kAdaptive ? "adaptive" : "fixed";
}

std::string_view to_string(fusion::Metric metric) {
  return metric == fusion::Metric::kNormalised ? "normalised" : "euclidean";
}

void read_fusion_section(YamlSection s, fusion::FusionSpec& spec) {
  using detail::read_enum;
  std::int64_t output_sensor = spec.output_sensor;
  s.integer("output_sensor", output_sensor,
            Range{0.0, static_cast<double>(std::numeric_limits<std::uint32_t>::max())});
  spec.output_sensor = static_cast<std::uint32_t>(output_sensor);
  s.number("cycle", spec.cycle, Range{1e-3, 3600.0});
  s.number("window", spec.window, Range{0.0, 3600.0});
  read_enum(s, "blend", spec.blend, {fusion::Blend::kAdaptive, fusion::Blend::kFixed});
  s.number("epsilon", spec.epsilon, Range{0.0, 1.0, false, true});
  s.number("history_weight", spec.history_weight, Range{0.0, 1.0, false, true});
  read_enum(s, "metric", spec.metric, {fusion::Metric::kNormalised, fusion::Metric::kEuclidean});
  s.number("cutoff", spec.cutoff, Range::positive());
  s.number("order", spec.order, Range{1.0, 10.0});
  s.number("label_penalty", spec.label_penalty, Range::non_negative());
  s.number("gate", spec.gate, Range::positive());
  s.number("sensor_timeout", spec.sensor_timeout, Range::positive());
  s.number("coast_time", spec.coast_time, Range::non_negative());
  s.boolean("firm_only", spec.firm_only);
  s.number("accel_psd", spec.accel_psd, Range{0.0, 1e6});
  s.number("missing_position_sigma", spec.missing_position_sigma, Range{1e-3, 1e6});
  s.number("missing_velocity_sigma", spec.missing_velocity_sigma, Range{1e-3, 1e5});
  s.integer("max_queued_frames", spec.max_queued_frames, Range{2.0, 100000.0});
  // The window holds whole cycles; alpha and gamma must lie below c to mean anything.
  detail::check_order(s, "cycle", spec.cycle, "window", spec.window, false);
  detail::check_order(s, "label_penalty", spec.label_penalty, "cutoff", spec.cutoff, true);
  detail::check_order(s, "gate", spec.gate, "cutoff", spec.cutoff, true);
  s.finish();
}

namespace {

Expected<fusion::FusionSpec> build(const YAML::Node& node, ErrorList& errors) {
  fusion::FusionSpec spec;
  try {
    YamlSection root(node, "", errors);
    read_fusion_section(root.section("fusion", true), spec);
    root.finish();
    if (errors.empty()) return spec;
  } catch (const YAML::Exception& e) {  // a reader missed a case; still no crash
    errors.add(YAML::Node(), "", std::string("unexpected YAML error: ") + e.what());
  }
  return make_error(errors.joined());
}

}  // namespace

Expected<fusion::FusionSpec> load_fusion_config(const std::string& path) {
  ErrorList errors(path);
  const auto node = load_yaml_file(path, errors);
  if (!node) return make_error(errors.joined());
  return build(*node, errors);
}

Expected<fusion::FusionSpec> parse_fusion_config(const std::string& yaml_text,
                                                 const std::string& name_for_messages) {
  ErrorList errors(name_for_messages);
  const auto node = parse_yaml_text(yaml_text, errors);
  if (!node) return make_error(errors.joined());
  return build(*node, errors);
}

}  // namespace skytrack::config
