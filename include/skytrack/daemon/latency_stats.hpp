#pragma once
// Per-scan latency figures for the status: p50 and p99 over the most recent `window` scans
// (nearest-rank percentiles), and the maximum since start. Not thread-safe; the owner locks.
#include <cstddef>
#include <vector>

namespace skytrack::daemon {

class LatencyStats {
 public:
  explicit LatencyStats(std::size_t window = 1024);

  void add(double seconds);

  /// Nearest-rank percentile (p in [0, 1]) of the window; 0 when empty.
  double percentile(double p) const;
  double max() const { return max_; }
  std::size_t count() const { return count_; }  // samples since start
  std::size_t window_size() const { return filled_; }

 private:
  std::vector<double> ring_;
  std::size_t next_ = 0;
  std::size_t filled_ = 0;
  std::size_t count_ = 0;
  double max_ = 0.0;
};

}  // namespace skytrack::daemon
