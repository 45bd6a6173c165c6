#include "options.hpp"

#include <cstdio>

#include <CLI/CLI.hpp>

namespace skytrack::adversary {

std::optional<int> parse_options(int argc, char** argv, Options& o) {
  CLI::App app{
      "skytrack-adversary - replays a good sensor into skytrackd over DDS (loopback only) while "
      "a second sensor sends plot clouds, bursts, huge batches and malformed samples; prints "
      "the good sensor's latency, the daemon's rejections and memory per phase, and whether "
      "the good sensor's tracks stayed as they are without the adversary"};
  app.add_option("--config", o.config,
                 "skytrackd configuration (domain, topics, QoS, profile, max_plots_per_scan)")
      ->check(CLI::ExistingFile);
  app.add_option("--domain", o.domain, "DDS domain id (default: the configuration's, else 231)")
      ->check(CLI::Range(1, 232));
  app.add_option("--profile", o.profile,
                 "Profile of the offline comparison (default: the configuration's)")
      ->check(CLI::ExistingFile);
  app.add_option("--daemon-pid", o.daemon_pid, "skytrackd's pid, for VmRSS and VmHWM")
      ->check(CLI::PositiveNumber);
  app.add_option("--wait", o.wait, "Seconds to wait for the daemon's DDS entities")
      ->check(CLI::PositiveNumber);
  auto* scenario = app.add_option("--scenario", o.scenario,
                                  "Good sensor: scenario to simulate (default: "
                                  "config/scenarios/default.yaml)")
                       ->check(CLI::ExistingFile);
  auto* plots = app.add_option("--plots", o.plots, "Good sensor: a recorded plot stream instead")
                    ->check(CLI::ExistingFile);
  scenario->excludes(plots);
  app.add_option("--sectors", o.sectors, "Simulated rotating antenna: batches per revolution")
      ->check(CLI::Range(1, 360));
  app.add_option("--seed", o.seed, "Simulation seed (default: the scenario's)");
  app.add_option("--rate", o.rate, "Pace of the good sensor, times real time")
      ->check(CLI::Range(0.01, 1000.0));
  app.add_option("--warmup", o.warmup, "Quiet stream seconds before the first phase")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--phase", o.phase, "Stream seconds of each adversarial phase")
      ->check(CLI::PositiveNumber);
  app.add_option("--settle", o.settle, "... of which the last are quiet")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--recovery", o.recovery, "Quiet stream seconds after the last phase")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--period", o.period, "Stream seconds between the adversary's events")
      ->check(CLI::PositiveNumber);
  app.add_option("--adversary-sensor", o.adversary_sensor, "The adversary's sensor id");
  app.add_option("--cloud-sizes", o.cloud_sizes,
                 "Co-located plots per cloud batch, one phase each (empty: no cloud phases)")
      ->delimiter(',')
      ->check(CLI::Range(1, 10000000));
  app.add_option("--bursts", o.bursts, "Bursts per burst phase (0: no burst phase)")
      ->check(CLI::Range(0, 100));
  app.add_option("--burst-batches", o.burst_batches, "Batches per burst, back to back")
      ->check(CLI::Range(1, 100000));
  app.add_option("--burst-plots", o.burst_plots, "Plots per burst batch")
      ->check(CLI::Range(0, 100000));
  app.add_option("--max-plots", o.max_plots,
                 "The daemon's max_plots_per_scan (default: the configuration's); huge batches "
                 "are one plot under and one over it")
      ->check(CLI::Range(1, 10000000));
  app.add_flag("!--no-huge", o.huge, "No huge-batch phases");
  app.add_flag("!--no-malformed", o.malformed, "No malformed-sample phase");
  app.add_flag("!--no-clock-hijack", o.clock_hijack,
               "No clock-hijack phase (three far-future batches in a row)");
  app.add_option("--tolerance", o.tolerance, "Metres within which a live track matches")
      ->check(CLI::PositiveNumber);
  app.add_option("--drain", o.drain, "Seconds to wait for the last TrackBatches")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--max-rss-mb", o.max_rss_mb, "Stop when the daemon's VmRSS passes this [MiB]")
      ->check(CLI::PositiveNumber);
  app.add_option("--max-seconds", o.max_seconds, "Stop sending after this many seconds")
      ->check(CLI::PositiveNumber);
  app.add_option("--differences", o.differences, "First frame differences listed")
      ->check(CLI::NonNegativeNumber);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  if (o.settle > o.phase) {
    std::fprintf(stderr, "skytrack-adversary: --settle must not exceed --phase\n");
    return 2;
  }
  return std::nullopt;
}

}  // namespace skytrack::adversary
