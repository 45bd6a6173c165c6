#include "measurements.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace skytrack::adversary {
namespace {

/// The nearest-rank p-quantile of sorted values.
double quantile(const std::vector<double>& sorted, double p) {
  const auto rank = static_cast<std::size_t>(std::ceil(p * static_cast<double>(sorted.size())));
  return sorted[std::clamp<std::size_t>(rank, 1, sorted.size()) - 1];
}

/// Counts of `now` minus those of `before` (a reason absent before counts from 0).
std::map<std::string, std::uint64_t> minus(const std::vector<RejectionCount>& now,
                                           const std::vector<RejectionCount>* before) {
  std::map<std::string, std::uint64_t> out;
  for (const RejectionCount& c : now) out[c.reason] += c.count;
  if (before != nullptr) {
    for (const RejectionCount& c : *before) out[c.reason] -= std::min(out[c.reason], c.count);
  }
  std::erase_if(out, [](const auto& kv) { return kv.second == 0; });
  return out;
}

}  // namespace

LatencySummary summarize_latency(std::vector<double> latencies, std::size_t sent) {
  LatencySummary s;
  s.sent = sent;
  s.answered = latencies.size();
  if (latencies.empty()) return s;
  std::sort(latencies.begin(), latencies.end());
  s.p50 = quantile(latencies, 0.50);
  s.p99 = quantile(latencies, 0.99);
  s.max = latencies.back();
  return s;
}

std::optional<MemorySample> read_memory(int pid) {
  if (pid <= 0) return std::nullopt;
  std::ifstream in("/proc/" + std::to_string(pid) + "/status");
  if (!in) return std::nullopt;
  MemorySample m;
  bool rss = false;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string key;
    double kb = 0.0;
    fields >> key >> kb;
    if (key == "VmRSS:") {
      m.rss_mib = kb / 1024.0;
      rss = true;
    } else if (key == "VmHWM:") {
      m.hwm_mib = kb / 1024.0;
    } else if (key == "State:" && line.find("zombie") != std::string::npos) {
      return std::nullopt;  // exited, not yet reaped
    }
  }
  if (!rss) return std::nullopt;
  return m;
}

StatusWindow status_window(const std::vector<ReceivedStatus>& statuses, Clock::time_point from,
                           Clock::time_point to) {
  StatusWindow w;
  const TrackerStatusReport* before = nullptr;
  const TrackerStatusReport* last = nullptr;
  for (const ReceivedStatus& s : statuses) {  // in arrival order
    if (s.at < from) before = &s.status;
    if (s.at < to) last = &s.status;
    if (s.at >= from && s.at < to) w.queue_max = std::max(w.queue_max, s.status.queue_depth);
  }
  if (last == nullptr) return w;
  w.seen = true;
  w.scans_rejected = minus(last->scans_rejected, before ? &before->scans_rejected : nullptr);
  w.plots_rejected = minus(last->plots_rejected, before ? &before->plots_rejected : nullptr);
  const auto delta = [](std::uint64_t now, std::uint64_t then) {
    return now - std::min(now, then);
  };
  w.scans_processed = delta(last->scans_processed, before ? before->scans_processed : 0);
  w.plots_processed = delta(last->plots_processed, before ? before->plots_processed : 0);
  w.scans_dropped = delta(last->scans_dropped, before ? before->scans_dropped : 0);
  w.confirmed = last->tracks_confirmed;
  return w;
}

std::string format_counts(const std::map<std::string, std::uint64_t>& counts) {
  if (counts.empty()) return "none";
  std::string out;
  for (const auto& [reason, n] : counts) {
    out += (out.empty() ? "" : ", ") + reason + ": " + std::to_string(n);
  }
  return out;
}

}  // namespace skytrack::adversary
