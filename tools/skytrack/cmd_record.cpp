// `skytrack record`: subscribes to TrackBatch (and optionally PlotBatch) and writes the
// CONTRACTS JSON Lines, so a live session can be evaluated with `skytrack eval` and replayed.
#include <algorithm>
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "dds_tool.hpp"
#include "skytrack/daemon/dds_session.hpp"
#include "skytrack/dds/checked_take.hpp"
#include "skytrack/dds/conversion.hpp"
#include "skytrack/io/jsonl_writer.hpp"

namespace skytrack::tool {
namespace {

using Clock = std::chrono::steady_clock;

struct RecordOptions {
  DdsToolOptions dds;
  std::string tracks;
  std::string plots;
  double until_idle = 0.0;  // [s] 0: until interrupted
  bool quiet = false;
};

/// Takes every sample of `reader` (checked as bytes before Cyclone deserialises it), converts
/// it and writes it in the order the samples were written (a take groups samples by instance,
/// i.e. by sensor); returns the number written. Malformed and unconvertible samples are
/// counted and the first 20 printed.
template <class DdsType, class Convert>
std::size_t drain(dds_entity_t reader, dds::OwnedSample<DdsType>& scratch, io::JsonLinesWriter& out,
                  std::size_t& failed, Convert convert) {
  using Record = typename decltype(convert(std::declval<const DdsType&>()))::value_type;
  std::vector<std::pair<dds_time_t, Record>> records;
  const auto refuse = [&failed](const std::string& why) {
    if (failed++ < 20) fmt::print(stderr, "skytrack record: {}\n", why);
  };
  dds::take_checked(
      reader, scratch,
      [&](const DdsType& sample, const dds_sample_info_t& info) {
        auto record = convert(sample);
        if (!record) return refuse(record.error().message);
        records.emplace_back(info.source_timestamp, std::move(*record));
      },
      [&](const dds_sample_info_t&, const Error& e) { refuse("malformed sample: " + e.message); });
  std::stable_sort(records.begin(), records.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::size_t written = 0;
  for (const auto& [when, record] : records) written += out.write(record) ? 1 : 0;
  return written;
}

/// The subscription loop: drains the readers until interrupted or idle.
struct Recorder {
  const RecordOptions& options;
  dds_entity_t tracks = 0;
  dds_entity_t plots = 0;  // 0: plots not recorded
  io::JsonLinesWriter& track_out;
  io::JsonLinesWriter* plot_out = nullptr;
  std::size_t frames = 0, scans = 0, failed = 0;
  dds::TrackBatchSample track_sample{};
  dds::PlotBatchSample plot_sample{};

  void run(dds_entity_t waitset) {
    bool matched = false;
    std::optional<Clock::time_point> last_data;
    const auto idle = std::chrono::duration<double>(options.until_idle);
    while (!stop_requested()) {
      dds_waitset_wait(waitset, nullptr, 0, DDS_MSECS(100));
      if (!matched) {
        dds_subscription_matched_status_t m{};
        dds_get_subscription_matched_status(tracks, &m);
        matched = m.current_count > 0;
        if (matched && !options.quiet) {
          fmt::print(stderr, "skytrack record: matched a TrackBatch writer\n");
        }
      }
      std::size_t got = drain(tracks, track_sample, track_out, failed,
                              [](const auto& b) { return dds::from_dds(b); });
      frames += got;
      if (plots > 0) {
        const std::size_t p = drain(plots, plot_sample, *plot_out, failed,
                                    [](const auto& b) { return dds::from_dds(b); });
        scans += p;
        got += p;
      }
      const auto now = Clock::now();
      if (got > 0) last_data = now;
      if (options.until_idle > 0.0 && last_data && now - *last_data > idle) break;
    }
  }
};

int fail(const std::string& message) {
  fmt::print(stderr, "skytrack record: {}\n", message);
  return 2;
}

int run_record(const RecordOptions& options) {
  auto config = resolve_dds_tool_config(options.dds);
  if (!config) return fail(config.error().message);
  install_stop_handlers();
  auto track_out = io::JsonLinesWriter::open(options.tracks);
  if (!track_out) return fail(track_out.error().message);
  std::optional<io::JsonLinesWriter> plot_out;
  if (!options.plots.empty()) {
    auto w = io::JsonLinesWriter::open(options.plots);
    if (!w) return fail(w.error().message);
    plot_out.emplace(std::move(*w));
  }
  auto session = daemon::DdsSession::open(config->dds);
  if (!session) return fail(session.error().message);
  const auto& dds = config->dds;
  auto tracks = open_reader(*session, &skytrack_dds_TrackBatch_desc, dds.topics.tracks,
                            daemon::tracks_reader_qos(dds, true).get());
  if (!tracks) return fail(tracks.error().message);
  Recorder recorder{options, *tracks, 0, *track_out};
  const dds_entity_t waitset = dds_create_waitset(session->participant());
  dds_waitset_attach(waitset, dds_create_readcondition(*tracks, DDS_ANY_STATE), 0);
  if (plot_out) {
    auto plots = open_reader(*session, &skytrack_dds_PlotBatch_desc, dds.topics.plots,
                             daemon::plots_reader_qos(dds).get());
    if (!plots) return fail(plots.error().message);
    recorder.plots = *plots;
    recorder.plot_out = &*plot_out;
    dds_waitset_attach(waitset, dds_create_readcondition(*plots, DDS_ANY_STATE), 0);
  }
  if (!options.quiet) {
    fmt::print(stderr, "skytrack record: recording '{}'{} on domain {}\n", dds.topics.tracks,
               plot_out ? " and '" + dds.topics.plots + "'" : std::string(), dds.domain);
  }
  recorder.run(waitset);
  const bool ok = track_out->close() && (!plot_out || plot_out->close());
  fmt::print(stderr, "skytrack record: {} track batches{} written{}\n", recorder.frames,
             plot_out ? fmt::format(", {} plot batches", recorder.scans) : std::string(),
             recorder.failed
                 ? fmt::format(", {} samples malformed or not convertible", recorder.failed)
                 : std::string());
  return ok ? 0 : fail("writing the output failed");
}

}  // namespace

void add_record_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<RecordOptions>();
  CLI::App* cmd =
      app.add_subcommand("record", "Record TrackBatch (and PlotBatch) samples to JSON Lines (DDS)");
  cmd->add_option("--tracks", options->tracks, "Track output file (JSON Lines)")->required();
  cmd->add_option("--plots", options->plots, "Also record the plot stream to this file");
  cmd->add_option("--until-idle", options->until_idle,
                  "Stop after this many seconds without data, once data has arrived (default: "
                  "until interrupted)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--quiet", options->quiet, "Only the summary");
  add_dds_options(*cmd, options->dds);
  cmd->footer(
      "Example: skytrack record --config config/skytrackd.yaml --tracks "
      "out/live.tracks.jsonl --until-idle 2\nExit codes: 0 stopped (idle or "
      "SIGINT/SIGTERM) with everything written; 2 the configuration, DDS or an output "
      "file failed; 1xx command-line mistakes (CLI11: 105 a bad value, 106 a required "
      "option missing, 109 an unknown argument).");
  cmd->callback([options, &exit_code] { exit_code = run_record(*options); });
}

}  // namespace skytrack::tool
