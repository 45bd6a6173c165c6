// `skytrack replay`: publishes a recorded plot stream as PlotBatch samples, at recorded timing,
// N times faster, or as fast as the daemon takes them (--rate max: at most --window scans in
// flight, a scan counting as taken once the daemon's TrackBatch for it or for a later scan
// arrives; the daemon's queue is FIFO, so a later answer means the earlier scan was handled).
// It waits for the daemon's reader to match before it starts. --asterix replays an ASTERIX
// recording instead, batched as `import-asterix` batches it.
#include <chrono>
#include <deque>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "dds_tool.hpp"
#include "progress_bar.hpp"
#include "scan_source.hpp"
#include "skytrack/daemon/dds_session.hpp"
#include "skytrack/dds/checked_take.hpp"
#include "skytrack/dds/conversion.hpp"

namespace skytrack::tool {
namespace {

using Clock = std::chrono::steady_clock;

struct ReplayOptions {
  DdsToolOptions dds;
  std::vector<std::string> plots;  // several: merged in time order
  std::string asterix;             // an ASTERIX recording instead of --plots
  AsterixOptions asterix_options;
  std::string rate = "1";
  bool loop = false;
  bool quiet = false;
  double wait = 30.0;  // [s] for the daemon's reader
  int window = 8;      // scans in flight at --rate max
};

/// Scans sent and not yet answered by a TrackBatch, in send order.
class InFlight {
 public:
  void sent(std::uint32_t sensor, std::uint64_t scan) { items_.push_back({sensor, scan}); }
  /// A TrackBatch for (sensor, scan): that scan and every one sent before it are done.
  void answered(std::uint32_t sensor, std::uint64_t scan) {
    for (std::size_t i = 0; i < items_.size(); ++i) {
      if (items_[i].first == sensor && items_[i].second == scan) {
        items_.erase(items_.begin(), items_.begin() + static_cast<std::ptrdiff_t>(i) + 1);
        return;
      }
    }
  }
  void give_up_oldest() {
    if (!items_.empty()) items_.pop_front();
  }
  std::size_t size() const { return items_.size(); }

 private:
  std::deque<std::pair<std::uint32_t, std::uint64_t>> items_;
};

class Replayer {
 public:
  Replayer(const ReplayOptions& o, daemon::DdsSession& session, dds_entity_t writer,
           dds_entity_t tracks_reader)
      : options_(o), session_(session), writer_(writer), tracks_(tracks_reader) {}

  int run();

 private:
  bool pass(double time_offset, std::uint64_t scan_offset);
  void take_answers();
  /// --rate max: waits until fewer than `limit` scans are in flight (1 s without an answer
  /// counts the oldest as lost, e.g. a scan of a sensor the daemon does not accept).
  void wait_in_flight(std::size_t limit);

