#pragma once
// The bounded queue between DDS reception and the tracker. push() never waits: when the queue
// is full the overload policy drops the oldest waiting scan or the new one, and push() says
// which, so reception never waits on tracking. pop() waits for a scan or close().
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <mutex>
#include <optional>

#include "skytrack/core/plot.hpp"
#include "skytrack/daemon/daemon_config.hpp"

namespace skytrack::daemon {

struct QueuedScan {
  PlotScan scan;
  std::chrono::steady_clock::time_point received;  // when DDS delivered it
};

class ScanQueue {
 public:
  ScanQueue(std::size_t capacity, OverloadPolicy policy);

  /// The scan that the overload policy dropped to make room (the oldest waiting one, or
  /// `item` itself), if any. A closed queue drops `item`.
  std::optional<QueuedScan> push(QueuedScan item);

  /// The oldest scan; waits until one arrives or the queue is closed (then nullopt).
  std::optional<QueuedScan> pop();
  /// As pop(), giving up after `timeout`.
  std::optional<QueuedScan> pop_for(std::chrono::milliseconds timeout);

  /// Wakes pop(); later pushes are refused. Scans still waiting can be discarded with clear().
  void close();
  /// Removes every waiting scan; returns how many there were.
  std::size_t clear();

  std::size_t size() const;
  std::size_t capacity() const { return capacity_; }

 private:
  std::optional<QueuedScan> pop_locked();

  const std::size_t capacity_;
  const OverloadPolicy policy_;
  mutable std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<QueuedScan> items_;
  bool closed_ = false;
};

}  // namespace skytrack::daemon
