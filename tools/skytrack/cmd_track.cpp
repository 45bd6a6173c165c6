// `skytrack track`: a plot stream through the Pipeline (the daemon's code path) into track
// output, with a progress bar and the figures that matter printed at the end.
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "progress_bar.hpp"
#include "skytrack/config/profile_loader.hpp"
#include "skytrack/io/jsonl_reader.hpp"
#include "skytrack/io/jsonl_writer.hpp"
#include "skytrack/pipeline/pipeline.hpp"

namespace skytrack::tool {
namespace {

struct TrackOptions {
  std::string profile;
  std::string plots;
  std::string out;
  bool quiet = false;
};

/// Peak resident set size of this process [MiB].
double peak_rss_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

double per_batch_ms(std::chrono::microseconds total, std::size_t batches) {
  return batches == 0 ? 0.0
                      : static_cast<double>(total.count()) / 1000.0 / static_cast<double>(batches);
}

double mean(const std::vector<double>& values) {
  double sum = 0.0;
  for (const double v : values) sum += v;
  return values.empty() ? 0.0 : sum / static_cast<double>(values.size());
}

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  const auto k = static_cast<std::size_t>(p * static_cast<double>(values.size() - 1));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

int run_track(const TrackOptions& options) {
  config::TrackingProfile profile;  // the shipped default point-tracking profile
  profile.identity = {"default", "1", "built-in default point-tracking profile"};
  if (!options.profile.empty()) {
    auto loaded = config::load_profile(options.profile);
    if (!loaded) {
      fmt::print(stderr, "{}\n", loaded.error().message);
      return 2;
    }
    profile = std::move(*loaded);
  }
  auto pipeline = Pipeline::create(profile);
  if (!pipeline) {
    fmt::print(stderr, "skytrack track: {}\n", pipeline.error().message);
    return 2;
  }
  std::size_t shown = 0;
  auto reader = io::PlotStreamReader::open(options.plots, [&](const io::LineError& e) {
    if (shown++ < 20) fmt::print(stderr, "{}\n", io::to_string(e));
  });
  if (!reader) {
    fmt::print(stderr, "skytrack track: {}\n", reader.error().message);
    return 2;
  }
  auto writer = io::JsonLinesWriter::open(options.out);
  if (!writer) {
    fmt::print(stderr, "skytrack track: {}\n", writer.error().message);
    return 2;
  }
  ProgressBar progress(!options.quiet);
  std::vector<double> latency_ms;
  std::size_t rejected_scans = 0, initiated = 0, refused = 0, held = 0, max_tracks = 0;
  std::chrono::microseconds predict{}, associate{}, manage{};
  const auto start = std::chrono::steady_clock::now();
  while (auto scan = reader->next()) {
    const auto t0 = std::chrono::steady_clock::now();
    const ScanResult& result = pipeline->process(*scan);
    latency_ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    if (result.refused) {  // the profile cannot serve this stream: stop, do not track on
      progress.finish();
      fmt::print(stderr, "skytrack track: {}: batch {}: {}\n", options.plots, scan->scan,
                 result.rejection);
      return 2;
    }
    if (!result.accepted) {
      if (rejected_scans++ < 20)
        fmt::print(stderr, "\n{}: batch skipped: {}\n", options.plots, result.rejection);
      continue;
    }
    if (const std::string change = timeline_change(result); !change.empty()) {
      fmt::print(stderr, "\n{}: sensor {} batch {} (t = {}): {}\n", options.plots, scan->sensor,
                 scan->scan, scan->time, change);
    }
    initiated += static_cast<std::size_t>(result.report.initiated);
    refused += static_cast<std::size_t>(result.report.initiations_refused);
    held += static_cast<std::size_t>(result.report.chains_held);
    predict += result.report.predict;
    associate += result.report.associate;
    manage += result.report.manage;
    max_tracks = std::max(max_tracks, result.frame.tracks.size());
    if (!writer->write(result.frame)) {
      fmt::print(stderr, "skytrack track: writing {} failed\n", options.out);
      return 2;
    }
    progress.update(reader->bytes_read(), reader->file_size(), latency_ms.size());
  }
  progress.finish();
  if (reader->read_error()) {
    fmt::print(stderr, "skytrack track: {}\n", *reader->read_error());
    return 2;
  }
  if (!writer->close()) {
    fmt::print(stderr, "skytrack track: writing {} failed\n", options.out);
    return 2;
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const PipelineCounters& c = pipeline->counters();
  fmt::print(
      stderr,
      "skytrack track: profile '{}': {} batches ({} skipped), {} plots ({} invalid, {} "
      "rejected as clutter), {} lines rejected, {} numeric failures\n"
      "  tracks initiated {}, most at once {}; initiations refused (max_tentative) {}; chains "
      "held for their next plot {}\n"
      "  per batch: mean {:.3f} ms, p50 {:.3f} ms, p99 {:.3f} ms, max {:.3f} ms; wall {:.2f} s; "
      "peak RSS {:.1f} MiB\n"
      "  stages, mean per batch: gating {:.3f} ms, association {:.3f} ms, management {:.3f} ms\n",
      profile.identity.name, c.scans_processed, c.scans_rejected, c.plots_processed,
      c.plots_invalid, c.plots_rejected_clutter, reader->counts().rejected_lines,
      c.numeric_failures, initiated, max_tracks, refused, held, mean(latency_ms),
      percentile(latency_ms, 0.5), percentile(latency_ms, 0.99),
      latency_ms.empty() ? 0.0 : *std::max_element(latency_ms.begin(), latency_ms.end()), wall,
      peak_rss_mib(), per_batch_ms(predict, latency_ms.size()),
      per_batch_ms(associate, latency_ms.size()), per_batch_ms(manage, latency_ms.size()));
  return 0;
}

}  // namespace

void add_track_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<TrackOptions>();
  CLI::App* cmd =
      app.add_subcommand("track", "Track a plot stream offline (the daemon's pipeline)");
  cmd->add_option("--profile", options->profile,
                  "Tracking profile YAML (default: the built-in point-tracking profile)");
  cmd->add_option("--plots", options->plots, "Input plot stream (JSON Lines)")->required();
  cmd->add_option("--out", options->out, "Output track stream (JSON Lines)")->required();
  cmd->add_flag("--quiet", options->quiet, "No progress bar");
  cmd->footer(
      "Example: skytrack track --profile config/profiles/default.yaml --plots "
      "out/default.plots.jsonl --out out/offline.tracks.jsonl\nExit codes: 0 done (bad "
      "lines are reported and skipped); 2 the profile is invalid or a file cannot be "
      "read or written; 1xx command-line mistakes (CLI11: 105 a bad value, 106 a "
      "required option missing, 109 an unknown argument).");
  cmd->callback([options, &exit_code] { exit_code = run_track(*options); });
}

}  // namespace skytrack::tool
