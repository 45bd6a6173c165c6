#pragma once
// skytrackd's live ASTERIX input: a UDP socket (unicast, or a multicast group joined on a
// configured local address; loopback by default), read by its own thread, each datagram
// decoded and batched as `skytrack import-asterix` does, each closed batch handed on (to the
// same queue and Pipeline as DDS PlotBatch samples). Decoding errors and dropped reports go to
// a callback with the datagram number; when no datagram has come for `flush_after` the open
// batches are closed, so a radar that stops still gets its last batch tracked.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "skytrack/asterix/records.hpp"
#include "skytrack/core/expected.hpp"
#include "skytrack/core/plot.hpp"
#include "skytrack/daemon/daemon_config.hpp"

namespace skytrack::daemon {

class UdpInput {
 public:
  using ScanHandler = std::function<void(PlotScan&& scan)>;
  using ErrorHandler = std::function<void(const asterix::DecodeError& error)>;
  /// A report the decoder dropped (by reason), `count` of them.
  using DropHandler = std::function<void(asterix::DropReason reason, std::uint64_t count)>;

  /// Opens and binds the socket (and joins the group); nothing is read yet.
  static Expected<std::unique_ptr<UdpInput>> open(const AsterixInput& settings);
  ~UdpInput();
  UdpInput(const UdpInput&) = delete;
  UdpInput& operator=(const UdpInput&) = delete;

  /// "127.0.0.1:8600" (the port actually bound when 0 was configured), or the group.
  const std::string& endpoint() const;

  void start(ScanHandler on_scan, ErrorHandler on_error, DropHandler on_drop);
  /// Wakes and joins the thread. Open batches are not closed (the queue is closing).
  void stop();

  std::uint64_t datagrams() const;

 private:
  struct Impl;
  explicit UdpInput(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace skytrack::daemon
