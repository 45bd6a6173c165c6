#pragma once
// Recordings of ASTERIX: raw concatenated data blocks (.ast), and pcap / pcapng captures of UDP
// datagrams over Ethernet (with 802.1Q / 802.1ad VLAN tags), Linux cooked (SLL, SLL2), BSD
// loopback or raw IP link types, IPv4 or IPv6. The file is mapped, not read into memory.
// Frames that are not UDP, fragments and frames the filter rejects are counted and skipped; a
// damaged capture is reported with the byte offset and read up to the damage.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "skytrack/asterix/records.hpp"
#include "skytrack/core/expected.hpp"

namespace skytrack::asterix {

enum class CaptureFormat : std::uint8_t { kRaw, kPcap, kPcapNg };
std::string_view to_string(CaptureFormat format);

/// Which datagrams to keep: to a destination port, from a source address (and port).
struct CaptureFilter {
  std::optional<std::uint16_t> port;         // UDP destination port
  std::optional<std::string> source;         // source IP address as text (IPv4 or IPv6)
  std::optional<std::uint16_t> source_port;  // UDP source port
};
/// "8600" -> port; "10.0.0.1" or "10.0.0.1:8600" -> source (and source port).
Expected<CaptureFilter> parse_capture_filter(const std::string& port, const std::string& source);

/// One UDP payload (capture) or one data block (raw file).
struct Datagram {
  std::span<const std::uint8_t> payload;
  Origin where;                          // file offset of payload[0]; datagram number
  std::optional<double> reception_time;  // [s] capture time stamp (seconds since the epoch)
};

struct CaptureCounts {
  std::uint64_t frames = 0;         // capture records (or raw blocks) read
  std::uint64_t datagrams = 0;      // given out
  std::uint64_t not_udp = 0;        // other link types, protocols or non-first fragments
  std::uint64_t filtered = 0;       // UDP, rejected by the filter
  std::uint64_t damaged = 0;        // frames or records cut short or inconsistent
  std::uint64_t skipped_bytes = 0;  // raw files: bytes skipped to find the next block
};

/// A problem in the container (not in the ASTERIX inside it).
struct CaptureProblem {
  std::uint64_t offset = 0;
  std::string message;
};
using CaptureProblemSink = std::function<void(const CaptureProblem&)>;

class CaptureReader {
 public:
  /// Opens and maps `path`; the format is told by its first bytes (pcap or pcapng magic,
  /// else raw blocks).
  static Expected<CaptureReader> open(const std::string& path, CaptureFilter filter = {},
                                      CaptureProblemSink on_problem = {});
  /// Reads from memory that outlives the reader (tests, fuzzing).
  static CaptureReader from_memory(std::span<const std::uint8_t> bytes, CaptureFilter filter = {},
                                   CaptureProblemSink on_problem = {});
  ~CaptureReader();
  CaptureReader(CaptureReader&&) noexcept;
  CaptureReader& operator=(CaptureReader&&) noexcept;
  CaptureReader(const CaptureReader&) = delete;
  CaptureReader& operator=(const CaptureReader&) = delete;

  /// The next datagram that passes the filter, or nullopt at the end (or at damage that
  /// cannot be read past).
  std::optional<Datagram> next();

  CaptureFormat format() const;
  const CaptureCounts& counts() const;
  std::size_t bytes_read() const;
  std::size_t file_size() const;

 private:
  struct Impl;
  explicit CaptureReader(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace skytrack::asterix
