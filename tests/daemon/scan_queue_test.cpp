#include "skytrack/daemon/scan_queue.hpp"

#include <atomic>
#include <thread>

#include <gtest/gtest.h>

namespace skytrack::daemon {
namespace {

QueuedScan scan_number(std::uint64_t n) {
  QueuedScan item;
  item.scan.scan = n;
  return item;
}

TEST(ScanQueue, PopsInArrivalOrder) {
  ScanQueue queue(4, OverloadPolicy::kDropOldest);
  for (std::uint64_t n = 1; n <= 3; ++n) EXPECT_FALSE(queue.push(scan_number(n)));
  EXPECT_EQ(queue.size(), 3u);
  for (std::uint64_t n = 1; n <= 3; ++n) EXPECT_EQ(queue.pop()->scan.scan, n);
}

TEST(ScanQueue, DropOldestMakesRoomForTheNewScan) {
  // GIVEN a full queue of 2 with the drop-oldest policy
  ScanQueue queue(2, OverloadPolicy::kDropOldest);
  queue.push(scan_number(1));
  queue.push(scan_number(2));
  // WHEN a third scan arrives THEN the oldest is dropped and reported
  const auto dropped = queue.push(scan_number(3));
  ASSERT_TRUE(dropped);
  EXPECT_EQ(dropped->scan.scan, 1u);
  EXPECT_EQ(queue.pop()->scan.scan, 2u);
  EXPECT_EQ(queue.pop()->scan.scan, 3u);
}

TEST(ScanQueue, DropNewestRefusesTheNewScan) {
  ScanQueue queue(2, OverloadPolicy::kDropNewest);
  queue.push(scan_number(1));
  queue.push(scan_number(2));
  const auto dropped = queue.push(scan_number(3));
  ASSERT_TRUE(dropped);
  EXPECT_EQ(dropped->scan.scan, 3u);
  EXPECT_EQ(queue.pop()->scan.scan, 1u);
  EXPECT_EQ(queue.pop()->scan.scan, 2u);
  EXPECT_EQ(queue.size(), 0u);
}

TEST(ScanQueue, CloseWakesAWaitingPopAndRefusesPushes) {
  ScanQueue queue(2, OverloadPolicy::kDropOldest);
  std::thread closer([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    queue.close();
  });
  EXPECT_FALSE(queue.pop());  // returns only because close() woke it
  closer.join();
  EXPECT_TRUE(queue.push(scan_number(1)));  // handed back: refused
  EXPECT_EQ(queue.size(), 0u);
}

TEST(ScanQueue, PopForTimesOutOnAnEmptyQueue) {
  ScanQueue queue(2, OverloadPolicy::kDropOldest);
  EXPECT_FALSE(queue.pop_for(std::chrono::milliseconds(5)));
  queue.push(scan_number(7));
  EXPECT_EQ(queue.pop_for(std::chrono::milliseconds(5))->scan.scan, 7u);
}

TEST(ScanQueue, ClearDiscardsWaitingScans) {
  ScanQueue queue(8, OverloadPolicy::kDropOldest);
  for (std::uint64_t n = 0; n < 5; ++n) queue.push(scan_number(n));
  EXPECT_EQ(queue.clear(), 5u);
  EXPECT_EQ(queue.size(), 0u);
}

TEST(ScanQueue, ProducerAndConsumerThreadsLoseNothingButPolicyDrops) {
  // GIVEN a producer faster than the consumer on a small queue
  ScanQueue queue(4, OverloadPolicy::kDropOldest);
  constexpr std::uint64_t kScans = 20000;
  std::atomic<std::uint64_t> dropped{0};
  std::thread producer([&] {
    for (std::uint64_t n = 1; n <= kScans; ++n) {
      if (queue.push(scan_number(n))) ++dropped;
    }
    queue.close();
  });
  // WHEN the consumer takes what it can
  std::uint64_t received = 0, last = 0;
  bool ordered = true;
  while (auto item = queue.pop()) {
    ordered = ordered && item->scan.scan > last;
    last = item->scan.scan;
    ++received;
  }
  producer.join();
  received += queue.clear();  // left behind by close()
  // THEN every scan was either delivered (in order) or counted as dropped
  EXPECT_TRUE(ordered);
  EXPECT_EQ(received + dropped.load(), kScans);
}

}  // namespace
}  // namespace skytrack::daemon
