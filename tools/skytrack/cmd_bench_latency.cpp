// `skytrack bench-latency`: the daemon's end-to-end latency. Publishes PlotBatch samples of N
// moving targets (Cartesian plots, no clutter, seeded noise) one at a time and times each until
// the TrackBatch of the same scan arrives (ping-pong, like ddsperf's round trip; each scan
// sent when the last is answered, or one every --period-ms as a radar sends them), then
// prints p50/p99/max over the scans after the warm-up. A benchmark tool, not a test:
// tools/experiments/daemon-latency.sh runs it next to ddsperf for the floor. With
// --write-plots it writes the same scans as a plot stream instead, for `skytrack track`.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "dds_tool.hpp"
#include "skytrack/daemon/dds_session.hpp"
#include "skytrack/daemon/latency_stats.hpp"
#include "skytrack/dds/checked_take.hpp"
#include "skytrack/dds/conversion.hpp"
#include "skytrack/io/jsonl_writer.hpp"

namespace skytrack::tool {
namespace {

using Clock = std::chrono::steady_clock;

struct BenchOptions {
  DdsToolOptions dds;
  int targets = 100;
  int scans = 300;
  int warmup = 20;
  std::uint32_t sensor = 1;
  double period_ms = 0.0;   // a scan every period_ms, as a radar sends them; 0: back to back
  std::string write_plots;  // the scans as a plot stream, no DDS
};

/// Scan k of N targets on a 2 km grid, all flying east at 200 m/s (a steady picture: no
/// crossings, so every scan costs the tracker about the same).
PlotScan make_scan(int targets, int k, std::uint32_t sensor, std::mt19937_64& rng) {
  std::normal_distribution<double> noise(0.0, 20.0);
  PlotScan scan;
  scan.sensor = sensor;
  scan.scan = static_cast<std::uint64_t>(k);
  scan.time = static_cast<double>(k);
  scan.sigma.x = 20.0;
  scan.sigma.y = 20.0;
  const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(targets))));
  for (int i = 0; i < targets; ++i) {
    Plot p;
    p.id = i;
    p.form = PlotForm::kCartesian;
    p.x = 2000.0 * (i % side) + 200.0 * scan.time + noise(rng);
    p.y = 2000.0 * (i / side) + noise(rng);
    scan.plots.push_back(p);
  }
  return scan;
}

constexpr std::uint64_t kSeed = 42;

/// The warm-up and timed scans, written as a plot stream (CONTRACTS.md section 1).
int write_plots(const BenchOptions& o) {
  auto out = io::JsonLinesWriter::open(o.write_plots);
  if (!out) {
    fmt::print(stderr, "skytrack bench-latency: {}\n", out.error().message);
    return 2;
  }
  std::mt19937_64 rng(kSeed);
  for (int k = 0; k < o.warmup + o.scans; ++k) {
    out->write(make_scan(o.targets, k + 1, o.sensor, rng));
  }
  if (!out->close()) {
    fmt::print(stderr, "skytrack bench-latency: cannot write {}\n", o.write_plots);
    return 2;
  }
  return 0;
}

