#pragma once
// The daemon's logger from the configuration: level, console (stderr) or a rotating file.
// Asynchronous; a full log queue overwrites its oldest message instead of blocking a thread.
#include "skytrack/core/expected.hpp"
#include "skytrack/daemon/daemon_config.hpp"

namespace skytrack::daemon {

/// Creates the logger and makes it spdlog's default. Fails when the log file cannot be opened.
Expected<void> setup_logging(const LogSettings& settings);

/// Flushes and stops logging (call before exit).
void shutdown_logging();

}  // namespace skytrack::daemon
