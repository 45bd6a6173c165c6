// The C examples of docs/c-clients.md against a running skytrackd: the publisher's PlotBatch
// samples are tracked, and the subscriber prints the TrackBatch samples that come back.
#include <filesystem>
#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "process_helpers.hpp"

namespace skytrack::test {
namespace {

using namespace std::chrono_literals;
using ::testing::HasSubstr;

TEST(CClients, PublisherAndSubscriberTalkToSkytrackd) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("skytrack_c_clients_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const auto path = [&](const std::string& name) { return (dir / name).string(); };
  const int domain = 232;  // no other test uses it
  std::ofstream(path("skytrackd.yaml"))
      << "skytrackd: {instance: c_clients, status_period: 0.2}\n"
      << "dds: {domain: " << domain << ", qos: {status: {deadline: 1.0}}}\n";
  // GIVEN skytrackd and the C subscriber
  Child daemon({SKYTRACKD, "--config", path("skytrackd.yaml")}, path("daemon.log"));
  ASSERT_TRUE(daemon.wait_for_log("running", 10s)) << daemon.log();
  Child subscriber({TRACK_SUBSCRIBER, std::to_string(domain), "20", "5"}, path("sub.log"));
  ASSERT_TRUE(subscriber.wait_for_log("waiting on domain", 10s)) << subscriber.log();
  // WHEN the C publisher sends 20 batches of one aircraft
  ASSERT_EQ(run({PLOT_PUBLISHER, std::to_string(domain), "20"}, path("pub.log"), 30s), 0)
      << read_file(path("pub.log"));
  // THEN the subscriber receives the 20 TrackBatch samples, with a confirmed track
  ASSERT_EQ(subscriber.wait(30s), 0) << subscriber.log();
  daemon.signal(SIGTERM);
  ASSERT_EQ(daemon.wait(5s), 0) << daemon.log();
  EXPECT_THAT(subscriber.log(), HasSubstr("20 batches received"));
  EXPECT_THAT(subscriber.log(), HasSubstr("scan 19 t=19.0: 0 tentative, 1 confirmed"));
  if (!HasFailure()) std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace skytrack::test
