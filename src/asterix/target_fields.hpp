#pragma once
// Fields that CAT001 and CAT048 target reports share in layout: data source, polar position,
// Mode 3/A code, Mode C / flight level.
#include <cmath>
#include <optional>

#include "category_decoders.hpp"
#include "skytrack/core/transponder.hpp"

namespace skytrack::asterix::detail {

inline std::uint32_t read_sensor(const std::uint8_t* p) {
  return sensor_id(p[0], p[1]);
}

/// RHO (`per_nm` steps per NM: 128 in CAT001, 256 in CAT048) and THETA (2^16 per turn).
inline void read_polar(const std::uint8_t* p, double per_nm, TargetReport& out) {
  out.range = be16(p) * (kNauticalMile / per_nm);
  out.azimuth = be16(p + 2) * (kTwoPi / 65536.0);
}

/// The 12-bit code when validated (V = 0): a code the radar marks not validated would mislead
/// a tracker's identity logic. A garbled (G) code is kept, as the radar validated it.
inline std::optional<std::uint16_t> read_mode3a(const std::uint8_t* p) {
  const std::uint32_t v = be16(p);
  if ((v & 0x8000u) != 0) return std::nullopt;
  return static_cast<std::uint16_t>(v & 0x0FFFu);
}

/// Flight level (14-bit two's complement, 1/4 FL) when validated (V = 0); out of the
/// transponder's range it is left out and `bad` set.
inline std::optional<double> read_flight_level(const std::uint8_t* p, bool& bad) {
  const std::uint32_t v = be16(p);
  if ((v & 0x8000u) != 0) return std::nullopt;
  const double fl = signed_bits(v, 14) * 0.25;
  if (!plausible_flight_level(fl)) {
    bad = true;
    return std::nullopt;
  }
  return fl;
}

}  // namespace skytrack::asterix::detail
