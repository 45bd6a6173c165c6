#pragma once
// Rate-limited logging: at most one message per `interval`, with the number of events that
// were not logged in between, so a flood of drops or bad samples costs one line per second.
#include <chrono>
#include <cstdint>
#include <optional>

namespace skytrack::daemon {

class RateLimiter {
 public:
  using Clock = std::chrono::steady_clock;
  explicit RateLimiter(Clock::duration interval = std::chrono::seconds(1)) : interval_(interval) {}

  /// Counts an event; returns how many events this message stands for (itself and the ones
  /// suppressed since the last message) when a message may be logged now, else nullopt.
  std::optional<std::uint64_t> allow(Clock::time_point now = Clock::now()) {
    ++pending_;
    if (last_ && now - *last_ < interval_) return std::nullopt;
    last_ = now;
    const std::uint64_t n = pending_;
    pending_ = 0;
    return n;
  }

 private:
  Clock::duration interval_;
  std::optional<Clock::time_point> last_;
  std::uint64_t pending_ = 0;
};

}  // namespace skytrack::daemon
