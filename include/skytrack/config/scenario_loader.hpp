#pragma once
// Scenario YAML -> sim::Scenario, validated key by key (schema: config/README.md).
#include <string>

#include "skytrack/core/expected.hpp"
#include "skytrack/sim/scenario.hpp"

namespace skytrack::config {

Expected<sim::Scenario> load_scenario(const std::string& path);
/// Parses YAML text; `name` stands for the file in messages.
Expected<sim::Scenario> parse_scenario(const std::string& yaml_text, const std::string& name);

}  // namespace skytrack::config
