// `skytrack record`: subscribes to TrackBatch (and optionally PlotBatch) and writes the
// CONTRACTS JSON Lines, so a live session can be evaluated with `skytrack eval` and replayed.
#include <algorithm>
#include <array>
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

/// Takes every sample of `reader`, converts it and writes it in the order the samples were
/// written (a take groups samples by instance, i.e. by sensor); returns the number written.
template <class DdsType, class Convert>
std::size_t drain(dds_entity_t reader, io::JsonLinesWriter& out, std::size_t& failed,
                  Convert convert) {
  using Record = typename decltype(convert(std::declval<const DdsType&>()))::value_type;
  std::vector<std::pair<dds_time_t, Record>> records;
  std::array<void*, 32> samples{};
  std::array<dds_sample_info_t, 32> infos{};
  for (;;) {
    const dds_return_t n = dds_take(reader, samples.data(), infos.data(), 32, 32);
    if (n <= 0) break;
    for (dds_return_t i = 0; i < n; ++i) {
      const dds_sample_info_t& info = infos[static_cast<std::size_t>(i)];
      if (!info.valid_data) continue;
      auto record = convert(*static_cast<const DdsType*>(samples[static_cast<std::size_t>(i)]));
      if (!record) {
        if (failed++ < 20) fmt::print(stderr, "skytrack record: {}\n", record.error().message);
        continue;
      }
      records.emplace_back(info.source_timestamp, std::move(*record));
    }
    dds_return_loan(reader, samples.data(), n);
    if (n < 32) break;
  }
  std::stable_sort(records.begin(), records.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::size_t written = 0;
  for (const auto& [when, record] : records) written += out.write(record) ? 1 : 0;
  return written;
}

int run_record(const RecordOptions& options) {
  auto config = resolve_dds_tool_config(options.dds);
  if (!config) {
    fmt::print(stderr, "{}\n", config.error().message);
    return 2;
  }
  install_stop_handlers();
  auto track_out = io::JsonLinesWriter::open(options.tracks);
  if (!track_out) {
    fmt::print(stderr, "skytrack record: {}\n", track_out.error().message);
    return 2;
  }
  std::optional<io::JsonLinesWriter> plot_out;
  if (!options.plots.empty()) {
    auto w = io::JsonLinesWriter::open(options.plots);
    if (!w) {
      fmt::print(stderr, "skytrack record: {}\n", w.error().message);
      return 2;
    }
    plot_out.emplace(std::move(*w));
  }
  auto session = daemon::DdsSession::open(config->dds);
  if (!session) {
    fmt::print(stderr, "skytrack record: {}\n", session.error().message);
    return 2;
  }
  const auto& dds = config->dds;
  auto tracks_topic = session->topic(&skytrack_dds_TrackBatch_desc, dds.topics.tracks);
  if (!tracks_topic) {
    fmt::print(stderr, "skytrack record: {}\n", tracks_topic.error().message);
    return 2;
  }
  auto tracks = session->reader(*tracks_topic, daemon::tracks_reader_qos(dds, true).get());
  if (!tracks) {
    fmt::print(stderr, "skytrack record: {}\n", tracks.error().message);
    return 2;
  }
  dds_entity_t plots = 0;
  if (plot_out) {
    auto plots_topic = session->topic(&skytrack_dds_PlotBatch_desc, dds.topics.plots);
    Expected<dds_entity_t> r = unexpected(Error{});
    if (plots_topic) {
      r = session->reader(*plots_topic, daemon::plots_reader_qos(dds).get());
    } else {
      r = unexpected(plots_topic.error());
    }
    if (!r) {
      fmt::print(stderr, "skytrack record: {}\n", r.error().message);
      return 2;
    }
    plots = *r;
  }
  const dds_entity_t waitset = dds_create_waitset(session->participant());
  dds_waitset_attach(waitset, dds_create_readcondition(*tracks, DDS_ANY_STATE), 0);
  if (plots > 0) dds_waitset_attach(waitset, dds_create_readcondition(plots, DDS_ANY_STATE), 0);
  if (!options.quiet) {
    fmt::print(stderr, "skytrack record: recording '{}'{} on domain {}\n", dds.topics.tracks,
               plots > 0 ? " and '" + dds.topics.plots + "'" : std::string(), dds.domain);
  }
  bool matched = false;
  std::size_t frames = 0, scans = 0, failed = 0;
  std::optional<Clock::time_point> last_data;
  const auto idle = std::chrono::duration<double>(options.until_idle);
  while (!stop_requested()) {
    dds_waitset_wait(waitset, nullptr, 0, DDS_MSECS(100));
    if (!matched) {
      dds_subscription_matched_status_t m{};
      dds_get_subscription_matched_status(*tracks, &m);
      if (m.current_count > 0) {
        matched = true;
        if (!options.quiet) fmt::print(stderr, "skytrack record: matched a TrackBatch writer\n");
      }
    }
    std::size_t got = drain<skytrack_dds_TrackBatch>(
        *tracks, *track_out, failed, [](const auto& b) { return dds::from_dds(b); });
    frames += got;
    if (plots > 0) {
      const std::size_t p = drain<skytrack_dds_PlotBatch>(
          plots, *plot_out, failed, [](const auto& b) { return dds::from_dds(b); });
      scans += p;
      got += p;
    }
    const auto now = Clock::now();
    if (got > 0) last_data = now;
    if (options.until_idle > 0.0 && last_data && now - *last_data > idle) break;
  }
  const bool ok = track_out->close() && (!plot_out || plot_out->close());
  fmt::print(stderr, "skytrack record: {} track batches{} written{}\n", frames,
             plot_out ? fmt::format(", {} plot batches", scans) : std::string(),
             failed ? fmt::format(", {} samples not convertible", failed) : std::string());
  if (!ok) {
    fmt::print(stderr, "skytrack record: writing the output failed\n");
    return 2;
  }
  return 0;
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
  cmd->callback([options, &exit_code] { exit_code = run_record(*options); });
}

}  // namespace skytrack::tool
