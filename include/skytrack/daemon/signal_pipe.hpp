#pragma once
// Signals to the main loop through a self-pipe: the handler only write()s the signal number,
// which is async-signal-safe; the main loop poll()s the pipe and does the real work (stop,
// reload) from normal code. One instance per process.
#include <chrono>
#include <initializer_list>
#include <optional>

#include "skytrack/core/expected.hpp"

namespace skytrack::daemon {

class SignalPipe {
 public:
  /// Installs handlers for `signals` (SIGPIPE is ignored as well).
  static Expected<void> install(std::initializer_list<int> signals);

  /// The next signal received, waiting up to `timeout`; nullopt on timeout.
  static std::optional<int> wait(std::chrono::milliseconds timeout);
};

}  // namespace skytrack::daemon
