// skytrackd's ASTERIX input: the `input` configuration section, the UDP input on loopback, and
// end to end a capture streamed into the daemon over UDP (127.0.0.1 only) giving the tracks of
// `skytrack import-asterix` + `skytrack track` on the same capture.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>

#include <filesystem>
#include <fstream>
#include <mutex>
#include <regex>
#include <thread>

#include <gtest/gtest.h>

#include "process_helpers.hpp"
#include "skytrack/asterix/capture.hpp"
#include "skytrack/daemon/daemon_config.hpp"
#include "skytrack/daemon/udp_input.hpp"
#include "skytrack/io/jsonl_reader.hpp"

namespace skytrack::test {
namespace {

using namespace std::chrono_literals;

const std::string kSource = SKYTRACK_SOURCE_DIR;
const std::string kTool = SKYTRACK_TOOL;
const std::string kDaemon = SKYTRACKD;
const std::string kBds30 = kSource + "/../shared/realdata/asterix/bds30_cat048_cat034.pcap";

TEST(InputConfig, DefaultsToDdsAndALoopbackAddress) {
  auto c = daemon::parse_daemon_config("{}", "t.yaml", "/tmp");
  ASSERT_TRUE(c);
  EXPECT_EQ(c->input.mode, daemon::InputMode::kDds);
  EXPECT_EQ(c->input.asterix.address, "127.0.0.1");
  EXPECT_EQ(c->input.asterix.interface, "127.0.0.1");
}

TEST(InputConfig, ReadsTheAsterixSection) {
  auto c = daemon::parse_daemon_config(
      "input: {from: both, asterix: {address: 239.1.2.3, port: 8600, interface: 127.0.0.1, "
      "source: 127.0.0.2, batch: 'block:20', sensor: 20/130, keep_tests: true, flush_after: "
      "2.5}}",
      "t.yaml", "/tmp");
  ASSERT_TRUE(c) << c.error().message;
  EXPECT_EQ(c->input.mode, daemon::InputMode::kBoth);
  EXPECT_EQ(c->input.asterix.address, "239.1.2.3");
  EXPECT_EQ(c->input.asterix.batch, "block:20");
  EXPECT_EQ(c->input.asterix.sensor, "20/130");
  EXPECT_TRUE(c->input.asterix.keep_tests);
  EXPECT_DOUBLE_EQ(c->input.asterix.flush_after, 2.5);
}

TEST(InputConfig, NamesEveryMistake) {
  auto c = daemon::parse_daemon_config(
      "input: {from: radar, asterix: {address: 'not an address', port: 70000, batch: scans, "
      "sensor: 300/1, colour: red}}",
      "t.yaml", "/tmp");
  ASSERT_FALSE(c);
  for (const char* key : {"input.from", "input.asterix.address", "input.asterix.port",
                          "input.asterix.batch", "input.asterix.sensor", "input.asterix.colour"}) {
    EXPECT_NE(c.error().message.find(key), std::string::npos) << key << "\n" << c.error().message;
  }
}

/// Sends datagrams to 127.0.0.1:`port` from a loopback socket.
class LoopbackSender {
 public:
  explicit LoopbackSender(int port) : socket_(::socket(AF_INET, SOCK_DGRAM, 0)) {
    to_.sin_family = AF_INET;
    to_.sin_port = htons(static_cast<std::uint16_t>(port));
    to_.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  }
  ~LoopbackSender() { ::close(socket_); }
  bool send(std::span<const std::uint8_t> payload) const {
    return ::sendto(socket_, payload.data(), payload.size(), 0,
                    reinterpret_cast<const sockaddr*>(&to_),
                    sizeof to_) == static_cast<ssize_t>(payload.size());
  }

