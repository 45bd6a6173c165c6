#include "skytrack/daemon/fusion_node.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "skytrack/daemon/dds_session.hpp"
#include "skytrack/daemon/edge_validator.hpp"
#include "skytrack/daemon/rate_limiter.hpp"
#include "skytrack/daemon/status_collector.hpp"
#include "skytrack/dds/checked_take.hpp"
#include "skytrack/dds/conversion.hpp"
#include "skytrack/fusion/track_fusion.hpp"

namespace skytrack::daemon {

namespace {

using Clock = std::chrono::steady_clock;

// Rejection reasons of the fusion role: frames in TrackerStatus.scans_rejected, local tracks
// in plots_rejected (a local track is the fusion's "plot").
constexpr std::string_view kLateFrame = "track frame older than the fused picture";
constexpr std::string_view kInvalidFrame = "track frame with a non-finite time";
constexpr std::string_view kDroppedFrame = "track frame queued beyond max_queued_frames";
constexpr std::string_view kInvalidTrack = "local track with non-finite or non-PD values";

}  // namespace

struct FusionNode::Impl {
  Impl(const DaemonConfig& c, const fusion::FusionSpec& spec, DdsSession s)
      : config(c), fusion(spec), session(std::move(s)), status(c.instance) {}

  bool open_reception(dds_entity_t topic);
  void receive_loop();
  void receive_batch();
  /// Feeds one local frame to the fusion and publishes the fused frames it completes.
  void fuse(const TrackFrame& local, Clock::time_point received);
  void publish(const std::vector<TrackFrame>& fused);
  void count_rejections();

