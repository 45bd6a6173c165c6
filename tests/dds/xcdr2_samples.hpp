#pragma once
// Serialized skytrack samples written byte by byte, independently of Cyclone: an XCDR2 writer
// in either byte order, encoders of the three IDL types laid out member by member as
// idl/skytrack.idl declares them, and the crafted samples of issue 30, finding 7. Shared by the
// checker's unit tests and the end-to-end tests that put these bytes on a DDS domain.
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <vector>

#include "skytrack.h"

namespace skytrack::test::xcdr2 {

/// A D_CDR2 sample: the encapsulation header, then the body with XCDR2 alignment (at most 4).
/// Records where each length (sequence count, string length) and DHEADER went, so tests can
/// tamper with every one of them.
class Writer {
 public:
  explicit Writer(bool big_endian) : big_(big_endian) {
    bytes_ = {std::byte{0}, std::byte{big_endian ? std::uint8_t{8} : std::uint8_t{9}}, std::byte{0},
              std::byte{0}};
  }
  void u8(std::uint8_t v) { bytes_.push_back(std::byte{v}); }
  void u32(std::uint32_t v) { put(v, 4); }
  void u64(std::uint64_t v) { put(v, 8); }
  void f64(double v) { u64(std::bit_cast<std::uint64_t>(v)); }
  /// A length field (recorded in lengths()).
  void length(std::uint32_t n) {
    align(4);
    lengths_.push_back(bytes_.size());
    u32(n);
  }
  void string(std::string_view s) {
    length(static_cast<std::uint32_t>(s.size() + 1));
    for (char c : s) u8(static_cast<std::uint8_t>(c));
    u8(0);
  }
  /// Reserves a DHEADER; close() fills in the bytes written after it.
  std::size_t open() {
    align(4);
    dheaders_.push_back(bytes_.size());
    u32(0);
    return bytes_.size();
  }
  void close(std::size_t start) { patch(start - 4, static_cast<std::uint32_t>(size() - start)); }
  void patch(std::size_t at, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) bytes_[at + static_cast<std::size_t>(i)] = byte_of(v, i, 4);
  }
  std::size_t size() const { return bytes_.size(); }
  const std::vector<std::byte>& bytes() const { return bytes_; }
  const std::vector<std::size_t>& lengths() const { return lengths_; }
  const std::vector<std::size_t>& dheaders() const { return dheaders_; }

 private:
  void align(std::size_t a) {
    while ((bytes_.size() - 4) % a != 0) bytes_.push_back(std::byte{0});
  }
  std::byte byte_of(std::uint64_t v, int i, int n) const {
    const int shift = 8 * (big_ ? n - 1 - i : i);
    return std::byte{static_cast<std::uint8_t>(v >> shift)};
  }
  void put(std::uint64_t v, int n) {
    align(4);
    for (int i = 0; i < n; ++i) bytes_.push_back(byte_of(v, i, n));
  }
  bool big_;
  std::vector<std::byte> bytes_;
  std::vector<std::size_t> lengths_, dheaders_;
};

template <class Seq, class Put>
void sequence(Writer& w, const Seq& seq, Put put) {
  w.length(seq._length);
  for (std::uint32_t i = 0; i < seq._length; ++i) put(seq._buffer[i]);
}

/// Strings and structs: DHEADER, count, elements.
template <class Seq, class Put>
void delimited_sequence(Writer& w, const Seq& seq, Put put) {
  const std::size_t d = w.open();
  sequence(w, seq, put);
  w.close(d);
}

template <std::size_t N>
void doubles(Writer& w, const double (&a)[N]) {
  for (double v : a) w.f64(v);
}

