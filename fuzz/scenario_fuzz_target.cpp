// Fuzz target: any bytes as a scenario's YAML through skytrack::config::parse_scenario. It
// must not crash (ASan, UBSan), and a rejected text must say why.
#include <string>

#include "fuzz_support.hpp"
#include "fuzz_targets.hpp"
#include "skytrack/config/scenario_loader.hpp"

int skytrack_scenario_fuzz_one(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const auto scenario = skytrack::config::parse_scenario(text, "fuzz.yaml");
  if (!scenario) SKYTRACK_FUZZ_CHECK(!scenario.error().message.empty());
  return 0;
}
