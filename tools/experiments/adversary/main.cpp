// skytrack-adversary: adversarial load against a running skytrackd over DDS (loopback only,
// a private domain). A good sensor's batches are replayed at their pace throughout while a
// second sensor, in phases, sends plot clouds of growing size, bursts of batches, batches just
// under and over max_plots_per_scan, malformed samples and a hijack of its own clock. Per
// phase it prints the good sensor's latency, the daemon's rejections, drops, queue depth and
// memory, and at the end whether the good sensor's tracks stayed those of an offline run of
// its batches alone. tools/experiments/adversarial-load.sh starts the daemon and runs it.
// Exit: 0 the run completed, 1 it stopped early (daemon gone, memory or time bound), 2 bad
// usage or setup, 3 no daemon answered.
#include <filesystem>

#include <fmt/format.h>

#include "adversary_actions.hpp"
#include "adversary_batches.hpp"
#include "adversary_geometry.hpp"
#include "dds_link.hpp"
#include "frame_comparison.hpp"
#include "good_stream.hpp"
#include "live_run.hpp"
#include "options.hpp"
#include "phase_plan.hpp"
#include "report.hpp"
#include "skytrack/daemon/daemon.hpp"
#include "skytrack/daemon/daemon_config.hpp"
#include "skytrack/daemon/tsan_suppressions.hpp"

namespace skytrack::adversary {
namespace {

namespace fs = std::filesystem;

constexpr std::uint64_t kAdversarySeed = 20260430;

/// The shipped default scenario: beside the build tree, else in the source tree built from.
std::string default_scenario() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path beside = (self.parent_path() / "../../../../config/scenarios/default.yaml");
    if (fs::exists(beside)) return beside.lexically_normal().string();
  }
  return std::string(SKYTRACK_SOURCE_DIR) + "/config/scenarios/default.yaml";
}

/// The daemon's configuration (domain, topics, QoS, profile, limits) with the options applied.
Expected<daemon::DaemonConfig> daemon_config(const Options& options) {
  daemon::DaemonConfig config;
  if (!options.config.empty()) {
    auto loaded = daemon::load_daemon_config(options.config);
    if (!loaded) return unexpected(loaded.error());
    config = std::move(*loaded);
  } else {
    config.dds.domain = kDefaultDomain;
  }
  if (options.domain > 0) config.dds.domain = options.domain;
  if (config.dds.domain == 0) {
    return make_error(
        "DDS domain 0 is the shipped default: give the daemon and this tool a "
        "private domain (--domain, e.g. 231)");
  }
  return config;
}

int run(const Options& options) {
  auto dds = require_loopback();
  if (!dds) {
    fmt::print(stderr, "skytrack-adversary: {}\n", dds.error().message);
    return 2;
  }
  auto config = daemon_config(options);
  if (!config) {
    fmt::print(stderr, "skytrack-adversary: {}\n", config.error().message);
    return 2;
  }
  const int max_plots = options.max_plots > 0 ? options.max_plots : config->max_plots_per_scan;
  auto profile =
      daemon::load_tracking_profile(options.profile.empty() ? config->profile : options.profile);
  auto good = profile ? load_good_stream(options, default_scenario(), planned_duration(options))
                      : unexpected(profile.error());
  if (!good) {
    fmt::print(stderr, "skytrack-adversary: {}\n", good.error().message);
    return 2;
  }
  const AdversaryGeometry geometry = place_adversary(good->scans);
  const std::vector<Phase> phases = plan_phases(options, max_plots, good->start);
  // The offline run first, so that it does not share the machine with the live one.
  auto offline = offline_frames(*profile, good->scans);
  if (!offline) {
    fmt::print(stderr, "skytrack-adversary: offline run: {}\n", offline.error().message);
    return 2;
  }
  fmt::print(stderr, "skytrack-adversary: {}; domain {}; profile '{}'\n", *dds, config->dds.domain,
             profile->identity.name);
  auto link = DdsLink::open(config->dds, good->sensor);
  if (!link) {
    fmt::print(stderr, "skytrack-adversary: {}\n", link.error().message);
    return 2;
  }
  const auto wait = std::chrono::milliseconds(static_cast<long long>(options.wait * 1e3));
  if (!(*link)->wait_for_daemon(wait)) {
    fmt::print(stderr,
               "skytrack-adversary: no skytrackd on domain {} within {} s (plot reader, track "
               "and status writers)\n",
               config->dds.domain, options.wait);
    return 3;
  }
  (*link)->listen();
  AdversaryBatches batches(geometry, options.adversary_sensor, kAdversarySeed);
  Adversary adversary(batches, **link, options);
  const RunRecord record = run_live(options, *good, phases, **link, adversary);
  print_report({options, *good, phases, record, *offline, geometry});
  return record.stopped.empty() ? 0 : 1;
}

}  // namespace
}  // namespace skytrack::adversary

int main(int argc, char** argv) {
  skytrack::adversary::Options options;
  if (auto code = skytrack::adversary::parse_options(argc, argv, options)) return *code;
  return skytrack::adversary::run(options);
}
