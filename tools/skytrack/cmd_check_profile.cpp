// skytrack check-profile FILE...: validates tracking profiles. A valid file gets a one-line
// summary on stdout; an invalid one gets every error on stderr, and the exit code is 1.
#include <memory>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "commands.hpp"
#include "skytrack/config/profile_loader.hpp"

namespace skytrack::tool {
namespace {

std::string summary(const std::string& path, const config::TrackingProfile& profile) {
  std::string models;
  for (const auto& model : profile.motion_models) {
    models += (models.empty() ? "" : ", ") + model.name;
  }
  const std::string dims =
      profile.dimension == 0 ? std::string("auto 2-D/3-D") : fmt::format("{}-D", profile.dimension);
  // What the mode's estimator runs on: the IMM's models, or its own.
  std::string estimator = "models " + models;
  if (profile.mode == config::TrackingMode::kGroup) {
    estimator = fmt::format("group boxes ({})", group::to_string(profile.group.motion));
  } else if (profile.mode == config::TrackingMode::kExtended) {
    estimator = fmt::format("extent estimator {}", extended::to_string(profile.extended.kind));
  }
  return fmt::format("{}: ok: {} version {}, mode {}, {}, {}", path, profile.identity.name,
                     profile.identity.version, config::to_string(profile.mode), dims, estimator);
}

}  // namespace

void add_check_profile_command(CLI::App& app, int& exit_code) {
  auto files = std::make_shared<std::vector<std::string>>();
  CLI::App* cmd = app.add_subcommand("check-profile", "Validate YAML tracking profiles");
  cmd->add_option("files", *files, "Profile files (YAML)")->required();
  cmd->footer(
      "Example: skytrack check-profile config/profiles/*.yaml\nExit codes: 0 every "
      "profile is valid; 1 at least one is not (each mistake printed as file:line: key: "
      "reason); 1xx command-line mistakes (CLI11: 105 a bad value, 106 a required "
      "option missing, 109 an unknown argument).");
  cmd->callback([files, &exit_code] {
    for (const auto& path : *files) {
      const auto profile = config::load_profile(path);
      if (profile) {
        fmt::print("{}\n", summary(path, *profile));
      } else {
        fmt::print(stderr, "{}\n", profile.error().message);
        exit_code = 1;
      }
    }
  });
}

}  // namespace skytrack::tool
