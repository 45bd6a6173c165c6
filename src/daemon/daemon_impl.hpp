#pragma once
// The daemon's private state, shared by its translation units: daemon.cpp (creation, the
// tracking thread, status, profile reload, stop) and daemon_reception.cpp (DDS and UDP
// reception into the queue). Not installed.
#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "skytrack/daemon/daemon.hpp"
#include "skytrack/daemon/dds_session.hpp"
#include "skytrack/daemon/edge_validator.hpp"
#include "skytrack/daemon/rate_limiter.hpp"
#include "skytrack/daemon/scan_queue.hpp"
#include "skytrack/daemon/status_collector.hpp"
#include "skytrack/daemon/udp_input.hpp"
#include "skytrack/dds/conversion.hpp"
#include "skytrack/pipeline/pipeline.hpp"

namespace skytrack::daemon {

using Clock = std::chrono::steady_clock;

struct Daemon::Impl {
  Impl(const DaemonConfig& c, config::TrackingProfile p, Pipeline pipe, DdsSession s)
      : config(c),
        profile(std::move(p)),
        pipeline(std::move(pipe)),
        session(std::move(s)),
        queue(static_cast<std::size_t>(c.queue.capacity), c.queue.overload),
        status(c.instance),
        validator(c.sensors, c.max_ahead_of_host) {}

  void receive_loop();
  void receive_batch();
  /// Into the queue; a scan the overload policy drops is counted and logged (rate-limited).
  void enqueue(QueuedScan item);
  void start_udp();
  /// The PlotBatch reader and the reception waitset (input.from: dds or both).
  bool open_plot_reception(dds_entity_t topic);
  /// The scan in a sample, or nullopt when it is rejected (counted and logged).
  std::optional<QueuedScan> convert(const skytrack_dds_PlotBatch& batch,
                                    Clock::time_point received);
  /// Counts a rejected sample under `reason` and logs it (rate-limited).
  void reject_sample(std::string_view reason, const std::string& which, const std::string& detail);
  void track_loop();
  void track_one(QueuedScan& item);
  void apply_pending_profile();

  const DaemonConfig config;
  config::TrackingProfile profile;  // owner's thread: the profile last applied or requested
  Pipeline pipeline;                // tracking thread only
  DdsSession session;
  dds_entity_t plots_reader = 0;
  dds_entity_t tracks_writer = 0;
  dds_entity_t status_writer = 0;
  dds_entity_t waitset = 0;
  dds_entity_t readable = 0;
  dds_entity_t stop_guard = 0;

  ScanQueue queue;
  StatusCollector status;
  EdgeValidator validator;  // tracking thread only
  struct Arrival {
    dds_time_t written = 0;  // source timestamp
    QueuedScan item;
  };
  std::vector<Arrival> arrivals;     // reception thread only
  dds::PlotBatchSample plot_sample;  // reception thread: the sample being converted

  std::mutex pending_mutex;
  std::optional<Pipeline> pending;  // a reloaded pipeline, applied before the next scan
  bool pending_keeps_tracks = false;
  config::ProfileIdentity pending_identity;

  std::unique_ptr<UdpInput> udp;  // input.from: asterix or both
  std::thread receiver;
  std::thread tracker;
  bool running = false;

  std::mutex drop_log_mutex;  // the DDS and UDP reception threads share drop_log
  RateLimiter drop_log;
  RateLimiter bad_sample_log;  // reception thread
  RateLimiter bad_scan_log;    // tracking thread
  RateLimiter write_log;
  RateLimiter capacity_log;  // tracking thread
  RateLimiter asterix_log;   // UDP input thread
};

}  // namespace skytrack::daemon
