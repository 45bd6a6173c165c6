#include "skytrack/daemon/status_collector.hpp"

#include <spdlog/spdlog.h>

#include "skytrack/dds/conversion.hpp"

namespace skytrack::daemon {
namespace {

void add(std::map<std::string, std::uint64_t, std::less<>>& counts, std::string_view reason,
         std::uint64_t n) {
  auto it = counts.find(reason);
  if (it == counts.end()) it = counts.emplace(std::string(reason), 0).first;
  it->second += n;
}

}  // namespace

StatusCollector::StatusCollector(std::string instance, std::size_t latency_window)
    : latency_(latency_window) {
  report_.instance = std::move(instance);
}

void StatusCollector::set_profile(const std::string& name, const std::string& version) {
  std::lock_guard lock(mutex_);
  report_.profile_name = name;
  report_.profile_version = version;
}

void StatusCollector::scan_rejected(std::string_view reason) {
  std::lock_guard lock(mutex_);
  add(scans_rejected_, reason, 1);
}

void StatusCollector::plots_rejected(std::string_view reason, std::uint64_t count) {
  if (count == 0) return;
  std::lock_guard lock(mutex_);
  add(plots_rejected_, reason, count);
}

std::uint64_t StatusCollector::scan_dropped() {
  std::lock_guard lock(mutex_);
  return ++report_.scans_dropped;
}

void StatusCollector::scan_processed(std::uint64_t plots, double latency, const TrackFrame& frame,
                                     std::uint64_t numeric_failures) {
  std::uint32_t tentative = 0, confirmed = 0, coasting = 0;
  for (const TrackReport& t : frame.tracks) {
    tentative += t.status == TrackStatus::kTentative;
    confirmed += t.status == TrackStatus::kConfirmed;
    coasting += t.status == TrackStatus::kCoasting;
  }
  std::lock_guard lock(mutex_);
  ++report_.scans_processed;
  report_.plots_processed += plots;
  latency_.add(latency);
  report_.tracks_tentative = tentative;
  report_.tracks_confirmed = confirmed;
  report_.tracks_coasting = coasting;
  report_.numeric_failures += numeric_failures;
}

TrackerStatusReport StatusCollector::snapshot(std::uint32_t queue_depth) const {
  std::lock_guard lock(mutex_);
  TrackerStatusReport out = report_;
  out.uptime = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  out.queue_depth = queue_depth;
  for (const auto& [reason, count] : plots_rejected_) out.plots_rejected.push_back({reason, count});
  for (const auto& [reason, count] : scans_rejected_) out.scans_rejected.push_back({reason, count});
  out.latency_p50 = latency_.percentile(0.50);
  out.latency_p99 = latency_.percentile(0.99);
  out.latency_max = latency_.max();
  return out;
}

void publish_status(dds_entity_t writer, const TrackerStatusReport& report) {
  auto sample = dds::to_dds(report);
  if (!sample) {
    spdlog::error("TrackerStatus not published: {}", sample.error().message);
    return;
  }
  if (const dds_return_t rc = dds_write(writer, sample->data()); rc != DDS_RETCODE_OK) {
    spdlog::error("TrackerStatus not published: {}", dds_strretcode(rc));
  }
}

}  // namespace skytrack::daemon
