// The daemon's reception: PlotBatch samples from DDS and ASTERIX datagrams from UDP,
// checked, converted and queued for the tracking thread (daemon_impl.hpp).
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <utility>

#include "skytrack/dds/checked_take.hpp"
#include "skytrack/dds/conversion.hpp"

#include "daemon_impl.hpp"

namespace skytrack::daemon {

void Daemon::Impl::receive_loop() {
  for (;;) {
    std::array<dds_attach_t, 2> triggered{};
    const dds_return_t n =
        dds_waitset_wait(waitset, triggered.data(), triggered.size(), DDS_INFINITY);
    if (n < 0) {
      spdlog::error("plot reception: waitset: {}", dds_strretcode(n));
      return;
    }
    bool stop = false;
    dds_read_guardcondition(stop_guard, &stop);
    if (stop) return;
    receive_batch();
  }
}

void Daemon::Impl::receive_batch() {
  // Take everything available, then restore the order the samples were written in: a take
  // returns samples grouped by instance (sensor), which would reorder the sensors' scans
  // against each other and so change what the shared tracker sees. Every sample is checked
  // as bytes before Cyclone deserialises it (take_checked).
  arrivals.clear();
  const Clock::time_point received = Clock::now();
  dds::take_checked(
      plots_reader, plot_sample,
      [&](const skytrack_dds_PlotBatch& batch, const dds_sample_info_t& info) {
        if (auto item = convert(batch, received)) {
          arrivals.push_back({info.source_timestamp, std::move(*item)});
        }
      },
      [&](const dds_sample_info_t& info, const Error& error) {
        reject_sample(reason::kMalformedSample,
                      "from writer " + std::to_string(info.publication_handle), error.message);
      });
  std::stable_sort(arrivals.begin(), arrivals.end(),
                   [](const Arrival& a, const Arrival& b) { return a.written < b.written; });
  for (Arrival& arrival : arrivals) enqueue(std::move(arrival.item));
}

void Daemon::Impl::enqueue(QueuedScan item) {
  // Both inputs may push at once: the queue and the counters lock themselves.
  auto dropped = queue.push(std::move(item));
  if (!dropped) return;
  const std::uint64_t total = status.scan_dropped();
  std::lock_guard lock(drop_log_mutex);
  if (const auto count = drop_log.allow()) {
    spdlog::warn(
        "overload ({}, queue of {}): dropped sensor {} scan {}; {} dropped since last "
        "message, {} in all",
        to_string(config.queue.overload), queue.capacity(), dropped->scan.sensor,
        dropped->scan.scan, *count, total);
  }
}

bool Daemon::Impl::open_plot_reception(dds_entity_t topic) {
  auto reader = session.reader(topic, plots_reader_qos(config.dds).get());
  if (!reader) {
    spdlog::error("{}", reader.error().message);
    return false;
  }
  plots_reader = *reader;
  waitset = dds_create_waitset(session.participant());
  readable = dds_create_readcondition(plots_reader, DDS_ANY_STATE);
  stop_guard = dds_create_guardcondition(session.participant());
  return waitset >= 0 && readable >= 0 && stop_guard >= 0 &&
         dds_waitset_attach(waitset, readable, readable) == DDS_RETCODE_OK &&
         dds_waitset_attach(waitset, stop_guard, stop_guard) == DDS_RETCODE_OK;
}

void Daemon::Impl::start_udp() {
  // Decoding errors and dropped reports count as rejected plots, "asterix <reason>".
  udp->start(
      [this](PlotScan&& scan) {
        enqueue(QueuedScan{std::move(scan), Clock::now()});
      },
      [this](const asterix::DecodeError& e) {
        status.plots_rejected("asterix " + std::string(asterix::to_string(e.reason)), 1);
        if (const auto count = asterix_log.allow()) {
          spdlog::warn("ASTERIX input: {} ({} errors since last message)", asterix::to_string(e),
                       *count);
        }
      },
      [this](asterix::DropReason reason, std::uint64_t n) {
        status.plots_rejected("asterix " + std::string(asterix::to_string(reason)), n);
      });
}

std::optional<QueuedScan> Daemon::Impl::convert(const skytrack_dds_PlotBatch& batch,
                                                Clock::time_point received) {
  QueuedScan item{{}, received};
  const auto which = [&batch] {
    return "of sensor " + std::to_string(batch.sensor) + " scan " + std::to_string(batch.scan);
  };
  if (batch.plot_ids._length > static_cast<std::uint32_t>(config.max_plots_per_scan)) {
    reject_sample(reason::kTooManyPlots, which(),
                  std::to_string(batch.plot_ids._length) + " plots, at most " +
                      std::to_string(config.max_plots_per_scan));
    return std::nullopt;
  }
  if (auto ok = dds::from_dds(batch, item.scan); !ok) {
    reject_sample(reason::kMalformedSample, which(), ok.error().message);
    return std::nullopt;
  }
  return item;
}

void Daemon::Impl::reject_sample(std::string_view reason, const std::string& which,
                                 const std::string& detail) {
  status.scan_rejected(reason);
  if (const auto count = bad_sample_log.allow()) {
    spdlog::warn("plot batch {} rejected: {}: {} ({} rejected since last message)", which, reason,
                 detail, *count);
  }
}

}  // namespace skytrack::daemon
