// skytrackd: the tracking daemon. PlotBatch in over DDS, TrackBatch and TrackerStatus out; in
// the fusion role, local trackers' TrackBatch in and the fused TrackBatch out.
// SIGINT/SIGTERM stop it (the scan in hand is finished and published, exit 0); SIGHUP reloads
// the profile. docs/daemon.md has the configuration schema, QoS, threads and signals.
#include <csignal>
#include <cstdio>
#include <string>

#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "skytrack/config/fusion_section.hpp"
#include "skytrack/daemon/daemon.hpp"
#include "skytrack/daemon/daemon_config.hpp"
#include "skytrack/daemon/fusion_node.hpp"
#include "skytrack/daemon/logging.hpp"
#include "skytrack/daemon/memory_policy.hpp"
#include "skytrack/daemon/signal_pipe.hpp"
#include "skytrack/daemon/systemd_notify.hpp"
#include "skytrack/daemon/tsan_suppressions.hpp"

namespace {

using namespace skytrack::daemon;
using skytrack::Expected;
using skytrack::unexpected;

/// The status period, signals and stop, for either role: a node with start, publish_status
/// and stop; `reload` answers SIGHUP.
template <class Node, class Reload>
void serve(Node& node, const DaemonConfig& config, Reload reload) {
  node.start();
  node.publish_status();
  notify_systemd("READY=1");
  spdlog::info("skytrackd '{}' running as {} (pid {})", config.instance, to_string(config.role),
               static_cast<long>(getpid()));
  const auto period = std::chrono::duration_cast<std::chrono::milliseconds>(
      std::chrono::duration<double>(config.status_period));
  auto next_status = std::chrono::steady_clock::now() + period;
  for (;;) {
    const auto now = std::chrono::steady_clock::now();
    if (now >= next_status) {
      node.publish_status();
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
      reload();
      notify_systemd("READY=1");
      continue;
    }
    spdlog::info("signal {}: stopping", *signal);
    break;
  }
  notify_systemd("STOPPING=1");
  node.stop();
}

/// The fusion file the configuration names, or the built-in defaults.
Expected<skytrack::fusion::FusionSpec> fusion_spec(const DaemonConfig& config) {
  if (config.fusion.config.empty()) return skytrack::fusion::FusionSpec{};
  return skytrack::config::load_fusion_config(config.fusion.config);
}

int check(const std::string& config_path, const DaemonConfig& config) {
  if (config.role == Role::kFusion) {
    auto spec = fusion_spec(config);
    if (!spec) {
      std::fprintf(stderr, "%s\n", spec.error().message.c_str());
      return 2;
    }
    std::printf(
        "%s: ok (fusion role, %s)\n", config_path.c_str(),
        config.fusion.config.empty() ? "built-in fusion parameters" : config.fusion.config.c_str());
    return 0;
  }
  auto profile = load_tracking_profile(config.profile);
  if (!profile) {
    std::fprintf(stderr, "%s\n", profile.error().message.c_str());
    return 2;
  }
  std::printf("%s: ok (profile '%s' version %s)\n", config_path.c_str(),
              profile->identity.name.c_str(), profile->identity.version.c_str());
  return 0;
}

int run(const std::string& config_path, bool check_only,
        const skytrack::daemon::MemoryPolicy& memory) {
  auto config = load_daemon_config(config_path);
  if (!config) {
    std::fprintf(stderr, "%s\n", config.error().message.c_str());
    return 2;
  }
  if (check_only) return check(config_path, *config);
  if (auto ok = setup_logging(config->logging); !ok) {
    std::fprintf(stderr, "skytrackd: %s\n", ok.error().message.c_str());
    return 2;
  }
  spdlog::info("memory: freed memory kept for the next scan: {}; heap advised for huge pages: {}",
               memory.freed_memory_kept ? "yes" : "no (C library defaults)",
               memory.huge_page_heap ? "yes" : "no");
  if (auto ok = SignalPipe::install({SIGINT, SIGTERM, SIGHUP}); !ok) {
    spdlog::critical("{}", ok.error().message);
    shutdown_logging();
    return 2;
  }
  if (config->role == Role::kFusion) {
    auto spec = fusion_spec(*config);
    auto node = spec ? FusionNode::create(*config, *spec)
                     : Expected<std::unique_ptr<FusionNode>>(unexpected(spec.error()));
    if (!node) {
      spdlog::critical("not started: {}", node.error().message);
      shutdown_logging();
      return 2;
    }
    serve(**node, *config, [] {
      spdlog::warn(
          "SIGHUP: the fusion role keeps its parameters (a reload would renumber the system "
          "tracks); restart the node to apply a changed fusion file");
    });
    node->reset();  // deletes the DDS participant: peers see us leave at once
  } else {
    auto daemon = Daemon::create(*config);
    if (!daemon) {
      spdlog::critical("not started: {}", daemon.error().message);
      shutdown_logging();
      return 2;
    }
    serve(**daemon, *config, [&] { (*daemon)->reload_profile(); });
    daemon->reset();
  }
  spdlog::info("stopped");
  shutdown_logging();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const skytrack::daemon::MemoryPolicy memory = skytrack::daemon::apply_memory_policy();
  CLI::App app{"skytrackd - radar track-processing daemon: PlotBatch in, TrackBatch out (DDS)"};
  std::string config_path;
  bool check_only = false;
  app.add_option("--config", config_path, "Daemon configuration YAML (docs/daemon.md)")->required();
  app.footer(
      "Example: skytrackd --config config/skytrackd.yaml (a tracker); skytrackd --config "
      "config/two-radars/fusion.yaml (the fusion role)\nExit codes: 0 stopped by SIGINT or "
      "SIGTERM, or --check passed; 2 an invalid configuration, profile or fusion file, or DDS "
      "or an input unavailable; 1xx command-line mistakes (CLI11).");
  app.add_flag("--check", check_only,
               "Validate the configuration and its profile (or fusion file), then exit");
  CLI11_PARSE(app, argc, argv);
  return run(config_path, check_only, memory);
}
