#pragma once
// What the DDS subcommands (replay, record, status, bench-latency) share: the daemon
// configuration they take their domain, partition, topics and QoS from, and a stop flag set by
// SIGINT/SIGTERM.
#include <atomic>
#include <string>

#include <CLI/CLI.hpp>

#include "skytrack/core/expected.hpp"
#include "skytrack/daemon/daemon_config.hpp"
#include "skytrack/daemon/dds_session.hpp"

namespace skytrack::tool {

/// The daemon configuration at `path`, or the built-in defaults (those of
/// config/skytrackd.yaml) when `path` is empty.
Expected<daemon::DaemonConfig> load_dds_tool_config(const std::string& path);

/// Adds --config and --domain (which overrides the configuration's domain) to a subcommand.
struct DdsToolOptions {
  std::string config;
  int domain = -1;
};
void add_dds_options(CLI::App& cmd, DdsToolOptions& options);
/// The configuration with --domain applied; prints the error and returns nullopt-like failure.
Expected<daemon::DaemonConfig> resolve_dds_tool_config(const DdsToolOptions& options);

/// Installs the stop handlers and opens the DDS session of `dds`; a failure's message names
/// the tool ("skytrack <tool>: ...").
Expected<daemon::DdsSession> open_tool_session(const daemon::DdsSettings& dds,
                                               const std::string& tool);

/// What replay and bench-latency publish and listen with: the resolved configuration, its
/// session, a PlotBatch writer and a TrackBatch reader (keep-all) with the configured topics
/// and QoS. A failure's message names the tool.
struct PlotPipe {
  daemon::DaemonConfig config;
  daemon::DdsSession session;
  dds_entity_t writer = 0;
  dds_entity_t reader = 0;
};
Expected<PlotPipe> open_plot_pipe(const DdsToolOptions& options, const std::string& tool);

/// A reader on topic `name` of type `descriptor`, created in `session`.
Expected<dds_entity_t> open_reader(daemon::DdsSession& session,
                                   const dds_topic_descriptor_t* descriptor,
                                   const std::string& name, const dds_qos_t* qos);

/// Installs SIGINT/SIGTERM handlers that set stop_requested().
void install_stop_handlers();
bool stop_requested();

}  // namespace skytrack::tool
