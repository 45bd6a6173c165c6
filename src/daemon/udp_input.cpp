#include "skytrack/daemon/udp_input.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <thread>
#include <vector>

#include "skytrack/asterix/feed.hpp"

namespace skytrack::daemon {
namespace {

std::string errno_text(const char* what) {
  return std::string(what) + ": " + std::strerror(errno);
}

}  // namespace

struct UdpInput::Impl {
  AsterixInput settings;
  asterix::FeedOptions feed_options;
  int socket = -1;
  std::array<int, 2> wake{-1, -1};  // stop(): a byte on the pipe
  std::string endpoint;
  std::optional<in_addr> source;
  std::thread thread;
  std::atomic<std::uint64_t> datagrams{0};

  ~Impl() {
    for (const int fd : {socket, wake[0], wake[1]}) {
      if (fd >= 0) ::close(fd);
    }
  }
  void run(ScanHandler on_scan, ErrorHandler on_error, DropHandler on_drop);
};

void UdpInput::Impl::run(ScanHandler on_scan, ErrorHandler on_error, DropHandler on_drop) {
  asterix::Feed feed(feed_options, std::move(on_scan), std::move(on_error));
  std::array<std::uint64_t, static_cast<std::size_t>(asterix::DropReason::kCount)> dropped{};
  std::vector<std::uint8_t> buffer(65536);
  bool unflushed = false;
  const int idle_ms = static_cast<int>(settings.flush_after * 1000.0);
  for (;;) {
    std::array<pollfd, 2> fds{{{socket, POLLIN, 0}, {wake[0], POLLIN, 0}}};
    const int n = ::poll(fds.data(), fds.size(), unflushed ? idle_ms : -1);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 || (fds[1].revents & POLLIN) != 0) return;
    if (n == 0) {  // quiet for flush_after: the radar stopped, or paused
      feed.finish();
      unflushed = false;
      continue;
    }
    for (;;) {
      sockaddr_in from{};
      socklen_t from_length = sizeof from;
      const ssize_t got = ::recvfrom(socket, buffer.data(), buffer.size(), MSG_DONTWAIT,
                                     reinterpret_cast<sockaddr*>(&from), &from_length);
      if (got < 0) break;  // EAGAIN: all read
      if (source && from.sin_addr.s_addr != source->s_addr) continue;
      const std::uint64_t number = ++datagrams;
      const double now =
          std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch())
              .count();
      feed.feed({std::span<const std::uint8_t>(buffer.data(), static_cast<std::size_t>(got)),
                 asterix::Origin{0, number}, now});
      unflushed = true;
      const auto& counts = feed.decoder().counters().dropped;
      for (std::size_t i = 0; i < counts.size(); ++i) {
        if (counts[i] != dropped[i]) {
          on_drop(static_cast<asterix::DropReason>(i), counts[i] - dropped[i]);
          dropped[i] = counts[i];
        }
      }
    }
  }
}

UdpInput::UdpInput(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
UdpInput::~UdpInput() {
  stop();
}
const std::string& UdpInput::endpoint() const {
  return impl_->endpoint;
}
std::uint64_t UdpInput::datagrams() const {
  return impl_->datagrams.load();
}

Expected<std::unique_ptr<UdpInput>> UdpInput::open(const AsterixInput& settings) {
  auto impl = std::make_unique<Impl>();
  impl->settings = settings;
  auto batch = asterix::parse_batch_mode(settings.batch);
  if (!batch) return unexpected(batch.error());
  impl->feed_options.batch = *batch;
  impl->feed_options.decoder.keep_tests = settings.keep_tests;
  if (!settings.sensor.empty())
    impl->feed_options.decoder.sensor = asterix::parse_sac_sic(settings.sensor);
  in_addr address{}, interface {};
  if (inet_pton(AF_INET, settings.address.c_str(), &address) != 1 ||
      inet_pton(AF_INET, settings.interface.c_str(), &interface) != 1) {
    return make_error("input.asterix: address and interface must be IPv4 addresses");
  }
  if (!settings.source.empty()) {
    in_addr source{};
    if (inet_pton(AF_INET, settings.source.c_str(), &source) != 1) {
      return make_error("input.asterix.source: expected an IPv4 address");
    }
    impl->source = source;
  }
  impl->socket = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (impl->socket < 0 || ::pipe2(impl->wake.data(), O_CLOEXEC) != 0) {
    return make_error(errno_text("input.asterix: socket"));
  }
  const int one = 1, buffer = settings.receive_buffer_kb * 1024;
  ::setsockopt(impl->socket, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  ::setsockopt(impl->socket, SOL_SOCKET, SO_RCVBUF, &buffer, sizeof buffer);
  const bool multicast = IN_MULTICAST(ntohl(address.s_addr));
  sockaddr_in bind_to{};
  bind_to.sin_family = AF_INET;
  bind_to.sin_port = htons(static_cast<std::uint16_t>(settings.port));
  bind_to.sin_addr = address;  // a group address: only that group's datagrams
  if (::bind(impl->socket, reinterpret_cast<const sockaddr*>(&bind_to), sizeof bind_to) != 0) {
    return make_error(errno_text(
        ("input.asterix: bind " + settings.address + ":" + std::to_string(settings.port)).c_str()));
  }
  if (multicast) {
    ip_mreq join{};
    join.imr_multiaddr = address;
    join.imr_interface = interface;  // loopback unless configured otherwise
    if (::setsockopt(impl->socket, IPPROTO_IP, IP_ADD_MEMBERSHIP, &join, sizeof join) != 0) {
      return make_error(errno_text(
          ("input.asterix: joining " + settings.address + " on " + settings.interface).c_str()));
    }
  }
  sockaddr_in bound{};
  socklen_t length = sizeof bound;
  ::getsockname(impl->socket, reinterpret_cast<sockaddr*>(&bound), &length);
  impl->endpoint = settings.address + ":" + std::to_string(ntohs(bound.sin_port)) +
                   (multicast ? " (multicast, joined on " + settings.interface + ")" : "");
  return std::unique_ptr<UdpInput>(new UdpInput(std::move(impl)));
}

void UdpInput::start(ScanHandler on_scan, ErrorHandler on_error, DropHandler on_drop) {
  if (impl_->thread.joinable()) return;
  impl_->thread = std::thread(
      [this, s = std::move(on_scan), e = std::move(on_error), d = std::move(on_drop)]() mutable {
        impl_->run(std::move(s), std::move(e), std::move(d));
      });
}

void UdpInput::stop() {
  if (!impl_ || !impl_->thread.joinable()) return;
  const char byte = 1;
  [[maybe_unused]] const ssize_t n = ::write(impl_->wake[1], &byte, 1);
  impl_->thread.join();
}

}  // namespace skytrack::daemon