inline Writer encode(const skytrack_dds_PlotBatch& b, bool big_endian) {
  Writer w(big_endian);
  const std::size_t d = w.open();
  w.u32(b.sensor);
  w.u64(b.scan);
  w.f64(b.time);
  doubles(w, b.platform_position);
  doubles(w, b.platform_velocity);
  doubles(w, b.platform_attitude);
  doubles(w, b.sigma);
  w.u32(b.sigma_flags);
  sequence(w, b.plot_ids, [&](std::int64_t v) { w.u64(static_cast<std::uint64_t>(v)); });
  sequence(w, b.plot_flags, [&](std::uint32_t v) { w.u32(v); });
  sequence(w, b.plot_values, [&](double v) { w.f64(v); });
  w.u8(b.has_coverage ? 1 : 0);
  doubles(w, b.coverage);
  sequence(w, b.plot_mode3a, [&](std::int32_t v) { w.u32(static_cast<std::uint32_t>(v)); });
  sequence(w, b.plot_mode_s, [&](std::int32_t v) { w.u32(static_cast<std::uint32_t>(v)); });
  sequence(w, b.plot_flight_level, [&](double v) { w.f64(v); });
  w.close(d);
  return w;
}

inline void encode_track(Writer& w, const skytrack_dds_Track& t) {
  const std::size_t d = w.open();
  w.u64(static_cast<std::uint64_t>(t.id));
  w.u32(static_cast<std::uint32_t>(t.status));
  w.u32(static_cast<std::uint32_t>(t.kind));
  w.u8(t.dims);
  doubles(w, t.position);
  doubles(w, t.velocity);
  w.u8(t.covariance_dim);
  doubles(w, t.covariance);
  w.u8(t.has_quality ? 1 : 0);
  w.f64(t.quality);
  w.u8(t.has_extent ? 1 : 0);
  doubles(w, t.extent);
  w.u32(static_cast<std::uint32_t>(t.members));
  sequence(w, t.mode_probabilities, [&](double v) { w.f64(v); });
  w.close(d);
}

inline Writer encode(const skytrack_dds_TrackBatch& b, bool big_endian) {
  Writer w(big_endian);
  const std::size_t d = w.open();
  w.u32(b.sensor);
  w.u64(b.scan);
  w.f64(b.time);
  delimited_sequence(w, b.mode_names, [&](const char* s) { w.string(s); });
  delimited_sequence(w, b.tracks, [&](const skytrack_dds_Track& t) { encode_track(w, t); });
  delimited_sequence(w, b.associations, [&](const skytrack_dds_Association& a) {
    w.u64(static_cast<std::uint64_t>(a.track));
    w.u64(static_cast<std::uint64_t>(a.plot));
    w.f64(a.probability);
  });
  delimited_sequence(w, b.events, [&](const skytrack_dds_TrackEvent& e) {
    w.string(e.type);
    w.u64(static_cast<std::uint64_t>(e.track));
    w.string(e.detail);
  });
  sequence(w, b.association_scans, [&](std::uint64_t v) { w.u64(v); });
  delimited_sequence(w, b.track_sources, [&](const skytrack_dds_TrackSource& s) {
    w.u32(s.track_index);
    w.u32(s.sensor);
    w.u64(static_cast<std::uint64_t>(s.track));
  });
  w.close(d);
  return w;
}

inline Writer encode(const skytrack_dds_TrackerStatus& s, bool big_endian) {
  Writer w(big_endian);
  const std::size_t d = w.open();
  w.string(s.instance);
  w.string(s.profile_name);
  w.string(s.profile_version);
  w.f64(s.uptime);
  w.u64(s.scans_processed);
  w.u64(s.plots_processed);
  const auto count = [&](const skytrack_dds_RejectionCount& c) {
    w.string(c.reason);
    w.u64(c.count);
  };
  delimited_sequence(w, s.plots_rejected, count);
  delimited_sequence(w, s.scans_rejected, count);
  w.u64(s.scans_dropped);
  w.u32(s.queue_depth);
  w.f64(s.latency_p50);
  w.f64(s.latency_p99);
  w.f64(s.latency_max);
  w.u32(s.tracks_tentative);
  w.u32(s.tracks_confirmed);
  w.u32(s.tracks_coasting);
  w.u64(s.numeric_failures);
  w.close(d);
  return w;
}

// ---- issue 30, finding 7 ---------------------------------------------------------------------

enum class HalfPresent { kPlotIds, kPlotValues };