int run_bench(const BenchOptions& o) {
  if (!o.write_plots.empty()) return write_plots(o);
  auto pipe = open_plot_pipe(o.dds, "bench-latency");
  if (!pipe) {
    fmt::print(stderr, "{}\n", pipe.error().message);
    return 2;
  }
  const auto& dds = pipe->config.dds;
  daemon::DdsSession& session = pipe->session;
  const dds_entity_t writer = pipe->writer, reader = pipe->reader;
  if (!daemon::wait_for_readers(writer, 1, std::chrono::seconds(30)) ||
      !daemon::wait_for_writers(reader, 1, std::chrono::seconds(30))) {
    fmt::print(stderr, "skytrack bench-latency: no skytrackd on domain {}\n", dds.domain);
    return 3;
  }
  const dds_entity_t waitset = dds_create_waitset(session.participant());
  dds_waitset_attach(waitset, dds_create_readcondition(reader, DDS_ANY_STATE), 0);
  // Drain historical (transient-local) samples first.
  dds::TrackBatchSample answer;
  const auto drain = [&](std::uint64_t wanted) {
    bool found = false;
    dds::take_checked(
        reader, answer,
        [&](const skytrack_dds_TrackBatch& b, const dds_sample_info_t&) {
          found = found || (b.sensor == o.sensor && b.scan == wanted);
        },
        [](const dds_sample_info_t&, const Error&) {});
    return found;
  };
  drain(~0ull);
  std::mt19937_64 rng(kSeed);
  daemon::LatencyStats stats(static_cast<std::size_t>(o.scans));
  std::size_t payload = 0, lost = 0;
  dds::PlotBatchSample sample;
  const auto period = std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double, std::milli>(o.period_ms));
  auto next = Clock::now();
  for (int k = 0; k < o.warmup + o.scans && !stop_requested(); ++k) {
    if (o.period_ms > 0.0) {
      std::this_thread::sleep_until(next);
      next = std::max(next, Clock::now()) + period;  // an answer later than the period: no burst
    }
    const PlotScan scan = make_scan(o.targets, k + 1, o.sensor, rng);
    if (!dds::to_dds(scan, sample)) return 2;
    payload = sample->plot_ids._length * (8 + 4 + 8 * dds::kPlotStride) + 200;
    const auto t0 = Clock::now();
    if (dds_write(writer, sample.data()) != DDS_RETCODE_OK) return 2;
    bool answered = false;
    while (!answered && Clock::now() - t0 < std::chrono::seconds(5)) {
      dds_waitset_wait(waitset, nullptr, 0, DDS_MSECS(100));
      answered = drain(scan.scan);
    }
    const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    if (!answered) {
      ++lost;
      continue;
    }
    if (k >= o.warmup) stats.add(seconds);
  }
  fmt::print(
      "targets {:5d}  payload ~{:7d} B  scans {:4d}  PlotBatch->TrackBatch p50 {:8.1f} us  p99 "
      "{:8.1f} us  max {:8.1f} us  unanswered {}\n",
      o.targets, payload, stats.window_size(), stats.percentile(0.5) * 1e6,
      stats.percentile(0.99) * 1e6, stats.max() * 1e6, lost);
  return lost == 0 ? 0 : 1;
}

}  // namespace

void add_bench_latency_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App* cmd = app.add_subcommand(
      "bench-latency", "Time PlotBatch -> TrackBatch through a running skytrackd (benchmark)");
  cmd->add_option("--targets", o->targets, "Targets (plots) per scan")->default_val(100);
  cmd->add_option("--scans", o->scans, "Timed scans")->default_val(300);
  cmd->add_option("--warmup", o->warmup, "Untimed scans first (track initiation)")->default_val(20);
  cmd->add_option("--sensor", o->sensor, "Sensor id of the scans")->default_val(1);
  cmd->add_option("--period-ms", o->period_ms,
                  "Send a scan every this many milliseconds, as a radar does (0: each scan as "
                  "soon as the previous one is answered)")
      ->default_val(0.0)
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--write-plots", o->write_plots,
                  "Write the warm-up and timed scans to this plot stream (JSON Lines) and exit, "
                  "without DDS: the same load offline for `skytrack track`");
  add_dds_options(*cmd, o->dds);
  cmd->footer(
      "Example: skytrack bench-latency --config config/skytrackd.yaml --targets 1000 "
      "--scans 100\nExit codes: 0 every scan answered; 1 some scans had no TrackBatch; "
      "2 the configuration or DDS failed; 3 no skytrackd matched within 30 s; 1xx "
      "command-line mistakes (CLI11: 105 a bad value, 106 a required option missing, "
      "109 an unknown argument).");
  cmd->callback([o, &exit_code] { exit_code = run_bench(*o); });
}

}  // namespace skytrack::tool
