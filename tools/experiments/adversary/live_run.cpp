#include "live_run.hpp"

#include <algorithm>
#include <iterator>
#include <thread>

#include <fmt/format.h>

namespace skytrack::adversary {
namespace {

using namespace std::chrono_literals;

class LiveRun {
 public:
  LiveRun(const Options& options, const GoodStream& good, const std::vector<Phase>& phases,
          DdsLink& link, Adversary& adversary)
      : options_(options), good_(good), phases_(phases), link_(link), adversary_(adversary) {}

  RunRecord run();

 private:
  double elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
  /// Samples the daemon's memory into the current phase; false (and why) when the run must stop.
  bool check();
  /// Waits for `due`, checking meanwhile; false when the run must stop.
  bool wait_until(Clock::time_point due);
  void begin_phase(std::size_t p);
  /// Waits for the TrackBatches of every good batch written (at most --drain seconds), then
  /// for one status after them.
  void drain();

  const Options& options_;
  const GoodStream& good_;
  const std::vector<Phase>& phases_;
  DdsLink& link_;
  Adversary& adversary_;
  Clock::time_point start_;
  RunRecord record_;
};

bool LiveRun::check() {
  if (!record_.stopped.empty()) return false;
  auto frames = link_.take_frames();
  std::move(frames.begin(), frames.end(), std::back_inserter(record_.frames));
  if (elapsed() > options_.max_seconds) {
    record_.stopped = fmt::format("--max-seconds ({} s) reached", options_.max_seconds);
    return false;
  }
  if (options_.daemon_pid <= 0) return true;
  const auto memory = read_memory(options_.daemon_pid);
  if (!memory) {
    record_.stopped = fmt::format("skytrackd (pid {}) is gone", options_.daemon_pid);
    return false;
  }
  if (!record_.phases.empty()) {
    PhaseRecord& phase = record_.phases.back();
    phase.rss_max_mib = std::max(phase.rss_max_mib, memory->rss_mib);
    phase.last_memory = memory;
  }
  if (memory->rss_mib > options_.max_rss_mb) {
    record_.stopped = fmt::format("skytrackd's VmRSS ({:.0f} MiB) passed --max-rss-mb ({:.0f})",
                                  memory->rss_mib, options_.max_rss_mb);
    return false;
  }
  return true;
}

bool LiveRun::wait_until(Clock::time_point due) {
  for (;;) {
    if (!check()) return false;
    const auto now = Clock::now();
    if (now >= due) return true;
    std::this_thread::sleep_for(std::min<Clock::duration>(due - now, 100ms));
  }
}

void LiveRun::begin_phase(std::size_t p) {
  const auto now = Clock::now();
  if (!record_.phases.empty()) record_.phases.back().end = now;
  record_.phases.push_back({});
  record_.phases.back().begin = now;
  const Phase& phase = phases_[p];
  fmt::print(stderr, "[{:6.1f} s] phase {}/{}: {} (stream {:.0f}-{:.0f} s): {}\n", elapsed(), p + 1,
             phases_.size(), phase.name, phase.begin - good_.start, phase.end - good_.start,
             phase.what);
  check();
}

void LiveRun::drain() {
  const auto deadline = Clock::now() + std::chrono::duration<double>(options_.drain);
  while (record_.frames.size() < record_.writes && Clock::now() < deadline) {
    if (!check()) break;
    std::this_thread::sleep_for(20ms);
  }
  // One status after the last TrackBatch, so the last phase's counts are complete.
  const auto after = Clock::now();
  const auto status_deadline = after + 3s;
  while (Clock::now() < status_deadline) {
    const auto statuses = link_.statuses();
    if (!statuses.empty() && statuses.back().at > after) break;
    std::this_thread::sleep_for(20ms);
  }
  check();
}

RunRecord LiveRun::run() {
  start_ = Clock::now();
  record_.written.assign(good_.scans.size(), std::nullopt);
  std::size_t p = 0;
  bool begun = false;
  const auto& scans = good_.scans;
  for (std::size_t i = 0; i < scans.size(); ++i) {
    const PlotScan& scan = scans[i];
    while (p < phases_.size() && scan.time >= phases_[p].end) {
      ++p;
      begun = false;
    }
    if (p == phases_.size()) break;
    const auto due =
        start_ + std::chrono::duration_cast<Clock::duration>(
                     std::chrono::duration<double>((scan.time - good_.start) / options_.rate));
    if (!wait_until(due)) break;
    if (!begun) {
      begin_phase(p);
      begun = true;
    }
    PhaseRecord& phase = record_.phases.back();
    const auto now = Clock::now();
    if (auto ok = link_.write(scan); !ok) {
      record_.stopped = "writing sensor 1's batch failed: " + ok.error().message;
      break;
    }
    record_.written[i] = now;
    ++record_.writes;
    phase.good.push_back(i);
    const double next_time = i + 1 < scans.size() ? scans[i + 1].time : scan.time + 1.0;
    adversary_.act(phases_[p], scan.time, next_time, phase.tally);
  }
  if (record_.stopped.empty() || record_.stopped.find("gone") == std::string::npos) drain();
  if (!record_.phases.empty()) record_.phases.back().end = Clock::now();
  auto frames = link_.take_frames();
  std::move(frames.begin(), frames.end(), std::back_inserter(record_.frames));
  record_.statuses = link_.statuses();
  record_.wall_seconds = elapsed();
  return std::move(record_);
}

}  // namespace

RunRecord run_live(const Options& options, const GoodStream& good, const std::vector<Phase>& phases,
                   DdsLink& link, Adversary& adversary) {
  return LiveRun(options, good, phases, link, adversary).run();
}

}  // namespace skytrack::adversary
