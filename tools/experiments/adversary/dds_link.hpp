#pragma once
// The adversary's DDS side: one participant (the loopback configuration only, see
// require_loopback), a PlotBatch writer for both sensors, and a listener thread that stamps
// each TrackBatch of the good sensor and each TrackerStatus with the moment it arrived.
#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "skytrack/core/expected.hpp"
#include "skytrack/core/track_report.hpp"
#include "skytrack/core/tracker_status.hpp"
#include "skytrack/daemon/daemon_config.hpp"
#include "skytrack/daemon/dds_session.hpp"
#include "skytrack/dds/conversion.hpp"

namespace skytrack::adversary {

using Clock = std::chrono::steady_clock;

struct ReceivedFrame {
  TrackFrame frame;
  Clock::time_point at;
};
struct ReceivedStatus {
  TrackerStatusReport status;
  Clock::time_point at;
};

/// Sets CYCLONEDDS_URI to the shipped loopback XML when it is unset, and refuses any other
/// configuration than a loopback-only file: this tool floods the domain and must never do so
/// off the machine. Returns the line to print.
Expected<std::string> require_loopback();

class DdsLink {
 public:
  static Expected<std::unique_ptr<DdsLink>> open(const daemon::DdsSettings& dds,
                                                 std::uint32_t good_sensor);
  ~DdsLink();
  DdsLink(const DdsLink&) = delete;
  DdsLink& operator=(const DdsLink&) = delete;

  /// Waits until the daemon's plot reader, TrackBatch writer and status writer have matched.
  bool wait_for_daemon(std::chrono::milliseconds timeout);
  /// Starts the listener; samples written before `since` (transient-local history) are ignored.
  void listen();

  /// Writes a batch (the sample buffers are reused) or a prepared sample; the DDS error if any.
  Expected<void> write(const PlotScan& scan);
  Expected<void> write(dds::PlotBatchSample& sample);

  /// The good sensor's frames received since the last call, moved out.
  std::vector<ReceivedFrame> take_frames();
  /// Every status received so far (copied).
  std::vector<ReceivedStatus> statuses() const;
  /// TrackBatches of other sensors received.
  std::uint64_t other_frames() const { return other_frames_.load(); }

 private:
  DdsLink(daemon::DdsSession session, std::uint32_t good_sensor)
      : session_(std::move(session)), good_sensor_(good_sensor) {}
  void run();
  void take_tracks();
  void take_status();

  daemon::DdsSession session_;
  std::uint32_t good_sensor_;
  dds_entity_t writer_ = 0;
  dds_entity_t tracks_ = 0;
  dds_entity_t status_ = 0;
  dds_entity_t waitset_ = 0;
  dds_entity_t stop_ = 0;
  dds_time_t since_ = 0;
  dds::PlotBatchSample sample_;
  std::thread listener_;
  mutable std::mutex mutex_;
  std::vector<ReceivedFrame> frames_;
  std::vector<ReceivedStatus> statuses_;
  std::atomic<std::uint64_t> other_frames_{0};
};

}  // namespace skytrack::adversary
