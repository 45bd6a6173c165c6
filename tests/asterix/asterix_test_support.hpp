#pragma once
// Hand-built ASTERIX for the decoder tests: records from (FRN, bytes) items with the FSPEC
// computed, blocks from records, pcap / pcapng files around datagrams; and a sink that keeps
// what the decoder gives out.
#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

#include "skytrack/asterix/decoder.hpp"

namespace skytrack::asterix::test {

using Bytes = std::vector<std::uint8_t>;

struct Item {
  int frn;
  Bytes bytes;
};

inline Bytes record(std::initializer_list<Item> items) {
  int max_frn = 1;
  for (const Item& i : items) max_frn = std::max(max_frn, i.frn);
  Bytes fspec(static_cast<std::size_t>((max_frn + 6) / 7), 0);
  for (const Item& i : items) {
    const int bit = i.frn - 1;
    fspec[static_cast<std::size_t>(bit / 7)] |= static_cast<std::uint8_t>(0x80u >> (bit % 7));
  }
  for (std::size_t o = 0; o + 1 < fspec.size(); ++o) fspec[o] |= 1u;
  Bytes out = fspec;
  for (const Item& i : items) out.insert(out.end(), i.bytes.begin(), i.bytes.end());
  return out;
}

inline Bytes block(std::uint8_t category, std::initializer_list<Bytes> records) {
  Bytes out{category, 0, 0};
  for (const Bytes& r : records) out.insert(out.end(), r.begin(), r.end());
  out[1] = static_cast<std::uint8_t>(out.size() >> 8);
  out[2] = static_cast<std::uint8_t>(out.size() & 0xFF);
  return out;
}

inline Bytes concat(std::initializer_list<Bytes> parts) {
  Bytes out;
  for (const Bytes& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

inline Bytes u16(unsigned v) {
  return {static_cast<std::uint8_t>(v >> 8), static_cast<std::uint8_t>(v)};
}
inline Bytes u24(unsigned v) {
  return {static_cast<std::uint8_t>(v >> 16), static_cast<std::uint8_t>(v >> 8),
          static_cast<std::uint8_t>(v)};
}
/// Time of day [s] as I0xx/140, /030: 1/128 s in 3 bytes.
inline Bytes tod(double seconds) {
  return u24(static_cast<unsigned>(seconds * 128.0 + 0.5));
}
/// Polar position: RHO in `per_nm` steps, THETA in 2^16 per turn.
inline Bytes polar(double range_nm, double azimuth_deg, double per_nm) {
  return concat({u16(static_cast<unsigned>(range_nm * per_nm + 0.5)),
                 u16(static_cast<unsigned>(azimuth_deg / 360.0 * 65536.0 + 0.5))});
}

/// A UDP/IPv4 datagram in an Ethernet frame, optionally VLAN tagged.
Bytes ethernet_udp(const Bytes& payload, std::uint16_t source_port, std::uint16_t port,
                   std::array<std::uint8_t, 4> source = {10, 0, 0, 1}, bool vlan = false);
/// The IPv4 packet alone (raw IP link type).
Bytes ipv4_udp(const Bytes& payload, std::uint16_t source_port, std::uint16_t port,
               std::array<std::uint8_t, 4> source = {10, 0, 0, 1});

struct CapturedFrame {
  double time;
  Bytes data;
};
/// Classic pcap (little endian, microseconds) with one link type.
Bytes pcap_file(std::uint32_t link_type, const std::vector<CapturedFrame>& frames);
/// pcapng: section header, one interface (microsecond resolution), enhanced packet blocks.
Bytes pcapng_file(std::uint32_t link_type, const std::vector<CapturedFrame>& frames,
                  bool big_endian = false);

struct Collected final : RecordSink {
  std::vector<TargetReport> reports;
  std::vector<ServiceMessage> services;
  std::vector<DecodeError> errors;
  void on_report(const TargetReport& r) override { reports.push_back(r); }
  void on_service(const ServiceMessage& m) override { services.push_back(m); }
  void on_error(const DecodeError& e) override { errors.push_back(e); }
};

/// Decodes `bytes` as one datagram with a fresh decoder (unless given one).
inline Collected decode(const Bytes& bytes, std::optional<double> reception = std::nullopt,
                        DecoderOptions options = {}) {
  Decoder decoder(options);
  Collected out;
  decoder.decode(bytes, Origin{0, 1}, reception, out);
  return out;
}

}  // namespace skytrack::asterix::test
