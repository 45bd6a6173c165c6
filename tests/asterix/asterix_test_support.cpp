#include "asterix_test_support.hpp"

namespace skytrack::asterix::test {
namespace {

void le32(Bytes& out, std::uint32_t v, bool big = false) {
  for (int i = 0; i < 4; ++i) {
    const int shift = big ? 24 - 8 * i : 8 * i;
    out.push_back(static_cast<std::uint8_t>(v >> shift));
  }
}
void le16(Bytes& out, std::uint16_t v, bool big = false) {
  out.push_back(static_cast<std::uint8_t>(big ? v >> 8 : v));
  out.push_back(static_cast<std::uint8_t>(big ? v : v >> 8));
}

void append(Bytes& out, std::initializer_list<std::uint8_t> bytes) {
  for (const std::uint8_t b : bytes) out.push_back(b);
}
void append(Bytes& out, const Bytes& bytes) {
  for (const std::uint8_t b : bytes) out.push_back(b);
}

}  // namespace

Bytes ipv4_udp(const Bytes& payload, std::uint16_t source_port, std::uint16_t port,
               std::array<std::uint8_t, 4> source) {
  const std::size_t total = 20 + 8 + payload.size();
  Bytes out;
  out.reserve(total);
  append(out, {0x45, 0, static_cast<std::uint8_t>(total >> 8), static_cast<std::uint8_t>(total), 0,
               0, 0, 0, 64, 17, 0, 0});
  append(out, {source[0], source[1], source[2], source[3], 127, 0, 0, 1});
  const std::size_t udp = 8 + payload.size();
  append(out, {static_cast<std::uint8_t>(source_port >> 8), static_cast<std::uint8_t>(source_port),
               static_cast<std::uint8_t>(port >> 8), static_cast<std::uint8_t>(port),
               static_cast<std::uint8_t>(udp >> 8), static_cast<std::uint8_t>(udp), 0, 0});
  append(out, payload);
  return out;
}

Bytes ethernet_udp(const Bytes& payload, std::uint16_t source_port, std::uint16_t port,
                   std::array<std::uint8_t, 4> source, bool vlan) {
  Bytes out;
  append(out, {1, 0, 0x5e, 0, 0, 1, 2, 0, 0, 0, 0, 1});
  if (vlan) append(out, {0x81, 0x00, 0x00, 0x07});
  append(out, {0x08, 0x00});
  append(out, ipv4_udp(payload, source_port, port, source));
  return out;
}

Bytes pcap_file(std::uint32_t link_type, const std::vector<CapturedFrame>& frames) {
  Bytes out;
  le32(out, 0xA1B2C3D4);
  le16(out, 2);
  le16(out, 4);
  le32(out, 0);
  le32(out, 0);
  le32(out, 65535);
  le32(out, link_type);
  for (const CapturedFrame& f : frames) {
    const auto seconds = static_cast<std::uint32_t>(f.time);
    le32(out, seconds);
    le32(out, static_cast<std::uint32_t>((f.time - seconds) * 1e6 + 0.5));
    le32(out, static_cast<std::uint32_t>(f.data.size()));
    le32(out, static_cast<std::uint32_t>(f.data.size()));
    append(out, f.data);
  }
  return out;
}

Bytes pcapng_file(std::uint32_t link_type, const std::vector<CapturedFrame>& frames, bool big) {
  Bytes out;
  // Section header block: type, length, byte-order magic, version, section length (-1).
  le32(out, 0x0A0D0D0A, big);
  le32(out, 28, big);
  le32(out, 0x1A2B3C4D, big);
  le16(out, 1, big);
  le16(out, 0, big);
  le32(out, 0xFFFFFFFF, big);
  le32(out, 0xFFFFFFFF, big);
  le32(out, 28, big);
  // Interface description block with if_tsresol = 6 (microseconds) and end of options.
  le32(out, 1, big);
  le32(out, 32, big);
  le16(out, static_cast<std::uint16_t>(link_type), big);
  le16(out, 0, big);
  le32(out, 65535, big);
  le16(out, 9, big);
  le16(out, 1, big);
  append(out, {6, 0, 0, 0});
  le16(out, 0, big);
  le16(out, 0, big);
  le32(out, 32, big);
  for (const CapturedFrame& f : frames) {
    const std::size_t padded = (f.data.size() + 3) & ~std::size_t{3};
    const auto length = static_cast<std::uint32_t>(32 + padded);
    const auto stamp = static_cast<std::uint64_t>(f.time * 1e6 + 0.5);
    le32(out, 6, big);
    le32(out, length, big);
    le32(out, 0, big);
    le32(out, static_cast<std::uint32_t>(stamp >> 32), big);
    le32(out, static_cast<std::uint32_t>(stamp), big);
    le32(out, static_cast<std::uint32_t>(f.data.size()), big);
    le32(out, static_cast<std::uint32_t>(f.data.size()), big);
    append(out, f.data);
    out.resize(out.size() + padded - f.data.size(), 0);
    le32(out, length, big);
  }
  return out;
}

}  // namespace skytrack::asterix::test
