#include "skytrack/daemon/scan_queue.hpp"

#include <utility>

namespace skytrack::daemon {

ScanQueue::ScanQueue(std::size_t capacity, OverloadPolicy policy)
    : capacity_(capacity == 0 ? 1 : capacity), policy_(policy) {}

std::optional<QueuedScan> ScanQueue::push(QueuedScan item) {
  std::optional<QueuedScan> dropped;
  {
    std::lock_guard lock(mutex_);
    if (closed_) return item;
    if (items_.size() >= capacity_) {
      if (policy_ == OverloadPolicy::kDropNewest) return item;
      dropped = std::move(items_.front());
      items_.pop_front();
    }
    items_.push_back(std::move(item));
  }
  ready_.notify_one();
  return dropped;
}

std::optional<QueuedScan> ScanQueue::pop_locked() {
  if (items_.empty()) return std::nullopt;
  QueuedScan item = std::move(items_.front());
  items_.pop_front();
  return item;
}

std::optional<QueuedScan> ScanQueue::pop() {
  std::unique_lock lock(mutex_);
  ready_.wait(lock, [this] { return closed_ || !items_.empty(); });
  if (closed_) return std::nullopt;
  return pop_locked();
}

std::optional<QueuedScan> ScanQueue::pop_for(std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  ready_.wait_for(lock, timeout, [this] { return closed_ || !items_.empty(); });
  if (closed_) return std::nullopt;
  return pop_locked();
}

void ScanQueue::close() {
  {
    std::lock_guard lock(mutex_);
    closed_ = true;
  }
  ready_.notify_all();
}

std::size_t ScanQueue::clear() {
  std::lock_guard lock(mutex_);
  const std::size_t n = items_.size();
  items_.clear();
  return n;
}

std::size_t ScanQueue::size() const {
  std::lock_guard lock(mutex_);
  return items_.size();
}

}  // namespace skytrack::daemon