 private:
  int socket_;
  sockaddr_in to_{};
};

int port_of(const std::string& endpoint) {
  std::smatch m;
  return std::regex_search(endpoint, m, std::regex(":([0-9]+)")) ? std::stoi(m[1]) : 0;
}

TEST(UdpInput, DecodesAndBatchesDatagramsOnLoopback) {
  // GIVEN a UDP input on a free loopback port, batching every 2 plots
  daemon::AsterixInput settings;
  settings.port = 0;
  settings.batch = "block:2";
  settings.flush_after = 0.2;
  auto input = daemon::UdpInput::open(settings);
  ASSERT_TRUE(input) << input.error().message;
  std::mutex mutex;
  std::vector<PlotScan> scans;
  std::vector<std::string> errors;
  (*input)->start(
      [&](PlotScan&& s) {
        std::lock_guard lock(mutex);
        scans.push_back(std::move(s));
      },
      [&](const asterix::DecodeError& e) {
        std::lock_guard lock(mutex);
        errors.push_back(asterix::to_string(e));
      },
      [](asterix::DropReason, std::uint64_t) {});
  // WHEN three CAT048 plots and a truncated block arrive
  // CAT048: 010 (20/4), 140 (512 s), 020 (SSR), 040 (16 NM, 90 deg).
  const std::vector<std::uint8_t> plot{48,   0, 14,   0xF0, 20,   4,    0x01,
                                       0x00, 0, 0x20, 0x10, 0x00, 0x40, 0x00};
  LoopbackSender sender(port_of((*input)->endpoint()));
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(sender.send(plot));
  ASSERT_TRUE(sender.send(std::span(plot).first(10)));
  // THEN a batch of two comes at once, the third plot after flush_after, and the error names
  // its datagram
  const auto deadline = std::chrono::steady_clock::now() + 5s;
  for (;;) {
    {
      std::lock_guard lock(mutex);
      if (scans.size() >= 2 || std::chrono::steady_clock::now() > deadline) break;
    }
    std::this_thread::sleep_for(10ms);
  }
  (*input)->stop();
  ASSERT_EQ(scans.size(), 2u);
  EXPECT_EQ(scans[0].plots.size(), 2u);
  EXPECT_EQ(scans[1].plots.size(), 1u);
  EXPECT_EQ(scans[0].sensor, 20u * 256u + 4u);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].find("datagram 4"), std::string::npos) << errors[0];
  EXPECT_EQ((*input)->datagrams(), 4u);
}

TEST(UdpInput, JoinsAMulticastGroupOnLoopback) {
  // GIVEN an input on a multicast group joined on 127.0.0.1 (the default interface)
  daemon::AsterixInput settings;
  settings.address = "239.255.86.1";
  settings.port = 0;
  settings.batch = "block:1";
  auto input = daemon::UdpInput::open(settings);
  if (!input) GTEST_SKIP() << "no multicast on loopback here: " << input.error().message;
  std::mutex mutex;
  std::size_t scans = 0;
  (*input)->start(
      [&](PlotScan&&) {
        std::lock_guard lock(mutex);
        ++scans;
      },
      [](const asterix::DecodeError&) {}, [](asterix::DropReason, std::uint64_t) {});
  // WHEN a plot is sent to the group through the loopback interface only (TTL 0: it cannot
  // leave this machine)
  const int sender = ::socket(AF_INET, SOCK_DGRAM, 0);
  in_addr loopback{};
  loopback.s_addr = htonl(INADDR_LOOPBACK);
  const int ttl = 0;
  ASSERT_EQ(::setsockopt(sender, IPPROTO_IP, IP_MULTICAST_IF, &loopback, sizeof loopback), 0);
  ASSERT_EQ(::setsockopt(sender, IPPROTO_IP, IP_MULTICAST_TTL, &ttl, sizeof ttl), 0);
  sockaddr_in to{};
  to.sin_family = AF_INET;
  to.sin_port = htons(static_cast<std::uint16_t>(port_of((*input)->endpoint())));
  inet_pton(AF_INET, settings.address.c_str(), &to.sin_addr);
  const std::vector<std::uint8_t> plot{48,   0, 14,   0xF0, 20,   4,    0x01,
                                       0x00, 0, 0x20, 0x10, 0x00, 0x40, 0x00};
  ASSERT_EQ(::sendto(sender, plot.data(), plot.size(), 0, reinterpret_cast<const sockaddr*>(&to),
                     sizeof to),
            static_cast<ssize_t>(plot.size()));
  ::close(sender);
  // THEN it is decoded and batched
  const auto deadline = std::chrono::steady_clock::now() + 5s;
  for (;;) {
    {
      std::lock_guard lock(mutex);
      if (scans > 0 || std::chrono::steady_clock::now() > deadline) break;
    }
    std::this_thread::sleep_for(10ms);
  }
  (*input)->stop();
  EXPECT_EQ(scans, 1u);
  EXPECT_NE((*input)->endpoint().find("multicast, joined on 127.0.0.1"), std::string::npos);
}

