#pragma once
// The fusion role's YAML (schema: config/fusion.yaml, docs/fusion.md): a `fusion:` section,
// read the way the profiles are (every mistake as "file:line: key.path: what was expected",
// unknown keys refused). The daemon's configuration calls read_fusion_section for its own
// `fusion:` section; `skytrack fuse --config` loads a standalone file.
#include <string>

#include "skytrack/config/yaml_section.hpp"
#include "skytrack/core/expected.hpp"
#include "skytrack/fusion/fusion_spec.hpp"

namespace skytrack::config {

/// Reads the keys of a `fusion:` section over `spec` (absent keys keep its values), checks
/// the ranges and the keys that depend on each other, and reports unknown keys (finish()).
void read_fusion_section(YamlSection section, fusion::FusionSpec& spec);

/// A standalone fusion file: a top-level `fusion:` section, nothing else.
Expected<fusion::FusionSpec> load_fusion_config(const std::string& path);
/// As load_fusion_config, from text; `name_for_messages` stands for the file name.
Expected<fusion::FusionSpec> parse_fusion_config(const std::string& yaml_text,
                                                 const std::string& name_for_messages);

std::string_view to_string(fusion::Blend blend);
std::string_view to_string(fusion::Metric metric);

}  // namespace skytrack::config
