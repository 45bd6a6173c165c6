// `skytrack fuse`: the fusion role offline. Reads several local trackers' track files, feeds
// their frames to TrackFusion (the object skytrackd runs in the fusion role) merged in time
// order, ties by input order, and writes the fused frames (docs/fusion.md).
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "skytrack/config/fusion_section.hpp"
#include "skytrack/fusion/track_fusion.hpp"
#include "skytrack/io/jsonl_reader.hpp"
#include "skytrack/io/jsonl_writer.hpp"

namespace skytrack::tool {
namespace {

constexpr std::size_t kMaxErrorsShown = 20;  // per file, then only counted

struct FuseOptions {
  std::vector<std::string> tracks;
  std::string out, config;
};

struct Input {
  std::unique_ptr<io::TrackReader> reader;
  std::optional<TrackFrame> head;
  std::size_t shown = 0;
};

int run_fuse(const FuseOptions& options) {
  fusion::FusionSpec spec;
  if (!options.config.empty()) {
    auto loaded = config::load_fusion_config(options.config);
    if (!loaded) {
      fmt::print(stderr, "{}\n", loaded.error().message);
      return 2;
    }
    spec = *loaded;
  }
  std::vector<Input> inputs(options.tracks.size());
  for (std::size_t i = 0; i < options.tracks.size(); ++i) {
    std::size_t& shown = inputs[i].shown;
    auto reader = io::TrackReader::open(options.tracks[i], [&shown](const io::LineError& e) {
      if (shown < kMaxErrorsShown) fmt::print(stderr, "{}\n", io::to_string(e));
      if (shown == kMaxErrorsShown) {
        fmt::print(stderr, "{}: further rejected lines are counted, not shown\n", e.file);
      }
      ++shown;
    });
    if (!reader) {
      fmt::print(stderr, "{}\n", reader.error().message);
      return 2;
    }
    inputs[i].reader = std::make_unique<io::TrackReader>(std::move(*reader));
    inputs[i].head = inputs[i].reader->next();
  }
  auto writer = io::JsonLinesWriter::open(options.out);
  if (!writer) {
    fmt::print(stderr, "{}\n", writer.error().message);
    return 2;
  }

  fusion::TrackFusion fusion(spec);
  std::size_t cycles_out = 0;
  bool write_ok = true;
  std::chrono::nanoseconds busy{0};
  const auto emit = [&](const std::vector<TrackFrame>& frames) {
    for (const TrackFrame& f : frames) write_ok = writer->write(f) && write_ok;
    cycles_out += frames.size();
  };
  for (;;) {
    // The earliest head frame; ties go to the earlier input.
    Input* next = nullptr;
    for (Input& in : inputs) {
      if (in.head && (next == nullptr || in.head->time < next->head->time)) next = &in;
    }
    if (next == nullptr) break;
    const auto start = std::chrono::steady_clock::now();
    const std::vector<TrackFrame> frames = fusion.add(*next->head);
    busy += std::chrono::steady_clock::now() - start;
    emit(frames);
    next->head = next->reader->next();
  }
  const auto start = std::chrono::steady_clock::now();
  const std::vector<TrackFrame> rest = fusion.flush();
  busy += std::chrono::steady_clock::now() - start;
  emit(rest);
  write_ok = writer->close() && write_ok;

  std::size_t rejected = 0;
  for (const Input& in : inputs) {
    rejected += in.reader->counts().rejected_lines;
    if (in.reader->read_error()) fmt::print(stderr, "{}\n", *in.reader->read_error());
  }
  const fusion::FusionCounters& c = fusion.counters();
  const double ms_per_cycle = cycles_out > 0
                                  ? std::chrono::duration<double, std::milli>(busy).count() /
                                        static_cast<double>(cycles_out)
                                  : 0.0;
  fmt::print(
      "frames in: {} ({} late, {} invalid, {} dropped; {} tracks invalid; {} lines rejected)\n"
      "cycles out: {} ({} skipped over gaps), system tracks: {}, sensors dropped: {}\n"
      "fusion: {:.3f} ms per cycle, {} pairs scored\n",
      c.frames, c.frames_late, c.frames_invalid, c.frames_dropped, c.tracks_invalid, rejected,
      cycles_out, c.cycles_skipped, c.system_tracks, c.sensors_dropped, ms_per_cycle,
      c.pairs_scored);
  if (!write_ok) {
    fmt::print(stderr, "{}: write failed\n", options.out);
    return 2;
  }
  return 0;
}

}  // namespace

void add_fuse_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<FuseOptions>();
  CLI::App* cmd = app.add_subcommand(
      "fuse", "Fuse several trackers' track files into system tracks (paper 004 MOSPA)");
  cmd->add_option("--tracks", options->tracks, "Local track file (JSON Lines), one per tracker")
      ->required()
      ->take_all();
  cmd->add_option("--out", options->out, "Fused track file")->required();
  cmd->add_option("--config", options->config,
                  "Fusion configuration (config/fusion.yaml; default: its defaults)");
  cmd->footer(
      "Example: skytrack fuse --tracks radarA.tracks.jsonl --tracks radarB.tracks.jsonl "
      "--out fused.tracks.jsonl\n"
      "Exit codes: 0 done (bad lines are reported and counted), 2 a file cannot be read or "
      "written, or the configuration is wrong.");
  cmd->callback([options, &exit_code] { exit_code = run_fuse(*options); });
}

}  // namespace skytrack::tool
