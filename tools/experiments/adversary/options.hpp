#pragma once
// skytrack-adversary's command line: where the daemon is, what the good sensor replays, how
// long each phase lasts and how big the adversary's batches are. Times of phases are seconds
// of the good stream's own time; --rate turns them into wall-clock seconds.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace skytrack::adversary {

/// The domain used when neither --config nor --domain names one: private, not the shipped 0.
inline constexpr int kDefaultDomain = 231;

struct Options {
  // The daemon.
  std::string config;   // skytrackd configuration: domain, topics, QoS, profile, max plots
  int domain = -1;      // overrides the configuration's domain
  std::string profile;  // profile of the offline comparison; default: the configuration's
  int daemon_pid = 0;   // for VmRSS and VmHWM; 0: not measured
  double wait = 30.0;   // [s] for the daemon's reader and writers to match
  // The good sensor: a simulated scenario or a recorded plot stream.
  std::string scenario;
  std::string plots;
  int sectors = 8;  // simulated rotating antenna: batches per revolution
  std::optional<std::uint64_t> seed;
  double rate = 2.0;  // times real time
  // Phases [s of stream time].
  double warmup = 32.0;    // quiet: the good sensor's tracks confirm
  double phase = 20.0;     // each adversarial phase
  double settle = 8.0;     // ... of which the last seconds are quiet again
  double recovery = 28.0;  // quiet after the last phase
  double period = 4.0;     // between the adversary's events within a phase
  // The adversary.
  std::uint32_t adversary_sensor = 2;
  std::vector<int> cloud_sizes{250, 500, 1000, 3000};  // co-located plots per batch
  int bursts = 2;                                      // per burst phase
  int burst_batches = 300;                             // back to back
  int burst_plots = 10;                                // per burst batch
  int max_plots = 0;  // the daemon's max_plots_per_scan; 0: the configuration's
  bool huge = true;
  bool malformed = true;
  bool clock_hijack = true;
  // Measuring and bounds.
  double tolerance = 1.0;    // [m] a live track matches an offline one this close
  double drain = 30.0;       // [s] waiting for the last TrackBatches
  double max_rss_mb = 4096;  // the run stops when the daemon's VmRSS passes this
  double max_seconds = 900;  // the run stops after this many wall-clock seconds
  int differences = 10;      // first differences listed
};

/// Parses the command line into `options`. Returns the exit code to leave with (help, or a
/// usage error already printed), or nullopt to run.
std::optional<int> parse_options(int argc, char** argv, Options& options);

}  // namespace skytrack::adversary
