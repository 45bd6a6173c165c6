#pragma once
// skytrackd's engine: PlotBatch in, the same Pipeline as `skytrack track`, TrackBatch and
// TrackerStatus out. Two threads of its own: reception (DDS take, conversion, scan-size check,
// push into the bounded queue; never waits on tracking) and tracking (edge validation,
// Pipeline, publication). The owner's thread publishes the status and handles reload and
// stop. docs/daemon.md describes the threads, QoS and signals.
#include <memory>
#include <string>

#include "skytrack/config/profile.hpp"
#include "skytrack/core/expected.hpp"
#include "skytrack/daemon/daemon_config.hpp"

namespace skytrack::daemon {

/// The profile the daemon runs: the file's, or the built-in default point-tracking profile
/// when `path` is empty (as `skytrack track` without --profile).
Expected<config::TrackingProfile> load_tracking_profile(const std::string& path);

/// Why a change from `before` to `after` cannot keep the live tracks (the sections that
/// differ, apart from the identity), or empty when it can.
std::string restart_reason(const config::TrackingProfile& before,
                           const config::TrackingProfile& after);

class Daemon {
 public:
  /// Loads the profile, builds the pipeline, opens DDS and creates the topics, reader and
  /// writers. Nothing runs yet; on failure nothing is left behind.
  static Expected<std::unique_ptr<Daemon>> create(const DaemonConfig& config);
  ~Daemon();  // stops if still running, then deletes the DDS participant
  Daemon(const Daemon&) = delete;
  Daemon& operator=(const Daemon&) = delete;

  /// Starts the reception and tracking threads.
  void start();
  /// Publishes one TrackerStatus sample.
  void publish_status();
  /// SIGHUP: reads the profile file again. A valid profile replaces the running one before the
  /// next scan (tracks kept when only its identity changed, else restarted with the reason
  /// logged); an invalid one is logged and the old one kept. False when it was not applied.
  bool reload_profile();
  /// Stops reception, lets the tracker finish and publish the scan in hand, discards the
  /// scans still queued (logged), and publishes a final status.
  void stop();

 private:
  struct Impl;
  explicit Daemon(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace skytrack::daemon
