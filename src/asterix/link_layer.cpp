#include "link_layer.hpp"

#include <cstring>

namespace skytrack::asterix::detail {
namespace {

constexpr std::uint16_t kEtherIpv4 = 0x0800, kEtherIpv6 = 0x86DD, kEtherVlan = 0x8100,
                        kEtherQinQ = 0x88A8;
constexpr std::uint8_t kProtoUdp = 17;

std::uint16_t be16(const std::uint8_t* p) {
  return static_cast<std::uint16_t>(p[0] << 8 | p[1]);
}

FrameKind udp(std::span<const std::uint8_t> frame, std::size_t at, std::size_t end, UdpView& out) {
  if (at + 8 > end) return FrameKind::kDamaged;
  const std::size_t length = be16(&frame[at + 4]);
  if (length < 8 || at + length > end) return FrameKind::kDamaged;
  out.source_port = be16(&frame[at]);
  out.destination_port = be16(&frame[at + 2]);
  out.payload_offset = at + 8;
  out.payload = frame.subspan(at + 8, length - 8);
  return FrameKind::kUdp;
}

FrameKind ipv4(std::span<const std::uint8_t> frame, std::size_t at, UdpView& out) {
  if (at + 20 > frame.size()) return FrameKind::kDamaged;
  const std::uint8_t* h = &frame[at];
  if ((h[0] >> 4) != 4) return FrameKind::kDamaged;
  const std::size_t header = static_cast<std::size_t>(h[0] & 0x0Fu) * 4;
  const std::size_t total = be16(h + 2);
  if (header < 20 || total < header || at + total > frame.size()) return FrameKind::kDamaged;
  if (h[9] != kProtoUdp) return FrameKind::kNotUdp;
  if ((be16(h + 6) & 0x3FFFu) != 0) return FrameKind::kNotUdp;  // a fragment
  std::memcpy(out.source.data(), h + 12, 4);
  out.source_length = 4;
  return udp(frame, at + header, at + total, out);
}

FrameKind ipv6(std::span<const std::uint8_t> frame, std::size_t at, UdpView& out) {
  if (at + 40 > frame.size()) return FrameKind::kDamaged;
  const std::uint8_t* h = &frame[at];
  if ((h[0] >> 4) != 6) return FrameKind::kDamaged;
  const std::size_t payload = be16(h + 4);
  if (at + 40 + payload > frame.size()) return FrameKind::kDamaged;
  if (h[6] != kProtoUdp) return FrameKind::kNotUdp;  // extension headers are not followed
  std::memcpy(out.source.data(), h + 8, 16);
  out.source_length = 16;
  return udp(frame, at + 40, at + 40 + payload, out);
}

FrameKind by_ethertype(std::uint16_t type, std::span<const std::uint8_t> frame, std::size_t at,
                       UdpView& out) {
  if (type == kEtherIpv4) return ipv4(frame, at, out);
  if (type == kEtherIpv6) return ipv6(frame, at, out);
  return FrameKind::kNotUdp;
}

FrameKind by_version(std::span<const std::uint8_t> frame, std::size_t at, UdpView& out) {
  if (at >= frame.size()) return FrameKind::kDamaged;
  const int version = frame[at] >> 4;
  if (version == 4) return ipv4(frame, at, out);
  if (version == 6) return ipv6(frame, at, out);
  return FrameKind::kNotUdp;
}

}  // namespace

FrameKind extract_udp(std::uint32_t link_type, std::span<const std::uint8_t> frame,
                      UdpView& out) noexcept {
  switch (link_type) {
    case kLinkEthernet: {
      std::size_t at = 12;
      for (int tags = 0;; ++tags) {
        if (at + 2 > frame.size()) return FrameKind::kDamaged;
        const std::uint16_t type = be16(&frame[at]);
        if ((type == kEtherVlan || type == kEtherQinQ) && tags < 4) {
          at += 4;  // TCI, then the inner type
          continue;
        }
        return by_ethertype(type, frame, at + 2, out);
      }
    }
    case kLinkLinuxSll:
      if (frame.size() < 16) return FrameKind::kDamaged;
      return by_ethertype(be16(&frame[14]), frame, 16, out);
    case kLinkLinuxSll2:
      if (frame.size() < 20) return FrameKind::kDamaged;
      return by_ethertype(be16(&frame[0]), frame, 20, out);
    case kLinkNull:  // 4-byte address family in the capturing host's order
      return by_version(frame, 4, out);
    case kLinkRaw:
    case kLinkRawBsd:
    case kLinkIpv4:
    case kLinkIpv6:
      return by_version(frame, 0, out);
    default:
      return FrameKind::kNotUdp;
  }
}

}  // namespace skytrack::asterix::detail
