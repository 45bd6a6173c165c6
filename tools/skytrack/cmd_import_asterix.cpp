// `skytrack import-asterix`: ASTERIX recordings (raw blocks, pcap, pcapng) into the plot format,
// batched by the radar's sector messages, by revolution or per N plots. Prints what it read and
// every error with its byte offset (the first 20; the rest are counted).
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "asterix_options.hpp"
#include "commands.hpp"
#include "progress_bar.hpp"
#include "skytrack/io/jsonl_writer.hpp"

namespace skytrack::tool {
namespace {

struct ImportOptions {
  std::vector<std::string> inputs;
  std::string plots;
  AsterixOptions asterix;
  bool quiet = false;
};

int run_import(const ImportOptions& options) {
  auto resolved = resolve(options.asterix);
  if (!resolved) {
    fmt::print(stderr, "skytrack import-asterix: {}\n", resolved.error().message);
    return 2;
  }
  auto writer = io::JsonLinesWriter::open(options.plots);
  if (!writer) {
    fmt::print(stderr, "skytrack import-asterix: {}\n", writer.error().message);
    return 2;
  }
  bool write_failed = false;
  std::size_t plots_written = 0;
  ErrorPrinter errors(options.inputs.front());
  asterix::Feed feed(
      resolved->feed,
      [&](PlotScan&& scan) {
        plots_written += scan.plots.size();
        if (!writer->write(scan)) write_failed = true;
      },
      [&](const asterix::DecodeError& e) { errors(e); });
  asterix::CaptureCounts capture;
  const auto start = std::chrono::steady_clock::now();
  for (const std::string& input : options.inputs) {
    errors.set_file(input);
    auto reader = asterix::CaptureReader::open(
        input, resolved->filter, [&](const asterix::CaptureProblem& p) { errors(p); });
    if (!reader) {
      fmt::print(stderr, "skytrack import-asterix: {}\n", reader.error().message);
      return 2;
    }
    ProgressBar progress(!options.quiet && reader->file_size() > (1u << 20), "datagrams");
    std::size_t shown_before = errors.shown();
    while (auto datagram = reader->next()) {
      feed.feed(*datagram);
      if (errors.shown() != shown_before) {  // keep error lines apart from the bar
        shown_before = errors.shown();
        fmt::print(stderr, "\n");
      }
      progress.update(reader->bytes_read(), reader->file_size(), reader->counts().datagrams);
    }
    progress.finish();
    const asterix::CaptureCounts& c = reader->counts();
    fmt::print(stderr, "{}: {}, {} bytes\n", input, asterix::to_string(reader->format()),
               reader->file_size());
    capture.frames += c.frames;
    capture.datagrams += c.datagrams;
    capture.not_udp += c.not_udp;
    capture.filtered += c.filtered;
    capture.damaged += c.damaged;
    capture.skipped_bytes += c.skipped_bytes;
  }
  feed.finish();
  if (errors.shown() > 0) fmt::print(stderr, "\n");
  if (!writer->close() || write_failed) {
    fmt::print(stderr, "skytrack import-asterix: writing {} failed\n", options.plots);
    return 2;
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  fmt::print(stderr, "skytrack import-asterix: {} plots in {} batches written to {} ({:.2f} s)\n",
             plots_written, feed.batcher().batches(), options.plots, wall);
  print_summary(stderr, feed, capture);
  return 0;
}

}  // namespace

void add_import_asterix_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<ImportOptions>();
  CLI::App* cmd = app.add_subcommand(
      "import-asterix", "Convert ASTERIX recordings (raw, pcap, pcapng) into a plot stream");
  cmd->add_option("inputs", options->inputs, "ASTERIX recordings, read in this order")->required();
  cmd->add_option("--plots", options->plots, "Output plot stream (JSON Lines)")->required();
  add_asterix_options(*cmd, options->asterix);
  cmd->add_flag("--quiet", options->quiet, "No progress bar");
  cmd->footer(
      "Example: skytrack import-asterix capture.pcap --plots "
      "out/capture.plots.jsonl\nExit codes: 0 done (undecodable records are counted and "
      "reported); 2 an input cannot be read or the output written; 1xx command-line "
      "mistakes (CLI11: 105 a bad value, 106 a required option missing, 109 an unknown "
      "argument).");
  cmd->callback([options, &exit_code] { exit_code = run_import(*options); });
}

}  // namespace skytrack::tool
