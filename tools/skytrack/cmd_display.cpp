// `skytrack display`: the operator's live picture in a browser. Subscribes to PlotBatch,
// TrackBatch and TrackerStatus (the other DDS tools' configuration and loopback rules) or
// replays recorded files, and serves the page (tools/skytrack/display/) with the picture as
// server-sent events. Its own process: a slow browser can never slow the daemon.
#include <memory>
#include <string>
#include <thread>

#include <fmt/format.h>

#include "commands.hpp"
#include "dds_tool.hpp"
#include "display_replay.hpp"
#include "display_server.hpp"
#include "skytrack/daemon/dds_session.hpp"
#include "skytrack/dds/checked_take.hpp"
#include "skytrack/dds/conversion.hpp"
#include "skytrack/display/picture.hpp"

namespace skytrack::tool {
namespace {

struct DisplayOptions {
  DdsToolOptions dds;
  std::string listen = "127.0.0.1:8080";
  std::string web_root;
  std::string plots, tracks, truth;  // offline replay
  double rate = 1.0;
  int plot_scans = 4;
};

int fail(const std::string& message) {
  fmt::print(stderr, "skytrack display: {}\n", message);
  return 2;
}

// The display must never hold up the daemon or a replay: its plot reader is best effort and
// keeps the last batch per sensor, so a display that falls behind loses plots, not the
// writer's time. Tracks and status keep their usual QoS (keep-last: no back-pressure either).
daemon::QosPtr display_plots_qos() {
  daemon::QosPtr qos(dds_create_qos());
  dds_qset_reliability(qos.get(), DDS_RELIABILITY_BEST_EFFORT, 0);
  dds_qset_history(qos.get(), DDS_HISTORY_KEEP_LAST, 1);
  return qos;
}

struct LiveReaders {
  dds_entity_t plots = 0, tracks = 0, status = 0;
};

Expected<LiveReaders> open_live_readers(daemon::DdsSession& session,
                                        const daemon::DdsSettings& dds) {
  LiveReaders r;
  auto plots = open_reader(session, &skytrack_dds_PlotBatch_desc, dds.topics.plots,
                           display_plots_qos().get());
  if (!plots) return unexpected(plots.error());
  auto tracks = open_reader(session, &skytrack_dds_TrackBatch_desc, dds.topics.tracks,
                            daemon::tracks_reader_qos(dds, false).get());
  if (!tracks) return unexpected(tracks.error());
  auto status = open_reader(session, &skytrack_dds_TrackerStatus_desc, dds.topics.status,
                            daemon::status_reader_qos(dds).get());
  if (!status) return unexpected(status.error());
  return LiveReaders{*plots, *tracks, *status};
}

/// Takes what arrived on `reader` (checked before Cyclone deserialises it) into the picture.
template <class DdsType, class Add>
void drain(dds_entity_t reader, dds::OwnedSample<DdsType>& scratch, std::size_t& refused, Add add) {
  dds::take_checked(
      reader, scratch,
      [&](const DdsType& sample, const dds_sample_info_t&) {
        auto record = dds::from_dds(sample);
        if (!record) {
          if (refused++ < 20) fmt::print(stderr, "skytrack display: {}\n", record.error().message);
          return;
        }
        add(std::move(*record));
      },
      [&](const dds_sample_info_t&, const Error& e) {
        if (refused++ < 20)
          fmt::print(stderr, "skytrack display: malformed sample: {}\n", e.message);
      });
}

int run_live(const DisplayOptions& options, display::Picture& picture) {
  auto config = resolve_dds_tool_config(options.dds);
  if (!config) return fail(config.error().message);
  auto session = open_tool_session(config->dds, "display");
  if (!session) return fail(session.error().message);
  auto readers = open_live_readers(*session, config->dds);
  if (!readers) return fail(readers.error().message);
  const dds_entity_t waitset = dds_create_waitset(session->participant());
  for (const dds_entity_t r : {readers->plots, readers->tracks, readers->status}) {
    dds_waitset_attach(waitset, dds_create_readcondition(r, DDS_ANY_STATE), 0);
  }
  fmt::print(stderr, "skytrack display: live on domain {} ('{}', '{}', '{}')\n", config->dds.domain,
             config->dds.topics.plots, config->dds.topics.tracks, config->dds.topics.status);
  dds::PlotBatchSample plot_sample;
  dds::TrackBatchSample track_sample;
  dds::TrackerStatusSample status_sample;
  std::size_t refused = 0;
  while (!stop_requested()) {
    dds_waitset_wait(waitset, nullptr, 0, DDS_MSECS(100));
    drain(readers->plots, plot_sample, refused, [&](PlotScan s) { picture.add_plots(s); });
    drain(readers->tracks, track_sample, refused,
          [&](TrackFrame f) { picture.add_tracks(std::move(f)); });
    drain(readers->status, status_sample, refused,
          [&](TrackerStatusReport s) { picture.add_status(std::move(s)); });
  }
  return 0;
}

int run_display(const DisplayOptions& options) {
  const bool offline = !options.plots.empty() || !options.tracks.empty();
  if (offline && (options.plots.empty() || options.tracks.empty())) {
    return fail("an offline replay needs both --plots and --tracks");
  }
  auto address = parse_listen_address(options.listen);
  if (!address) return fail(address.error().message);
  auto web_root = find_web_root(options.web_root);
  if (!web_root) return fail(web_root.error().message);
  install_stop_handlers();
  display::Picture picture(options.plot_scans);
  std::unique_ptr<DisplayReplay> replay;
  ControlHandler control;
  if (offline) {
    auto files = load_replay_files(options.plots, options.tracks, options.truth);
    if (!files) return fail(files.error().message);
    replay = std::make_unique<DisplayReplay>(picture, std::move(*files), options.rate);
    control = [&replay](const std::string& cmd, double rate) { return replay->control(cmd, rate); };
  }
  DisplayServer server(picture, *web_root, control);
  auto port = server.start(*address);
  if (!port) return fail(port.error().message);
  if (!is_loopback_host(address->host)) {
    fmt::print(stderr,
               "skytrack display: warning: listening on {} (not loopback): the picture is "
               "visible from the network\n",
               address->host);
  }
  const bool v6 = address->host.find(':') != std::string::npos;
  fmt::print(stderr, "skytrack display: serving http://{}:{}/ ({}, page from {})\n",
             v6 ? "[" + address->host + "]" : address->host, *port,
             offline ? "offline replay" : "live", *web_root);
  int code = 0;
  if (replay) {
    replay->run([] { return stop_requested(); });
  } else {
    code = run_live(options, picture);
  }
  server.stop();
  return code;
}

}  // namespace

void add_display_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<DisplayOptions>();
  CLI::App* cmd = app.add_subcommand(
      "display", "Serve the live picture (plots, tracks, status) to a web browser (DDS or files)");
  cmd->add_option("--listen", options->listen,
                  "HOST:PORT to serve on; a loopback address unless you mean the network to see "
                  "it (port 0 picks a free one)")
      ->default_val(options->listen);
  cmd->add_option("--web-root", options->web_root,
                  "Folder of the page's files (default: share/skytrack/display of the install, "
                  "or the source tree)");
  cmd->add_option("--plots", options->plots, "Offline replay: plot stream (JSON Lines)");
  cmd->add_option("--tracks", options->tracks, "Offline replay: track output (JSON Lines)");
  cmd->add_option("--truth", options->truth, "Offline replay: ground truth to draw as well");
  cmd->add_option("--rate", options->rate, "Offline replay speed, times the data's own time")
      ->default_val(1.0)
      ->check(CLI::PositiveNumber);
  cmd->add_option("--plot-scans", options->plot_scans, "Scans of plots shown, fading out")
      ->default_val(4)
      ->check(CLI::Range(1, 20));
  add_dds_options(*cmd, options->dds);
  cmd->footer(
      "Examples:\n"
      "  skytrack display --config config/skytrackd.yaml          # live, http://127.0.0.1:8080/\n"
      "  skytrack display --plots out/default.plots.jsonl --tracks out/default.tracks.jsonl \\\n"
      "      --truth out/default.truth.jsonl --rate 5                # offline replay\n"
      "Exit codes: 0 stopped by SIGINT/SIGTERM; 2 bad option, configuration or input file, "
      "DDS or the listening address unavailable; 105-115 command-line syntax (CLI11).");
  cmd->callback([options, &exit_code] { exit_code = run_display(*options); });
}

}  // namespace skytrack::tool
