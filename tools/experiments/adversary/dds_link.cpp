#include "dds_link.hpp"

#include <array>
#include <cstdlib>
#include <filesystem>

#include "skytrack/daemon/dds_environment.hpp"

namespace skytrack::adversary {
namespace {

namespace fs = std::filesystem;

constexpr std::uint32_t kTake = 16;

std::string self_path() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string() : self.string();
}

}  // namespace

Expected<std::string> require_loopback() {
  const std::string exe = self_path();
  std::vector<std::string> candidates = daemon::loopback_config_candidates(exe);
  if (!exe.empty()) {  // build/tools/experiments/adversary/skytrack-adversary
    candidates.push_back((fs::path(exe).parent_path() / "../../../../config/dds/loopback.xml")
                             .lexically_normal()
                             .string());
  }
  auto chosen = daemon::ensure_dds_configuration(candidates);
  if (!chosen) return unexpected(chosen.error());
  std::string uri = std::getenv("CYCLONEDDS_URI");
  if (uri.rfind("file://", 0) == 0) uri = uri.substr(7);
  if (uri.find(',') != std::string::npos || !daemon::is_loopback_only_config(uri)) {
    return make_error("CYCLONEDDS_URI=" + std::string(std::getenv("CYCLONEDDS_URI")) +
                      " is not a loopback-only configuration file (loopback interface, no "
                      "multicast): skytrack-adversary floods its DDS domain and runs on loopback "
                      "only (config/dds/loopback.xml)");
  }
  return *chosen;
}

Expected<std::unique_ptr<DdsLink>> DdsLink::open(const daemon::DdsSettings& dds,
                                                 std::uint32_t good_sensor) {
  auto session = daemon::DdsSession::open(dds);
  if (!session) return unexpected(session.error());
  std::unique_ptr<DdsLink> link(new DdsLink(std::move(*session), good_sensor));
  daemon::DdsSession& s = link->session_;
  auto plots = s.topic(&skytrack_dds_PlotBatch_desc, dds.topics.plots);
  if (!plots) return unexpected(plots.error());
  auto tracks = s.topic(&skytrack_dds_TrackBatch_desc, dds.topics.tracks);
  if (!tracks) return unexpected(tracks.error());
  auto status = s.topic(&skytrack_dds_TrackerStatus_desc, dds.topics.status);
  if (!status) return unexpected(status.error());
  auto writer = s.writer(*plots, daemon::plots_writer_qos(dds).get());
  if (!writer) return unexpected(writer.error());
  auto tracks_reader = s.reader(*tracks, daemon::tracks_reader_qos(dds, true).get());
  if (!tracks_reader) return unexpected(tracks_reader.error());
  auto status_reader = s.reader(*status, daemon::status_reader_qos(dds).get());
  if (!status_reader) return unexpected(status_reader.error());
  link->writer_ = *writer;
  link->tracks_ = *tracks_reader;
  link->status_ = *status_reader;
  link->waitset_ = dds_create_waitset(s.participant());
  link->stop_ = dds_create_guardcondition(s.participant());
  const dds_entity_t tracks_ready = dds_create_readcondition(link->tracks_, DDS_ANY_STATE);
  const dds_entity_t status_ready = dds_create_readcondition(link->status_, DDS_ANY_STATE);
  if (link->waitset_ < 0 || link->stop_ < 0 || tracks_ready < 0 || status_ready < 0 ||
      dds_waitset_attach(link->waitset_, tracks_ready, 0) != DDS_RETCODE_OK ||
      dds_waitset_attach(link->waitset_, status_ready, 1) != DDS_RETCODE_OK ||
      dds_waitset_attach(link->waitset_, link->stop_, 2) != DDS_RETCODE_OK) {
    return make_error("creating the listener's waitset failed");
  }
  return link;
}

DdsLink::~DdsLink() {
  if (listener_.joinable()) {
    dds_set_guardcondition(stop_, true);
    listener_.join();
  }
}

bool DdsLink::wait_for_daemon(std::chrono::milliseconds timeout) {
  const auto deadline = Clock::now() + timeout;
  const auto left = [&] {
    return std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
  };
  return daemon::wait_for_readers(writer_, 1, timeout) &&
         daemon::wait_for_writers(tracks_, 1, std::max(left(), std::chrono::milliseconds(0))) &&
         daemon::wait_for_writers(status_, 1, std::max(left(), std::chrono::milliseconds(0)));
}

void DdsLink::listen() {
  since_ = dds_time();
  listener_ = std::thread([this] { run(); });
}

Expected<void> DdsLink::write(const PlotScan& scan) {
  if (auto ok = dds::to_dds(scan, sample_); !ok) return unexpected(ok.error());
  return write(sample_);
}

Expected<void> DdsLink::write(dds::PlotBatchSample& sample) {
  if (const dds_return_t rc = dds_write(writer_, sample.data()); rc != DDS_RETCODE_OK) {
    return make_error(std::string("dds_write: ") + dds_strretcode(rc));
  }
  return {};
}

std::vector<ReceivedFrame> DdsLink::take_frames() {
  std::lock_guard lock(mutex_);
  std::vector<ReceivedFrame> out;
  out.swap(frames_);
  return out;
}

std::vector<ReceivedStatus> DdsLink::statuses() const {
  std::lock_guard lock(mutex_);
  return statuses_;
}

void DdsLink::run() {
  for (;;) {
    std::array<dds_attach_t, 3> triggered{};
    if (dds_waitset_wait(waitset_, triggered.data(), triggered.size(), DDS_SECS(1)) < 0) return;
    bool stop = false;
    dds_read_guardcondition(stop_, &stop);
    if (stop) return;
    take_tracks();
    take_status();
  }
}

void DdsLink::take_tracks() {
  std::array<void*, kTake> samples{};
  std::array<dds_sample_info_t, kTake> infos{};
  for (;;) {
    const dds_return_t n = dds_take(tracks_, samples.data(), infos.data(), kTake, kTake);
    if (n <= 0) return;
    const Clock::time_point at = Clock::now();
    for (dds_return_t i = 0; i < n; ++i) {
      const auto k = static_cast<std::size_t>(i);
      if (!infos[k].valid_data || infos[k].source_timestamp < since_) continue;
      const auto& batch = *static_cast<const skytrack_dds_TrackBatch*>(samples[k]);
      if (batch.sensor != good_sensor_) {
        ++other_frames_;
        continue;
      }
      if (auto frame = dds::from_dds(batch)) {
        std::lock_guard lock(mutex_);
        frames_.push_back({std::move(*frame), at});
      }
    }
    dds_return_loan(tracks_, samples.data(), n);
  }
}

void DdsLink::take_status() {
  std::array<void*, kTake> samples{};
  std::array<dds_sample_info_t, kTake> infos{};
  for (;;) {
    const dds_return_t n = dds_take(status_, samples.data(), infos.data(), kTake, kTake);
    if (n <= 0) return;
    const Clock::time_point at = Clock::now();
    for (dds_return_t i = 0; i < n; ++i) {
      const auto k = static_cast<std::size_t>(i);
      if (!infos[k].valid_data) continue;
      if (auto report =
              dds::from_dds(*static_cast<const skytrack_dds_TrackerStatus*>(samples[k]))) {
        std::lock_guard lock(mutex_);
        statuses_.push_back({std::move(*report), at});
      }
    }
    dds_return_loan(status_, samples.data(), n);
  }
}

}  // namespace skytrack::adversary
