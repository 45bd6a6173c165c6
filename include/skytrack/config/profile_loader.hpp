#pragma once
// Reads and validates a YAML tracking profile (schema: config/README.md). Every problem of a
// file is reported at once, one per line of Error::message, each as
// "file:line: key.path: expected ..., got ...".
#include <string>

#include "skytrack/config/profile.hpp"
#include "skytrack/core/expected.hpp"

namespace skytrack::config {

Expected<TrackingProfile> load_profile(const std::string& path);

/// As load_profile, from text; `name_for_messages` stands for the file name in messages.
Expected<TrackingProfile> parse_profile(const std::string& yaml_text,
                                        const std::string& name_for_messages);

}  // namespace skytrack::config
