#include "dds_tool.hpp"

#include <csignal>

#include "skytrack/dds/conversion.hpp"

namespace skytrack::tool {
namespace {

volatile std::sig_atomic_t stop_flag = 0;

extern "C" void on_stop_signal(int) {
  stop_flag = 1;
}

}  // namespace

Expected<daemon::DaemonConfig> load_dds_tool_config(const std::string& path) {
  if (path.empty()) return daemon::DaemonConfig{};
  return daemon::load_daemon_config(path);
}

void add_dds_options(CLI::App& cmd, DdsToolOptions& options) {
  cmd.add_option("--config", options.config,
                 "skytrackd configuration to take the DDS domain, partition, topics and QoS from "
                 "(default: the built-in defaults of config/skytrackd.yaml)");
  cmd.add_option("--domain", options.domain, "DDS domain id (overrides the configuration)")
      ->check(CLI::Range(0, 232));
}

Expected<daemon::DaemonConfig> resolve_dds_tool_config(const DdsToolOptions& options) {
  auto config = load_dds_tool_config(options.config);
  if (config && options.domain >= 0) config->dds.domain = options.domain;
  return config;
}

Expected<dds_entity_t> open_reader(daemon::DdsSession& session,
                                   const dds_topic_descriptor_t* descriptor,
                                   const std::string& name, const dds_qos_t* qos) {
  auto topic = session.topic(descriptor, name);
  if (!topic) return unexpected(topic.error());
  return session.reader(*topic, qos);
}

Expected<daemon::DdsSession> open_tool_session(const daemon::DdsSettings& dds,
                                               const std::string& tool) {
  install_stop_handlers();
  auto session = daemon::DdsSession::open(dds);
  if (!session) return make_error("skytrack " + tool + ": " + session.error().message);
  return session;
}

Expected<PlotPipe> open_plot_pipe(const DdsToolOptions& options, const std::string& tool) {
  auto config = resolve_dds_tool_config(options);
  if (!config) return unexpected(config.error());
  const daemon::DdsSettings& dds = config->dds;
  auto session = open_tool_session(dds, tool);
  if (!session) return unexpected(session.error());
  const auto failed = [&](const Error& e) {
    return make_error("skytrack " + tool + ": " + e.message);
  };
  auto plots = session->topic(&skytrack_dds_PlotBatch_desc, dds.topics.plots);
  if (!plots) return failed(plots.error());
  auto tracks = session->topic(&skytrack_dds_TrackBatch_desc, dds.topics.tracks);
  if (!tracks) return failed(tracks.error());
  auto writer = session->writer(*plots, daemon::plots_writer_qos(dds).get());
  if (!writer) return failed(writer.error());
  auto reader = session->reader(*tracks, daemon::tracks_reader_qos(dds, true).get());
  if (!reader) return failed(reader.error());
  return PlotPipe{std::move(*config), std::move(*session), *writer, *reader};
}

void install_stop_handlers() {
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  std::signal(SIGPIPE, SIG_IGN);
}

bool stop_requested() {
  return stop_flag != 0;
}

}  // namespace skytrack::tool
