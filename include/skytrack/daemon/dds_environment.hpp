#pragma once
// Which Cyclone DDS configuration a skytrack process runs with. Cyclone's built-in default
// sends discovery multicast on the machine's external interface, so no skytrack process may
// create a participant without a configuration: a user's CYCLONEDDS_URI is respected (a
// deliberate choice), otherwise the shipped loopback XML is located and set, and when it
// cannot be found DDS must not be started at all.
#include <string>
#include <vector>

#include "skytrack/core/expected.hpp"

namespace skytrack::daemon {

/// Where the shipped loopback XML may be, in order: the install prefix next to the executable
/// (bin/../share/skytrack/dds), the build tree (build/tools/X/X -> source/config/dds), and the
/// source tree this binary was built from.
std::vector<std::string> loopback_config_candidates(const std::string& executable_path);

/// True when `path` is a readable Cyclone XML that pins the loopback interface and disables
/// multicast, which is what "safe" means here.
bool is_loopback_only_config(const std::string& path);

/// Leaves a non-empty CYCLONEDDS_URI as the user set it; otherwise sets it to the first safe
/// candidate. Returns a line for the log ("CYCLONEDDS_URI=... (set by the user)"), or an error
/// naming every place searched. Call before any dds_* function.
Expected<std::string> ensure_dds_configuration();
/// As above, searching `candidates` (for tests).
Expected<std::string> ensure_dds_configuration(const std::vector<std::string>& candidates);

}  // namespace skytrack::daemon
