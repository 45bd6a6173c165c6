// The file is mapped read-only; captures are walked frame by frame, raw files block by block.
// A raw file has no framing beyond each block's LEN, so after a bad LEN the reader looks for the
// next place where two consecutive plausible block headers line up, and counts what it skipped.
#include "skytrack/asterix/capture.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstring>

#include "capture_formats.hpp"
#include "link_layer.hpp"

namespace skytrack::asterix {

using namespace detail;

std::string_view to_string(CaptureFormat format) {
  switch (format) {
    case CaptureFormat::kPcap:
      return "pcap";
    case CaptureFormat::kPcapNg:
      return "pcapng";
    case CaptureFormat::kRaw:
      break;
  }
  return "raw ASTERIX";
}

Expected<CaptureFilter> parse_capture_filter(const std::string& port, const std::string& source) {
  CaptureFilter filter;
  const auto parse_port = [](const std::string& text) -> std::optional<std::uint16_t> {
    if (text.empty() || text.size() > 5 ||
        text.find_first_not_of("0123456789") != std::string::npos) {
      return std::nullopt;
    }
    const unsigned long v = std::stoul(text);
    if (v == 0 || v > 65535) return std::nullopt;
    return static_cast<std::uint16_t>(v);
  };
  if (!port.empty()) {
    filter.port = parse_port(port);
    if (!filter.port) return make_error("--port: expected a UDP port 1..65535, got '" + port + "'");
  }
  if (!source.empty()) {
    std::string address = source;
    // "a.b.c.d:port" or "[v6]:port"; a bare IPv6 address has several colons.
    const auto colon = source.rfind(':');
    if (colon != std::string::npos && source.find(':') == colon) {
      address = source.substr(0, colon);
      filter.source_port = parse_port(source.substr(colon + 1));
      if (!filter.source_port) return make_error("--source: bad port in '" + source + "'");
    } else if (source.front() == '[' && colon != std::string::npos && source[colon - 1] == ']') {
      address = source.substr(1, colon - 2);
      filter.source_port = parse_port(source.substr(colon + 1));
      if (!filter.source_port) return make_error("--source: bad port in '" + source + "'");
    }
    unsigned char probe[16];
    if (inet_pton(AF_INET, address.c_str(), probe) != 1 &&
        inet_pton(AF_INET6, address.c_str(), probe) != 1) {
      return make_error("--source: expected an IP address (and :port), got '" + source + "'");
    }
    filter.source = address;
  }
  return filter;
}

struct CaptureReader::Impl {
  CaptureFilter filter;
  CaptureProblemSink on_problem;
  std::span<const std::uint8_t> file;
  void* mapping = nullptr;
  std::size_t mapped = 0;
  CaptureFormat format = CaptureFormat::kRaw;
  PcapCursor pcap;
  PcapNgCursor pcapng;
  std::size_t pos = 0;  // raw files
  CaptureCounts counts;
  std::array<std::uint8_t, 16> source{};
  std::uint8_t source_length = 0;

