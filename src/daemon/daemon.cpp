#include "skytrack/daemon/daemon.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

#include "skytrack/config/profile_loader.hpp"
#include "skytrack/daemon/dds_session.hpp"
#include "skytrack/daemon/edge_validator.hpp"
#include "skytrack/daemon/rate_limiter.hpp"
#include "skytrack/daemon/scan_queue.hpp"
#include "skytrack/daemon/status_collector.hpp"
#include "skytrack/daemon/udp_input.hpp"
#include "skytrack/dds/checked_take.hpp"
#include "skytrack/dds/conversion.hpp"
#include "skytrack/pipeline/pipeline.hpp"

#include "daemon_impl.hpp"

namespace skytrack::daemon {

void Daemon::Impl::apply_pending_profile() {
  std::lock_guard lock(pending_mutex);
  if (!pending) return;
  if (pending_keeps_tracks) {
    pipeline.set_input_limits(pending->profile().input_limits);
  } else {
    pipeline = std::move(*pending);
  }
  status.set_profile(pending_identity.name, pending_identity.version);
  spdlog::info("profile '{}' version {} now in use ({})", pending_identity.name,
               pending_identity.version, pending_keeps_tracks ? "tracks kept" : "tracks restarted");
  pending.reset();
}

void Daemon::Impl::track_one(QueuedScan& item) {
  const PlotScan& scan = item.scan;
  const double host_time =
      std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  if (const auto bad = validator.check(scan, host_time)) {
    status.scan_rejected(*bad);
    if (const auto count = bad_scan_log.allow()) {
      spdlog::warn("sensor {} scan {} (t = {}) skipped: {} ({} skipped since last message)",
                   scan.sensor, scan.scan, scan.time, *bad, *count);
    }
    return;
  }
  const ScanResult& result = pipeline.process(scan);
  if (!result.accepted) {
    status.scan_rejected(result.reason);
    if (const auto count = bad_scan_log.allow()) {
      spdlog::warn("{} (t = {}; {} skipped since last message)", result.rejection, scan.time,
                   *count);
    }
    return;
  }
  if (const std::string change = timeline_change(result); !change.empty()) {
    spdlog::warn("sensor {} scan {} (t = {}): {}", scan.sensor, scan.scan, scan.time, change);
  }
  if (result.report.plots_invalid > 0) {
    for (const Plot& plot : scan.plots) {
      const auto why = invalid_plot_reason(plot, pipeline.profile().input_limits, scan.time);
      if (why) status.plots_rejected(*why, 1);
    }
  }
  status.plots_rejected(reason::kClutter,
                        static_cast<std::uint64_t>(result.report.plots_rejected_clutter));
  auto sample = dds::to_dds(result.frame);
  dds_return_t rc = DDS_RETCODE_OK;
  if (sample) rc = dds_write(tracks_writer, sample->data());
  if (!sample || rc != DDS_RETCODE_OK) {
    if (const auto count = write_log.allow()) {
      spdlog::error("sensor {} scan {}: TrackBatch not published: {} ({} since last message)",
                    scan.sensor, scan.scan,
                    sample ? std::string(dds_strretcode(rc)) : sample.error().message, *count);
    }
  }
  if (result.report.initiations_refused > 0) {
    if (const auto count = capacity_log.allow()) {
      spdlog::warn(
          "sensor {} scan {}: {} chains started no track: initiation.max_tentative ({}) "
          "tentative tracks held ({} batches with refusals since last message)",
          scan.sensor, scan.scan, result.report.initiations_refused,
          pipeline.profile().point.initiation.max_tentative, *count);
    }
  }
  const double latency = std::chrono::duration<double>(Clock::now() - item.received).count();
  status.scan_processed(scan.plots.size(), latency, result.frame,
                        static_cast<std::uint64_t>(result.report.numeric_failures));
  spdlog::debug("sensor {} scan {} t={:.3f}: {} plots, {} tracks, {} initiated, {:.3f} ms",
                scan.sensor, scan.scan, scan.time, scan.plots.size(), result.frame.tracks.size(),
                result.report.initiated, latency * 1e3);
}

void Daemon::Impl::track_loop() {
  while (auto item = queue.pop()) {
    apply_pending_profile();
    track_one(*item);
  }
}

Daemon::Daemon(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

Expected<std::unique_ptr<Daemon>> Daemon::create(const DaemonConfig& config) {
  auto profile = load_tracking_profile(config.profile);
  if (!profile) return unexpected(profile.error());
  auto pipeline = Pipeline::create(*profile);
  if (!pipeline) return unexpected(pipeline.error());
  auto session = DdsSession::open(config.dds);
  if (!session) return unexpected(session.error());
  spdlog::info("DDS: {}; domain {}", session->configuration(), config.dds.domain);
  auto impl = std::make_unique<Impl>(config, std::move(*profile), std::move(*pipeline),
                                     std::move(*session));
  Impl& d = *impl;
  d.status.set_profile(d.profile.identity.name, d.profile.identity.version);
  const DdsSettings& dds = config.dds;
  auto plots = d.session.topic(&skytrack_dds_PlotBatch_desc, dds.topics.plots);
  if (!plots) return unexpected(plots.error());
  auto tracks = d.session.topic(&skytrack_dds_TrackBatch_desc, dds.topics.tracks);
  if (!tracks) return unexpected(tracks.error());
  auto status = d.session.topic(&skytrack_dds_TrackerStatus_desc, dds.topics.status);
  if (!status) return unexpected(status.error());
  auto tracks_writer = d.session.writer(*tracks, tracks_writer_qos(dds).get());
  if (!tracks_writer) return unexpected(tracks_writer.error());
  auto status_writer = d.session.writer(*status, status_writer_qos(dds).get());
  if (!status_writer) return unexpected(status_writer.error());
  d.tracks_writer = *tracks_writer;
  d.status_writer = *status_writer;
  if (config.input.udp()) {
    auto udp = UdpInput::open(config.input.asterix);
    if (!udp) return unexpected(udp.error());
    d.udp = std::move(*udp);
    spdlog::info("ASTERIX input on UDP {}, batch {}", d.udp->endpoint(),
                 config.input.asterix.batch);
  }
  if (config.input.dds() && !d.open_plot_reception(*plots)) {
    return make_error("creating the PlotBatch reader and its waitset failed");
  }
  spdlog::info(
      "topics: plots '{}' ({}), tracks '{}' ({}), status '{}' (every {} s, deadline {} s); "
      "partition '{}'; queue {} scans, {}; profile '{}' version {}",
      dds.topics.plots, to_string(dds.plots.reliability), dds.topics.tracks,
      to_string(dds.tracks.durability), dds.topics.status, config.status_period,
      dds.status.deadline, dds.partitions.empty() ? "" : dds.partitions.front(),
      config.queue.capacity, to_string(config.queue.overload), d.profile.identity.name,
      d.profile.identity.version);
  return std::unique_ptr<Daemon>(new Daemon(std::move(impl)));
}

Daemon::~Daemon() {
  if (impl_ && impl_->running) stop();
}

void Daemon::start() {
  if (impl_->running) return;
  impl_->running = true;
  impl_->tracker = std::thread([this] { impl_->track_loop(); });
  if (impl_->config.input.dds()) impl_->receiver = std::thread([this] { impl_->receive_loop(); });
  if (impl_->udp) impl_->start_udp();
}

void Daemon::publish_status() {
  daemon::publish_status(impl_->status_writer,
                         impl_->status.snapshot(static_cast<std::uint32_t>(impl_->queue.size())));
}

bool Daemon::reload_profile() {
  Impl& d = *impl_;
  if (d.config.profile.empty()) {
    spdlog::warn("SIGHUP: no profile file configured (built-in default); nothing to reload");
    return false;
  }
  auto profile = config::load_profile(d.config.profile);
  if (!profile) {
    spdlog::error("SIGHUP: profile {} not reloaded, keeping '{}' version {}:\n{}", d.config.profile,
                  d.profile.identity.name, d.profile.identity.version, profile.error().message);
    return false;
  }
  auto pipeline = Pipeline::create(*profile);
  if (!pipeline) {
    spdlog::error("SIGHUP: profile {} not usable, keeping '{}' version {}: {}", d.config.profile,
                  d.profile.identity.name, d.profile.identity.version, pipeline.error().message);
    return false;
  }
  const std::string reason = restart_reason(d.profile, *profile);
  if (reason.empty()) {
    spdlog::info("SIGHUP: profile '{}' version {}: tracking parameters unchanged, tracks kept",
                 profile->identity.name, profile->identity.version);
  } else {
    spdlog::warn(
        "SIGHUP: profile '{}' version {} changes {}: the running tracker cannot take new "
        "parameters on live tracks, so the tracks restart with the next scan",
        profile->identity.name, profile->identity.version, reason);
  }
  {
    std::lock_guard lock(d.pending_mutex);
    d.pending_keeps_tracks = reason.empty();
    d.pending_identity = profile->identity;
    d.pending.emplace(std::move(*pipeline));
  }
  d.profile = std::move(*profile);
  return true;
}

void Daemon::stop() {
  Impl& d = *impl_;
  if (!d.running) return;
  d.running = false;
  if (d.receiver.joinable()) {
    dds_set_guardcondition(d.stop_guard, true);
    d.receiver.join();
  }
  if (d.udp) d.udp->stop();
  d.queue.close();  // the tracker finishes the scan in hand, then sees the close
  d.tracker.join();
  if (const std::size_t left = d.queue.clear()) {
    spdlog::warn("stopping: {} queued scans not processed", left);
  }
  publish_status();
}

}  // namespace skytrack::daemon
