// TrackerStatusReport <-> TrackerStatus.
#include "skytrack/dds/conversion.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "sequence_helpers.hpp"

namespace skytrack::dds {
namespace {

using namespace detail;

Expected<void> encode_rejections(const std::vector<RejectionCount>& from, std::string_view what,
                                 dds_sequence_skytrack_dds_RejectionCount& to) {
  if (from.size() > kMaxSequence) return make_error(std::string(what) + ": too many entries");
  if (!alloc_zeroed(to, from.size())) return unexpected(out_of_memory(what));
  for (std::size_t i = 0; i < from.size(); ++i) {
    auto reason = dup_string(from[i].reason, field(what, i, "reason"));
    if (!reason) return unexpected(reason.error());
    to._buffer[i].reason = *reason;
    to._buffer[i].count = from[i].count;
  }
  return {};
}

Expected<std::vector<RejectionCount>> decode_rejections(
    const dds_sequence_skytrack_dds_RejectionCount& from, std::string_view what) {
  if (auto e = missing_buffer(from, what)) return unexpected(*e);
  std::vector<RejectionCount> out;
  out.reserve(from._length);
  for (std::uint32_t i = 0; i < from._length; ++i) {
    out.push_back({from_c_string(from._buffer[i].reason), from._buffer[i].count});
  }
  return out;
}

}  // namespace

// ---- TrackerStatusReport <-> TrackerStatus --------------------------------------------------

Expected<TrackerStatusSample> to_dds(const TrackerStatusReport& status) {
  TrackerStatusSample out;
  skytrack_dds_TrackerStatus& s = out.get();
  const std::pair<const std::string*, char**> strings[] = {
      {&status.instance, &s.instance},
      {&status.profile_name, &s.profile_name},
      {&status.profile_version, &s.profile_version}};
  const char* names[] = {"TrackerStatusReport.instance", "TrackerStatusReport.profile_name",
                         "TrackerStatusReport.profile_version"};
  for (std::size_t i = 0; i < 3; ++i) {
    auto copy = dup_string(*strings[i].first, names[i]);
    if (!copy) return unexpected(copy.error());
    *strings[i].second = *copy;
  }
  s.uptime = status.uptime;
  s.scans_processed = status.scans_processed;
  s.plots_processed = status.plots_processed;
  if (auto ok = encode_rejections(status.plots_rejected, "TrackerStatusReport.plots_rejected",
                                  s.plots_rejected);
      !ok) {
    return unexpected(ok.error());
  }
  if (auto ok = encode_rejections(status.scans_rejected, "TrackerStatusReport.scans_rejected",
                                  s.scans_rejected);
      !ok) {
    return unexpected(ok.error());
  }
  s.scans_dropped = status.scans_dropped;
  s.queue_depth = status.queue_depth;
  s.latency_p50 = status.latency_p50;
  s.latency_p99 = status.latency_p99;
  s.latency_max = status.latency_max;
  s.tracks_tentative = status.tracks_tentative;
  s.tracks_confirmed = status.tracks_confirmed;
  s.tracks_coasting = status.tracks_coasting;
  s.numeric_failures = status.numeric_failures;
  return out;
}

Expected<TrackerStatusReport> from_dds(const skytrack_dds_TrackerStatus& status) {
  TrackerStatusReport out;
  out.instance = from_c_string(status.instance);
  out.profile_name = from_c_string(status.profile_name);
  out.profile_version = from_c_string(status.profile_version);
  out.uptime = status.uptime;
  out.scans_processed = status.scans_processed;
  out.plots_processed = status.plots_processed;
  auto plots = decode_rejections(status.plots_rejected, "TrackerStatus.plots_rejected");
  if (!plots) return unexpected(plots.error());
  out.plots_rejected = std::move(*plots);
  auto scans = decode_rejections(status.scans_rejected, "TrackerStatus.scans_rejected");
  if (!scans) return unexpected(scans.error());
  out.scans_rejected = std::move(*scans);
  out.scans_dropped = status.scans_dropped;
  out.queue_depth = status.queue_depth;
  out.latency_p50 = status.latency_p50;
  out.latency_p99 = status.latency_p99;
  out.latency_max = status.latency_max;
  out.tracks_tentative = status.tracks_tentative;
  out.tracks_confirmed = status.tracks_confirmed;
  out.tracks_coasting = status.tracks_coasting;
  out.numeric_failures = status.numeric_failures;
  return out;
}

}  // namespace skytrack::dds