  const DaemonConfig config;
  fusion::TrackFusion fusion;  // reception thread only (after start)
  DdsSession session;
  dds_entity_t tracks_reader = 0;
  dds_entity_t fused_writer = 0;
  dds_entity_t status_writer = 0;
  dds_entity_t waitset = 0;
  dds_entity_t readable = 0;
  dds_entity_t stop_guard = 0;
  StatusCollector status;
  TrackFrame last_fused;  // the picture the status reports
  fusion::FusionCounters counted;
  struct Arrival {
    dds_time_t written = 0;
    TrackFrame frame;
  };
  std::vector<Arrival> arrivals;
  dds::TrackBatchSample sample;
  std::thread receiver;
  bool running = false;
  RateLimiter bad_sample_log;
  RateLimiter write_log;
};

bool FusionNode::Impl::open_reception(dds_entity_t topic) {
  // Keep all: every local frame counts for the history window, none may be overwritten.
  auto reader = session.reader(topic, tracks_reader_qos(config.dds, true).get());
  if (!reader) {
    spdlog::error("{}", reader.error().message);
    return false;
  }
  tracks_reader = *reader;
  waitset = dds_create_waitset(session.participant());
  readable = dds_create_readcondition(tracks_reader, DDS_ANY_STATE);
  stop_guard = dds_create_guardcondition(session.participant());
  return waitset >= 0 && readable >= 0 && stop_guard >= 0 &&
         dds_waitset_attach(waitset, readable, readable) == DDS_RETCODE_OK &&
         dds_waitset_attach(waitset, stop_guard, stop_guard) == DDS_RETCODE_OK;
}

void FusionNode::Impl::receive_loop() {
  for (;;) {
    std::array<dds_attach_t, 2> triggered{};
    const dds_return_t n =
        dds_waitset_wait(waitset, triggered.data(), triggered.size(), DDS_INFINITY);
    if (n < 0) {
      spdlog::error("track reception: waitset: {}", dds_strretcode(n));
      return;
    }
    bool stop = false;
    dds_read_guardcondition(stop_guard, &stop);
    if (stop) return;
    receive_batch();
  }
}

void FusionNode::Impl::receive_batch() {
  // As the tracker role: restore the writing order a take groups by instance (sensor), so the
  // fusion sees the local frames as they were published.
  arrivals.clear();
  const Clock::time_point received = Clock::now();
  const auto reject = [&](std::string_view reason, const std::string& which,
                          const std::string& detail) {
    status.scan_rejected(reason);
    if (const auto count = bad_sample_log.allow()) {
      spdlog::warn("track batch {} rejected: {}: {} ({} rejected since last message)", which,
                   reason, detail, *count);
    }
  };
  dds::take_checked(
      tracks_reader, sample,
      [&](const skytrack_dds_TrackBatch& batch, const dds_sample_info_t& info) {
        const std::string which =
            "of sensor " + std::to_string(batch.sensor) + " scan " + std::to_string(batch.scan);
        const auto& accepted = config.sensors;
        if (!accepted.empty() &&
            std::find(accepted.begin(), accepted.end(), batch.sensor) == accepted.end()) {
          reject(reason::kUnknownSensor, which, "not in skytrackd.sensors");
          return;
        }
        auto frame = dds::from_dds(batch);
        if (!frame) {
          reject(reason::kMalformedSample, which, frame.error().message);
          return;
        }
        arrivals.push_back({info.source_timestamp, std::move(*frame)});
      },
      [&](const dds_sample_info_t& info, const Error& error) {
        reject(reason::kMalformedSample, "from writer " + std::to_string(info.publication_handle),
               error.message);
      });
  std::stable_sort(arrivals.begin(), arrivals.end(),
                   [](const Arrival& a, const Arrival& b) { return a.written < b.written; });
  for (const Arrival& arrival : arrivals) fuse(arrival.frame, received);
}

void FusionNode::Impl::fuse(const TrackFrame& local, Clock::time_point received) {
  const std::vector<TrackFrame> fused = fusion.add(local);
  count_rejections();
  publish(fused);
  if (!fused.empty()) last_fused = fused.back();
  const double latency = std::chrono::duration<double>(Clock::now() - received).count();
  status.scan_processed(local.tracks.size(), latency, last_fused);
}

void FusionNode::Impl::publish(const std::vector<TrackFrame>& fused) {
  for (const TrackFrame& frame : fused) {
    auto out = dds::to_dds(frame);
    dds_return_t rc = DDS_RETCODE_OK;
    if (out) rc = dds_write(fused_writer, out->data());
    if (!out || rc != DDS_RETCODE_OK) {
      if (const auto count = write_log.allow()) {
        spdlog::error("fused picture {} (t = {}) not published: {} ({} since last message)",
                      frame.scan, frame.time,
                      out ? std::string(dds_strretcode(rc)) : out.error().message, *count);
      }
    }
  }
}

void FusionNode::Impl::count_rejections() {
  const fusion::FusionCounters& now = fusion.counters();
  for (std::uint64_t i = counted.frames_late; i < now.frames_late; ++i) {
    status.scan_rejected(kLateFrame);
  }
  for (std::uint64_t i = counted.frames_invalid; i < now.frames_invalid; ++i) {
    status.scan_rejected(kInvalidFrame);
  }
  for (std::uint64_t i = counted.frames_dropped; i < now.frames_dropped; ++i) {
    status.scan_rejected(kDroppedFrame);
  }
  if (now.tracks_invalid > counted.tracks_invalid) {
    status.plots_rejected(kInvalidTrack, now.tracks_invalid - counted.tracks_invalid);
  }
  if (now.sensors_dropped > counted.sensors_dropped) {
    spdlog::warn("{} local tracker(s) silent for more than {} s: fused without them",
                 now.sensors_dropped - counted.sensors_dropped, fusion.spec().sensor_timeout);
  }
  counted = now;
}

FusionNode::FusionNode(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

Expected<std::unique_ptr<FusionNode>> FusionNode::create(const DaemonConfig& config,
                                                         const fusion::FusionSpec& spec) {
  auto session = DdsSession::open(config.dds);
  if (!session) return unexpected(session.error());
  spdlog::info("DDS: {}; domain {}", session->configuration(), config.dds.domain);
  auto impl = std::make_unique<Impl>(config, spec, std::move(*session));
  Impl& n = *impl;
  n.status.set_profile("fusion", config.fusion.config.empty() ? "built-in" : config.fusion.config);
  const DdsSettings& dds = config.dds;
  auto input = n.session.topic(&skytrack_dds_TrackBatch_desc, config.fusion.input_topic);
  if (!input) return unexpected(input.error());
  auto output = n.session.topic(&skytrack_dds_TrackBatch_desc, config.fusion.output_topic);
  if (!output) return unexpected(output.error());
  auto status = n.session.topic(&skytrack_dds_TrackerStatus_desc, dds.topics.status);
  if (!status) return unexpected(status.error());
  auto fused_writer = n.session.writer(*output, tracks_writer_qos(dds).get());
  if (!fused_writer) return unexpected(fused_writer.error());
  auto status_writer = n.session.writer(*status, status_writer_qos(dds).get());
  if (!status_writer) return unexpected(status_writer.error());
  n.fused_writer = *fused_writer;
  n.status_writer = *status_writer;
  if (!n.open_reception(*input)) {
    return make_error("creating the TrackBatch reader and its waitset failed");
  }
  spdlog::info(
      "fusion role: local tracks from '{}', fused picture to '{}' as sensor {} every {} s "
      "(window {} s), status '{}'; partition '{}'",
      config.fusion.input_topic, config.fusion.output_topic, spec.output_sensor, spec.cycle,
      spec.window, dds.topics.status, dds.partitions.empty() ? "" : dds.partitions.front());
  return std::unique_ptr<FusionNode>(new FusionNode(std::move(impl)));
}

FusionNode::~FusionNode() {
  if (impl_ && impl_->running) stop();
}

void FusionNode::start() {
  if (impl_->running) return;
  impl_->running = true;
  impl_->receiver = std::thread([this] { impl_->receive_loop(); });
}

void FusionNode::publish_status() {
  daemon::publish_status(impl_->status_writer, impl_->status.snapshot(0));
}

void FusionNode::stop() {
  Impl& n = *impl_;
  if (!n.running) return;
  n.running = false;
  dds_set_guardcondition(n.stop_guard, true);
  n.receiver.join();
  // The reception thread has ended: the fusion is this thread's now.
  const std::vector<TrackFrame> rest = n.fusion.flush();
  n.publish(rest);
  if (!rest.empty()) n.last_fused = rest.back();
  spdlog::info("stopping: {} fused pictures published in all", n.fusion.counters().cycles);
  publish_status();
}

}  // namespace skytrack::daemon
