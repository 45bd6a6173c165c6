// `skytrack rebatch`: delivers a plot stream's plots in other batches, as a radar feed might:
// by antenna sector or in blocks of a few plots, without `coverage`. Each plot keeps its own
// time (the batch time given to it when it had none), its id and its batch's platform state
// and sigmas; a new batch is stamped with its latest plot's time. For checking that the
// tracks do not depend on the batching (tools/experiments/compare-batching.sh).
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "skytrack/io/jsonl_reader.hpp"
#include "skytrack/io/jsonl_writer.hpp"
#include "skytrack/pipeline/antenna_sweep.hpp"

namespace skytrack::tool {
namespace {

struct RebatchOptions {
  std::string plots, out;
  int sectors = 0;  // per revolution, by body azimuth clockwise from the nose
  int block = 0;    // plots per batch
  bool keep_coverage = false;
};

/// One sensor's batch being filled.
class Batcher {
 public:
  Batcher(const RebatchOptions& options, io::JsonLinesWriter& out) : options_(options), out_(out) {}

  /// Adds an input batch's plots in time order; writes the batches they complete.
  bool add(const PlotScan& input) {
    std::vector<Plot> plots = input.plots;
    for (Plot& p : plots) p.time = plot_time(p, input);
    std::stable_sort(plots.begin(), plots.end(),
                     [](const Plot& a, const Plot& b) { return *a.time < *b.time; });
    for (Plot& plot : plots) {
      const int key = options_.sectors > 0 ? sector_of(plot, input.platform) : 0;
      // A batch holds one sector, one header (platform, sigmas), unique ids, at most `block`.
      const bool full =
          options_.block > 0 && static_cast<int>(batch_.plots.size()) >= options_.block;
      if (open_ && (full || key != key_ || batch_.platform != input.platform ||
                    batch_.sigma != input.sigma || ids_.count(plot.id) > 0)) {
        if (!flush()) return false;
      }
      if (!open_) start(input, key);
      ids_.insert(plot.id);
      batch_.time = std::max(batch_.time, *plot.time);
      batch_.plots.push_back(std::move(plot));
    }
    return true;
  }

  bool flush() {
    if (!open_) return true;
    open_ = false;
    batch_.scan = next_scan_++;
    return out_.write(batch_);
  }

 private:
  int sector_of(const Plot& plot, const PlatformState& platform) const {
    const double turn = 2.0 * std::numbers::pi;
    const double a = std::fmod(std::fmod(body_azimuth(plot, platform), turn) + turn, turn);
    return std::min(options_.sectors - 1, static_cast<int>(a / turn * options_.sectors));
  }
  void start(const PlotScan& input, int key) {
    batch_ = input;
    batch_.plots.clear();
    if (!options_.keep_coverage) batch_.coverage.reset();
    batch_.time = -INFINITY;
    ids_.clear();
    key_ = key;
    open_ = true;
  }

  const RebatchOptions& options_;
  io::JsonLinesWriter& out_;
  PlotScan batch_;
  std::set<std::int64_t> ids_;
  int key_ = 0;
  bool open_ = false;
  std::uint64_t next_scan_ = 0;
};

int run_rebatch(const RebatchOptions& options) {
  if ((options.sectors > 0) == (options.block > 0)) {
    fmt::print(stderr, "skytrack rebatch: give one of --sectors N or --block N\n");
    return 2;
  }
  auto reader = io::PlotStreamReader::open(
      options.plots, [](const io::LineError& e) { fmt::print(stderr, "{}\n", io::to_string(e)); });
  if (!reader) {
    fmt::print(stderr, "skytrack rebatch: {}\n", reader.error().message);
    return 2;
  }
  auto writer = io::JsonLinesWriter::open(options.out);
  if (!writer) {
    fmt::print(stderr, "skytrack rebatch: {}\n", writer.error().message);
    return 2;
  }
  std::map<std::uint32_t, Batcher> batchers;
  std::size_t in = 0;
  bool ok = true;
  while (std::optional<PlotScan> scan = reader->next()) {
    ++in;
    auto it = batchers.try_emplace(scan->sensor, options, *writer).first;
    ok = it->second.add(*scan) && ok;
  }
  if (reader->read_error()) {
    fmt::print(stderr, "skytrack rebatch: {}\n", *reader->read_error());
    return 2;
  }
  for (auto& [sensor, batcher] : batchers) ok = batcher.flush() && ok;
  ok = writer->close() && ok;
  if (!ok) {
    fmt::print(stderr, "skytrack rebatch: writing {} failed\n", options.out);
    return 2;
  }
  fmt::print(stderr, "skytrack rebatch: {} batches in, {} lines rejected\n", in,
             reader->counts().rejected_lines);
  return 0;
}

}  // namespace

void add_rebatch_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<RebatchOptions>();
  CLI::App* cmd = app.add_subcommand(
      "rebatch", "Deliver a plot stream in other batches (antenna sectors, blocks of plots)");
  cmd->add_option("--plots", options->plots, "Input plot stream (JSON Lines)")->required();
  cmd->add_option("--out", options->out, "Output plot stream")->required();
  cmd->add_option("--sectors", options->sectors,
                  "Batches per revolution, by the plots' body azimuth (clockwise from the nose)")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--block", options->block, "Plots per batch")->check(CLI::Range(1, 1000000));
  cmd->add_flag("--keep-coverage", options->keep_coverage,
                "Keep the input batches' coverage (default: none, as most feeds send)");
  cmd->footer(
      "Example: skytrack rebatch --plots canalA.plots.jsonl --sectors 8 --out "
      "canalA.8.plots.jsonl\n"
      "Exit codes: 0 done; 2 a file cannot be read or written; 1xx command-line mistakes (CLI11: "
      "105 a bad value, 106 a required option missing, 109 an unknown argument).");
  cmd->callback([options, &exit_code] { exit_code = run_rebatch(*options); });
}

}  // namespace skytrack::tool