  const ReplayOptions& options_;
  daemon::DdsSession& session_;
  dds_entity_t writer_;
  dds_entity_t tracks_;
  double rate_ = 1.0;  // 0: max
  dds_time_t start_dds_ = 0;
  Clock::time_point start_wall_;
  std::optional<double> first_time_;
  double last_time_ = 0.0;
  std::uint64_t max_scan_ = 0;
  std::size_t scans_ = 0, plots_ = 0, unanswered_ = 0, lines_rejected_ = 0, malformed_ = 0;
  InFlight in_flight_;
  dds::PlotBatchSample sample_;
  dds::TrackBatchSample answer_;
};

void Replayer::take_answers() {
  dds::take_checked(
      tracks_, answer_,
      [this](const skytrack_dds_TrackBatch& b, const dds_sample_info_t& info) {
        // Historical samples (transient-local) from before this replay answer nothing.
        if (info.source_timestamp >= start_dds_) in_flight_.answered(b.sensor, b.scan);
      },
      [this](const dds_sample_info_t&, const Error&) { ++malformed_; });
}

void Replayer::wait_in_flight(std::size_t limit) {
  auto last_progress = Clock::now();
  std::size_t before = in_flight_.size();
  while (in_flight_.size() >= limit && !stop_requested()) {
    take_answers();
    if (in_flight_.size() < before) {
      before = in_flight_.size();
      last_progress = Clock::now();
    } else if (Clock::now() - last_progress > std::chrono::seconds(1)) {
      in_flight_.give_up_oldest();
      ++unanswered_;
      before = in_flight_.size();
      last_progress = Clock::now();
    }
    if (in_flight_.size() >= limit) std::this_thread::sleep_for(std::chrono::microseconds(100));
  }
}

bool Replayer::pass(double time_offset, std::uint64_t scan_offset) {
  auto reader = options_.asterix.empty()
                    ? open_plot_streams(options_.plots)
                    : open_asterix_recording(options_.asterix, options_.asterix_options);
  if (!reader) {
    fmt::print(stderr, "skytrack replay: {}\n", reader.error().message);
    return false;
  }
  ScanSource& source = **reader;
  ProgressBar progress(!options_.quiet, "scans");
  while (auto scan = source.next()) {
    if (stop_requested()) break;
    scan->time += time_offset;
    for (Plot& p : scan->plots) {
      if (p.time) *p.time += time_offset;
    }
    scan->scan += scan_offset;
    if (!first_time_) first_time_ = scan->time;
    last_time_ = std::max(last_time_, scan->time);
    max_scan_ = std::max(max_scan_, scan->scan);
    if (rate_ > 0.0) {
      const auto due =
          start_wall_ + std::chrono::duration_cast<Clock::duration>(
                            std::chrono::duration<double>((scan->time - *first_time_) / rate_));
      while (Clock::now() < due && !stop_requested()) {
        std::this_thread::sleep_for(
            std::min<Clock::duration>(due - Clock::now(), std::chrono::milliseconds(50)));
      }
    } else {
      wait_in_flight(static_cast<std::size_t>(options_.window));
    }
    if (auto ok = dds::to_dds(*scan, sample_); !ok) {
      fmt::print(stderr, "\nskytrack replay: scan {} not sent: {}\n", scan->scan,
                 ok.error().message);
      continue;
    }
    if (const dds_return_t rc = dds_write(writer_, sample_.data()); rc != DDS_RETCODE_OK) {
      fmt::print(stderr, "\nskytrack replay: writing scan {} failed: {}\n", scan->scan,
                 dds_strretcode(rc));
      return false;
    }
    if (rate_ == 0.0) in_flight_.sent(scan->sensor, scan->scan);
    ++scans_;
    plots_ += scan->plots.size();
    progress.update(source.bytes_read(), source.file_size(), scans_);
  }
  progress.finish();
  lines_rejected_ += source.rejected();
  if (const auto error = source.read_error()) {  // not the end of the recording
    fmt::print(stderr, "skytrack replay: {}\n", *error);
    return false;
  }
  return true;
}

int Replayer::run() {
  if (options_.rate == "max") {
    rate_ = 0.0;
  } else {
    try {
      rate_ = std::stod(options_.rate);
    } catch (const std::exception&) {
      rate_ = -1.0;
    }
    if (!(rate_ > 0.0)) {
      fmt::print(stderr, "skytrack replay: --rate: expected a positive number or max, got '{}'\n",
                 options_.rate);
      return 2;
    }
  }
  start_dds_ = dds_time();
  start_wall_ = Clock::now();
  double time_offset = 0.0;
  std::uint64_t scan_offset = 0;
  std::size_t passes = 0;
  double time_span = 0.0;
  std::uint64_t scan_span = 0;
  do {
    if (!pass(time_offset, scan_offset)) return 2;
    if (passes++ == 0) {
      // The next pass continues the stream: later times and scan numbers, one period on.
      const double first = first_time_.value_or(0.0);
      const double period =
          scans_ > 1 ? (last_time_ - first) / static_cast<double>(scans_ - 1) : 1.0;
      time_span = last_time_ - first + period;
      scan_span = max_scan_ + 1;
    }
    time_offset += time_span;
    scan_offset += scan_span;
  } while (options_.loop && scans_ > 0 && !stop_requested());
  if (rate_ == 0.0) wait_in_flight(1);  // the last answers, so "done" means processed
  const double wall = std::chrono::duration<double>(Clock::now() - start_wall_).count();
  fmt::print(
      stderr, "skytrack replay: {} scans ({} plots) in {:.2f} s, {} pass(es), {} {} rejected{}{}\n",
      scans_, plots_, wall, passes, lines_rejected_,
      options_.asterix.empty() ? "lines" : "ASTERIX errors",
      rate_ == 0.0
          ? fmt::format(", {} scans unanswered by a TrackBatch", unanswered_ + in_flight_.size())
          : "",
      malformed_ ? fmt::format(", {} malformed TrackBatch samples refused", malformed_) : "");
  return 0;
}

int run_replay(const ReplayOptions& options) {
  auto pipe = open_plot_pipe(options.dds, "replay");
  if (!pipe) {
    fmt::print(stderr, "{}\n", pipe.error().message);
    return 2;
  }
  const auto& dds = pipe->config.dds;
  daemon::DdsSession& session = pipe->session;
  const dds_entity_t writer = pipe->writer, reader = pipe->reader;
  if (!options.quiet) {
    fmt::print(stderr, "skytrack replay: waiting for a reader of '{}' on domain {}\n",
               dds.topics.plots, dds.domain);
  }
  const auto wait = std::chrono::milliseconds(static_cast<long long>(options.wait * 1000.0));
  if (!daemon::wait_for_readers(writer, 1, wait, [] { return !stop_requested(); })) {
    fmt::print(stderr,
               "skytrack replay: no reader of '{}' matched on domain {} within {} s (is skytrackd "
               "running with the same domain, partition and QoS?)\n",
               dds.topics.plots, dds.domain, options.wait);
    return 3;
  }
  if (options.rate == "max") {
    // Pacing needs the daemon's answers: wait (briefly) for its TrackBatch writer too.
    daemon::wait_for_writers(reader, 1, std::chrono::seconds(5), [] { return !stop_requested(); });
  }
  Replayer replayer(options, session, writer, reader);
  return replayer.run();
}

}  // namespace

void add_replay_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<ReplayOptions>();
  CLI::App* cmd = app.add_subcommand("replay", "Publish a plot stream as PlotBatch samples (DDS)");
  auto* plots = cmd->add_option(
      "--plots", options->plots,
      "Plot stream to publish (JSON Lines); repeat for several sensors' streams, merged in "
      "time order");
  auto* asterix = cmd->add_option("--asterix", options->asterix,
                                  "ASTERIX recording to publish (raw, pcap, pcapng), batched "
                                  "by --batch as import-asterix does");
  plots->excludes(asterix);
  asterix->excludes(plots);
  add_asterix_options(*cmd, options->asterix_options);
  cmd->add_option("--rate", options->rate,
                  "1: recorded timing; N: N times faster; max: as fast as the daemon takes them")
      ->default_val("1");
  cmd->add_flag("--loop", options->loop,
                "Start over at the end, continuing times and scan numbers, until interrupted");
  cmd->add_option("--wait", options->wait, "Seconds to wait for the daemon's reader")
      ->default_val(30.0);
  cmd->add_option("--window", options->window, "Scans in flight at --rate max")
      ->default_val(8)
      ->check(CLI::Range(1, 100000));
  cmd->add_flag("--quiet", options->quiet, "No progress bar");
  add_dds_options(*cmd, options->dds);
  cmd->footer(
      "Example: skytrack replay --config config/skytrackd.yaml --plots out/default.plots.jsonl "
      "--rate max\nSeveral sensors: --plots radar1.plots.jsonl --plots radar2.plots.jsonl "
      "(merged in time order)\nExit codes: 0 every scan published; 2 the configuration, DDS "
      "or an input file failed; 3 no daemon's reader matched within --wait; 1xx command-line "
      "mistakes (CLI11: 105 a bad value, 106 a required option missing, 109 an unknown "
      "argument).");
  cmd->callback([options, &exit_code] {
    if (options->plots.empty() && options->asterix.empty()) {
      fmt::print(stderr, "skytrack replay: one of --plots or --asterix is required\n");
      exit_code = 2;
      return;
    }
    exit_code = run_replay(*options);
  });
}

}  // namespace skytrack::tool