  ~Impl() {
    if (mapping != nullptr) munmap(mapping, mapped);
  }
  void problem(std::uint64_t offset, std::string message) {
    ++counts.damaged;
    if (on_problem) on_problem(CaptureProblem{offset, std::move(message)});
  }
  void setup() {
    if (pcap.start(file)) {
      format = CaptureFormat::kPcap;
    } else if (pcapng.start(file)) {
      format = CaptureFormat::kPcapNg;
    }
    if (filter.source) {
      if (inet_pton(AF_INET, filter.source->c_str(), source.data()) == 1) {
        source_length = 4;
      } else if (inet_pton(AF_INET6, filter.source->c_str(), source.data()) == 1) {
        source_length = 16;
      }
    }
  }
  bool plausible_block(std::size_t at) const {
    if (at + 3 > file.size()) return false;
    const std::size_t length = static_cast<std::size_t>(file[at + 1]) << 8 | file[at + 2];
    return length >= 4 && at + length <= file.size();
  }
  std::optional<Datagram> next_raw();
  std::optional<Datagram> next_captured();
  bool passes(const UdpView& udp) const {
    if (filter.port && udp.destination_port != *filter.port) return false;
    if (filter.source_port && udp.source_port != *filter.source_port) return false;
    if (filter.source && (udp.source_length != source_length ||
                          std::memcmp(udp.source.data(), source.data(), source_length) != 0)) {
      return false;
    }
    return true;
  }
};

std::optional<Datagram> CaptureReader::Impl::next_raw() {
  if (pos >= file.size()) return std::nullopt;
  if (!plausible_block(pos)) {
    // Resynchronise: the next offset where a block header fits and is followed by another
    // (or by the end of the file).
    const std::size_t bad = pos;
    std::size_t at = pos + 1;
    for (; at < file.size(); ++at) {
      if (!plausible_block(at)) continue;
      const std::size_t after = at + (static_cast<std::size_t>(file[at + 1]) << 8 | file[at + 2]);
      if (after == file.size() || plausible_block(after)) break;
    }
    counts.skipped_bytes += at - bad;
    problem(bad, "no valid data block header (bad LEN or cut short); " + std::to_string(at - bad) +
                     " bytes skipped");
    pos = at;
    if (pos >= file.size()) return std::nullopt;
  }
  const std::size_t length = static_cast<std::size_t>(file[pos + 1]) << 8 | file[pos + 2];
  Datagram d{file.subspan(pos, length), Origin{pos, 0}, std::nullopt};
  pos += length;
  ++counts.frames;
  ++counts.datagrams;
  return d;
}

std::optional<Datagram> CaptureReader::Impl::next_captured() {
  Frame frame;
  std::string message;
  for (;;) {
    const std::size_t at = format == CaptureFormat::kPcap ? pcap.position() : pcapng.position();
    const FrameStatus status =
        format == CaptureFormat::kPcap ? pcap.next(frame, message) : pcapng.next(frame, message);
    if (status == FrameStatus::kEnd) return std::nullopt;
    if (status == FrameStatus::kDamaged) {
      problem(at, message);
      continue;  // the cursor has moved on (to the end, when nothing more can be found)
    }
    ++counts.frames;
    UdpView udp;
    const FrameKind kind = extract_udp(frame.link_type, frame.data, udp);
    if (kind == FrameKind::kNotUdp) {
      ++counts.not_udp;
      continue;
    }
    if (kind == FrameKind::kDamaged) {
      problem(frame.offset, "frame " + std::to_string(counts.frames) +
                                ": IP or UDP header cut short or inconsistent");
      continue;
    }
    if (!passes(udp)) {
      ++counts.filtered;
      continue;
    }
    ++counts.datagrams;
    return Datagram{udp.payload, Origin{frame.offset + udp.payload_offset, counts.frames},
                    frame.time};
  }
}

CaptureReader::CaptureReader(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
CaptureReader::~CaptureReader() = default;
CaptureReader::CaptureReader(CaptureReader&&) noexcept = default;
CaptureReader& CaptureReader::operator=(CaptureReader&&) noexcept = default;

Expected<CaptureReader> CaptureReader::open(const std::string& path, CaptureFilter filter,
                                            CaptureProblemSink on_problem) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return make_error(path + ": cannot open: " + std::strerror(errno));
  struct stat st {};
  if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    return make_error(path + ": not a regular file");
  }
  auto impl = std::make_unique<Impl>();
  impl->filter = std::move(filter);
  impl->on_problem = std::move(on_problem);
  if (st.st_size > 0) {
    impl->mapped = static_cast<std::size_t>(st.st_size);
    impl->mapping = mmap(nullptr, impl->mapped, PROT_READ, MAP_PRIVATE, fd, 0);
    if (impl->mapping == MAP_FAILED) {
      impl->mapping = nullptr;
      ::close(fd);
      return make_error(path + ": cannot map: " + std::strerror(errno));
    }
    madvise(impl->mapping, impl->mapped, MADV_SEQUENTIAL);
    impl->file = {static_cast<const std::uint8_t*>(impl->mapping), impl->mapped};
  }
  ::close(fd);
  impl->setup();
  return CaptureReader(std::move(impl));
}

CaptureReader CaptureReader::from_memory(std::span<const std::uint8_t> bytes, CaptureFilter filter,
                                         CaptureProblemSink on_problem) {
  auto impl = std::make_unique<Impl>();
  impl->filter = std::move(filter);
  impl->on_problem = std::move(on_problem);
  impl->file = bytes;
  impl->setup();
  return CaptureReader(std::move(impl));
}

std::optional<Datagram> CaptureReader::next() {
  return impl_->format == CaptureFormat::kRaw ? impl_->next_raw() : impl_->next_captured();
}
CaptureFormat CaptureReader::format() const {
  return impl_->format;
}
const CaptureCounts& CaptureReader::counts() const {
  return impl_->counts;
}
std::size_t CaptureReader::bytes_read() const {
  switch (impl_->format) {
    case CaptureFormat::kPcap:
      return impl_->pcap.position();
    case CaptureFormat::kPcapNg:
      return impl_->pcapng.position();
    case CaptureFormat::kRaw:
      break;
  }
  return impl_->pos;
}
std::size_t CaptureReader::file_size() const {
  return impl_->file.size();
}

}  // namespace skytrack::asterix