std::vector<TrackFrame> read_tracks(const std::string& file) {
  std::vector<TrackFrame> frames;
  auto reader = io::TrackReader::open(file);
  if (!reader) return frames;
  while (auto frame = reader->next()) frames.push_back(std::move(*frame));
  return frames;
}

/// Same scans, track numbers, statuses and events; positions equal to 1e-9.
void expect_same_tracks(const std::vector<TrackFrame>& live,
                        const std::vector<TrackFrame>& offline) {
  ASSERT_EQ(live.size(), offline.size());
  std::size_t tracks = 0;
  for (std::size_t i = 0; i < live.size(); ++i) {
    ASSERT_EQ(live[i].scan, offline[i].scan);
    EXPECT_EQ(live[i].time, offline[i].time);
    ASSERT_EQ(live[i].tracks.size(), offline[i].tracks.size()) << "scan " << live[i].scan;
    for (std::size_t t = 0; t < live[i].tracks.size(); ++t, ++tracks) {
      EXPECT_EQ(live[i].tracks[t].id, offline[i].tracks[t].id);
      EXPECT_EQ(live[i].tracks[t].status, offline[i].tracks[t].status);
      EXPECT_LE((live[i].tracks[t].position - offline[i].tracks[t].position).cwiseAbs().maxCoeff(),
                1e-9);
    }
    EXPECT_EQ(live[i].events, offline[i].events);
  }
  EXPECT_GT(tracks, 0u) << "nothing was tracked: the comparison would prove nothing";
}

