#include "skytrack/daemon/latency_stats.hpp"

#include <algorithm>
#include <cmath>

namespace skytrack::daemon {

LatencyStats::LatencyStats(std::size_t window) : ring_(window == 0 ? 1 : window, 0.0) {}

void LatencyStats::add(double seconds) {
  ring_[next_] = seconds;
  next_ = (next_ + 1) % ring_.size();
  filled_ = std::min(filled_ + 1, ring_.size());
  ++count_;
  max_ = std::max(max_, seconds);
}

double LatencyStats::percentile(double p) const {
  if (filled_ == 0) return 0.0;
  std::vector<double> values(ring_.begin(), ring_.begin() + static_cast<std::ptrdiff_t>(filled_));
  // Nearest rank: the smallest value with at least p of the samples at or below it.
  const double rank = std::ceil(std::clamp(p, 0.0, 1.0) * static_cast<double>(filled_));
  const std::size_t k = rank < 1.0 ? 0 : static_cast<std::size_t>(rank) - 1;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

}  // namespace skytrack::daemon
