#pragma once
// The UDP payload inside a captured frame: link layer (Ethernet with VLAN tags, Linux cooked
// SLL / SLL2, BSD loopback, raw IP), then IPv4 or IPv6, then UDP.
#include <array>
#include <cstdint>
#include <span>

namespace skytrack::asterix::detail {

// Link-layer header types (tcpdump.org LINKTYPE_ values).
inline constexpr std::uint32_t kLinkNull = 0, kLinkEthernet = 1, kLinkRawBsd = 12, kLinkRaw = 101,
                               kLinkLinuxSll = 113, kLinkIpv4 = 228, kLinkIpv6 = 229,
                               kLinkLinuxSll2 = 276;

struct UdpView {
  std::span<const std::uint8_t> payload;
  std::size_t payload_offset = 0;  // within the frame
  std::array<std::uint8_t, 16> source{};
  std::uint8_t source_length = 0;  // 4 or 16
  std::uint16_t source_port = 0;
  std::uint16_t destination_port = 0;
};

enum class FrameKind : std::uint8_t { kUdp, kNotUdp, kDamaged };

FrameKind extract_udp(std::uint32_t link_type, std::span<const std::uint8_t> frame,
                      UdpView& out) noexcept;

}  // namespace skytrack::asterix::detail