TEST(AsterixEndToEnd, CaptureStreamedOverUdpGivesTheOfflineTracks) {
  // The whole bds30 capture where the recordings are, else its committed excerpt (so the
  // test runs everywhere, CI included).
  const std::string capture =
      std::filesystem::exists(kBds30) ? kBds30 : kSource + "/tests/data/asterix/bds30_excerpt.pcap";
  const auto dir =
      std::filesystem::temp_directory_path() / ("skytrack_asterix_e2e_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto path = [&](const std::string& name) { return (dir / name).string(); };
  const std::string profile = kSource + "/config/profiles/default.yaml";
  // GIVEN the capture imported and tracked offline
  ASSERT_EQ(run({kTool, "import-asterix", capture, "--plots", path("plots.jsonl"), "--quiet"},
                path("import.log")),
            0)
      << read_file(path("import.log"));
  ASSERT_EQ(run({kTool, "track", "--profile", profile, "--plots", path("plots.jsonl"), "--out",
                 path("offline.tracks.jsonl"), "--quiet"},
                path("track.log")),
            0)
      << read_file(path("track.log"));
  std::size_t plots = 0;
  auto imported = io::PlotStreamReader::open(path("plots.jsonl"));
  ASSERT_TRUE(imported);
  while (auto scan = imported->next()) plots += scan->plots.size();
  ASSERT_GT(plots, 0u);
  // AND skytrackd reading ASTERIX on a free loopback port (no DDS plot input)
  const int domain = 220 + static_cast<int>(getpid() % 6);  // apart from the other tests
  std::ofstream(path("skytrackd.yaml"))
      << "skytrackd: {instance: asterix, profile: " << profile << ", status_period: 0.2}\n"
      << "input: {from: asterix, asterix: {port: 0, flush_after: 0.5}}\n"
      << "dds: {domain: " << domain << ", qos: {status: {deadline: 1.0}}}\n"
      << "queue: {capacity: 4096}\n";
  Child daemon({kDaemon, "--config", path("skytrackd.yaml")}, path("daemon.log"));
  ASSERT_TRUE(daemon.wait_for_log("running", 10s)) << daemon.log();
  const int port = port_of(daemon.log().substr(daemon.log().find("ASTERIX input on UDP")));
  ASSERT_GT(port, 0) << daemon.log();
  Child record({kTool, "record", "--config", path("skytrackd.yaml"), "--tracks",
                path("live.tracks.jsonl"), "--until-idle", "2.0"},
               path("record.log"));
  ASSERT_TRUE(record.wait_for_log("matched a TrackBatch writer", 10s)) << record.log();

  // WHEN the capture's datagrams are sent to it over UDP on loopback, paced
  auto reader = asterix::CaptureReader::open(capture);
  ASSERT_TRUE(reader);
  LoopbackSender sender(port);
  std::size_t sent = 0;
  while (auto d = reader->next()) {
    ASSERT_TRUE(sender.send(d->payload));
    if (++sent % 8 == 0) std::this_thread::sleep_for(1ms);
  }
  ASSERT_EQ(record.wait(60s), 0) << record.log();
  ASSERT_EQ(run({kTool, "status", "--config", path("skytrackd.yaml")}, path("status.log")), 0)
      << read_file(path("status.log"));
  daemon.signal(SIGTERM);
  ASSERT_EQ(daemon.wait(5s), 0) << daemon.log();

  // THEN the live tracks are the offline ones, batch for batch
  expect_same_tracks(read_tracks(path("live.tracks.jsonl")),
                     read_tracks(path("offline.tracks.jsonl")));
  EXPECT_NE(read_file(path("status.log")).find("\"plots_processed\": " + std::to_string(plots)),
            std::string::npos)
      << read_file(path("status.log"));
  if (!HasFailure()) std::filesystem::remove_all(dir);
}

TEST(AsterixEndToEnd, ReplayOfARecordingGivesTheOfflineTracks) {
  // GIVEN the committed bds30 excerpt imported and tracked offline
  const std::string capture = kSource + "/tests/data/asterix/bds30_excerpt.pcap";
  const auto dir = std::filesystem::temp_directory_path() /
                   ("skytrack_asterix_replay_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto path = [&](const std::string& name) { return (dir / name).string(); };
  const std::string profile = kSource + "/config/profiles/default.yaml";
  ASSERT_EQ(run({kTool, "import-asterix", capture, "--plots", path("plots.jsonl"), "--quiet"},
                path("import.log")),
            0)
      << read_file(path("import.log"));
  ASSERT_EQ(run({kTool, "track", "--profile", profile, "--plots", path("plots.jsonl"), "--out",
                 path("offline.tracks.jsonl"), "--quiet"},
                path("track.log")),
            0);
  // WHEN `replay --asterix` publishes the recording to skytrackd over DDS
  const int domain = 226 + static_cast<int>(getpid() % 6);
  std::ofstream(path("skytrackd.yaml"))
      << "skytrackd: {instance: replay, profile: " << profile << ", status_period: 0.2}\n"
      << "dds: {domain: " << domain << ", qos: {status: {deadline: 1.0}}}\n";
  Child daemon({kDaemon, "--config", path("skytrackd.yaml")}, path("daemon.log"));
  ASSERT_TRUE(daemon.wait_for_log("running", 10s)) << daemon.log();
  Child record({kTool, "record", "--config", path("skytrackd.yaml"), "--tracks",
                path("live.tracks.jsonl"), "--until-idle", "1.5"},
               path("record.log"));
  ASSERT_TRUE(record.wait_for_log("matched a TrackBatch writer", 10s)) << record.log();
  ASSERT_EQ(run({kTool, "replay", "--config", path("skytrackd.yaml"), "--asterix", capture,
                 "--rate", "max", "--quiet"},
                path("replay.log"), 60s),
            0)
      << read_file(path("replay.log"));
  ASSERT_EQ(record.wait(30s), 0) << record.log();
  daemon.signal(SIGTERM);
  ASSERT_EQ(daemon.wait(5s), 0) << daemon.log();
  // THEN the recorded tracks are the offline ones
  EXPECT_NE(read_file(path("replay.log")).find("30 scans (30 plots)"), std::string::npos)
      << read_file(path("replay.log"));
  expect_same_tracks(read_tracks(path("live.tracks.jsonl")),
                     read_tracks(path("offline.tracks.jsonl")));
  if (!HasFailure()) std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace skytrack::test
