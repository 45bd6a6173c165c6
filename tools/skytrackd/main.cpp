// skytrackd: the tracking daemon. PlotBatch in over DDS, TrackBatch and TrackerStatus out.
// SIGINT/SIGTERM stop it (the scan in hand is finished and published, exit 0); SIGHUP reloads
// the profile. docs/daemon.md has the configuration schema, QoS, threads and signals.
#include <csignal>
#include <cstdio>
#include <string>

#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "skytrack/daemon/daemon.hpp"
#include "skytrack/daemon/daemon_config.hpp"
#include "skytrack/daemon/logging.hpp"
#include "skytrack/daemon/signal_pipe.hpp"
#include "skytrack/daemon/systemd_notify.hpp"
#include "skytrack/daemon/tsan_suppressions.hpp"

namespace {

using namespace skytrack::daemon;

int run(const std::string& config_path, bool check_only) {
  auto config = load_daemon_config(config_path);
  if (!config) {
    std::fprintf(stderr, "%s\n", config.error().message.c_str());
    return 2;
  }
  if (check_only) {
    auto profile = load_tracking_profile(config->profile);
    if (!profile) {
      std::fprintf(stderr, "%s\n", profile.error().message.c_str());
      return 2;
    }
    std::printf("%s: ok (profile '%s' version %s)\n", config_path.c_str(),
                profile->identity.name.c_str(), profile->identity.version.c_str());
    return 0;
  }
  if (auto ok = setup_logging(config->logging); !ok) {
    std::fprintf(stderr, "skytrackd: %s\n", ok.error().message.c_str());
    return 2;
  }
  if (auto ok = SignalPipe::install({SIGINT, SIGTERM, SIGHUP}); !ok) {
    spdlog::critical("{}", ok.error().message);
    shutdown_logging();
    return 2;
  }
  auto daemon = Daemon::create(*config);
  if (!daemon) {
    spdlog::critical("not started: {}", daemon.error().message);
    shutdown_logging();
    return 2;
  }
  (*daemon)->start();
  (*daemon)->publish_status();
  notify_systemd("READY=1");
  spdlog::info("skytrackd '{}' running (pid {})", config->instance, static_cast<long>(getpid()));
  const auto period = std::chrono::duration_cast<std::chrono::milliseconds>(
      std::chrono::duration<double>(config->status_period));
  auto next_status = std::chrono::steady_clock::now() + period;
  for (;;) {
    const auto now = std::chrono::steady_clock::now();
    if (now >= next_status) {
      (*daemon)->publish_status();
      next_status += period;
      if (next_status < now) next_status = now + period;  // after a stall, no burst
      continue;
    }
    const auto signal =
        SignalPipe::wait(std::chrono::duration_cast<std::chrono::milliseconds>(next_status - now) +
                         std::chrono::milliseconds(1));
    if (!signal) continue;
    if (*signal == SIGHUP) {
      notify_systemd("RELOADING=1");
      (*daemon)->reload_profile();
      notify_systemd("READY=1");
      continue;
    }
    spdlog::info("signal {}: stopping", *signal);
    break;
  }
  notify_systemd("STOPPING=1");
  (*daemon)->stop();
  daemon->reset();  // deletes the DDS participant: peers see us leave at once
  spdlog::info("stopped");
  shutdown_logging();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"skytrackd - radar track-processing daemon: PlotBatch in, TrackBatch out (DDS)"};
  std::string config_path;
  bool check_only = false;
  app.add_option("--config", config_path, "Daemon configuration YAML (docs/daemon.md)")->required();
  app.add_flag("--check", check_only, "Validate the configuration and its profile, then exit");
  CLI11_PARSE(app, argc, argv);
  return run(config_path, check_only);
}