/// (a) A PlotBatch of `plots` plots whose plot_ids, or plot_values, claims all its 8-byte
/// elements with only half their bytes present; its DHEADER ends there, so later members are
/// absent. Cyclone 0.10.2 accepts it and its read copies twice the bytes present, past the end
/// of the sample. With kPlotValues the lengths agree (n ids, n flags, 17n values): before the
/// checker, skytrackd tracked it with heap memory for half the values.
inline Writer half_present_plot_batch(HalfPresent which, std::uint32_t plots, bool big_endian,
                                      std::uint32_t sensor = 1, std::uint64_t scan = 1000) {
  Writer w(big_endian);
  const std::size_t d = w.open();
  w.u32(sensor);
  w.u64(scan);
  w.f64(static_cast<double>(scan));
  for (int i = 0; i < 16; ++i) w.f64(0.0);
  w.u32(0);
  const std::uint32_t stride = skytrack_dds_PLOT_STRIDE;
  w.length(plots);
  for (std::uint32_t i = 0; i < plots; ++i) {
    if (which == HalfPresent::kPlotIds) {
      w.u32(i);  // 4 of each id's 8 bytes
    } else {
      w.u64(i);
    }
  }
  if (which == HalfPresent::kPlotValues) {
    w.length(plots);
    for (std::uint32_t i = 0; i < plots; ++i) w.u32((1u << 5) | (1u << 6) | (1u << 31));
    w.length(plots * stride);
    for (std::uint32_t i = 0; i < plots * stride; ++i) w.u32(0x40000000u);  // half of each
  }
  w.close(d);
  return w;
}

/// The 4-byte word Cyclone's read takes as the associations' count in shifted_track_batch:
/// 177 950 000 Association structs of 24 bytes, a 4.27 GB allocation.
inline constexpr std::uint32_t kShiftedAssociations = 177'950'000;

/// (b) A TrackBatch with one Track whose mode_probabilities claims 4 doubles with 16 bytes
/// present, the last member of the Track's DHEADER. Cyclone's validation resumes at the end
/// of that DHEADER, its read 16 bytes later: the read takes the associations' count from the
/// first word of association_scans' value, which the validation takes as part of a u64.
inline Writer shifted_track_batch(std::uint32_t associations, bool big_endian,
                                  std::uint32_t sensor = 99) {
  Writer w(big_endian);
  const std::size_t d = w.open();
  w.u32(sensor);
  w.u64(1);
  w.f64(1.0);
  const std::size_t names = w.open();
  w.length(0);
  w.close(names);
  const std::size_t tracks = w.open();
  w.length(1);
  const std::size_t track = w.open();
  w.u64(1);
  w.u32(skytrack_dds_TRACK_CONFIRMED);
  w.u32(skytrack_dds_OBJECT_POINT);
  w.u8(2);
  for (int i = 0; i < 6; ++i) w.f64(0.0);
  w.u8(0);
  for (int i = 0; i < 36; ++i) w.f64(0.0);
  w.u8(0);
  w.f64(0.0);
  w.u8(0);
  for (int i = 0; i < 4; ++i) w.f64(0.0);
  w.u32(0xffffffffu);
  w.length(4);
  for (int i = 0; i < 4; ++i) w.u32(0);  // 4 of the 8 bytes of each probability
  w.close(track);
  w.close(tracks);
  for (int i = 0; i < 2; ++i) {  // associations and events: empty
    const std::size_t empty = w.open();
    w.length(0);
    w.close(empty);
  }
  // association_scans: one value whose first word is where the shifted read looks for the
  // associations' count (any u64 is valid to the validation); then an empty track_sources.
  w.length(1);
  w.u64(big_endian ? std::uint64_t{associations} << 32 : std::uint64_t{associations});
  const std::size_t sources = w.open();
  w.length(0);
  w.close(sources);
  // The rest pads to 1568 bytes.
  while (w.size() < 1568) w.u32(0);
  w.close(d);
  return w;
}

}  // namespace skytrack::test::xcdr2
