#pragma once
// What the ASTERIX decoder gives out: target reports (plots), service messages (north markers,
// sector crossings, rotation period, radar position), and errors with where they happened.
// Units: metres, seconds, radians; azimuth clockwise from north. Times are seconds of the day
// (UTC), continuing past 86 400 after midnight so that they never go backwards.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace skytrack::asterix {

/// The sensor id of a radar: SAC * 256 + SIC (I0xx/010).
inline constexpr std::uint32_t sensor_id(std::uint8_t sac, std::uint8_t sic) {
  return static_cast<std::uint32_t>(sac) * 256u + sic;
}
/// "20/130" -> 20 * 256 + 130; nullopt unless two integers 0..255 separated by '/'.
std::optional<std::uint32_t> parse_sac_sic(std::string_view text);
std::string format_sac_sic(std::uint32_t sensor);  // "20/130"

/// Where a block or record was found: the byte offset in the input file (0 for a live
/// datagram) and the datagram number (1-based; 0 in a raw file of concatenated blocks).
struct Origin {
  std::uint64_t offset = 0;
  std::uint64_t datagram = 0;
};
std::string to_string(const Origin& where);  // "byte 1234" / "datagram 17, byte 3"

/// One plot: a target report with a measured position.
struct TargetReport {
  std::uint8_t category = 0;            // 1 or 48
  std::uint32_t sensor = 0;             // SAC * 256 + SIC
  double time = 0.0;                    // [s] time of day, continued past midnight
  double range = 0.0;                   // [m] slant range as measured
  double azimuth = 0.0;                 // [rad] clockwise from north, [0, 2 pi)
  std::optional<std::uint16_t> mode3a;  // validated Mode 3/A code (12 bits)
  std::optional<std::uint32_t> mode_s;  // Mode S address (24 bits)
  std::optional<double> flight_level;   // validated, plausible [100 ft]
  bool simulated = false;               // SIM
  bool test = false;                    // TST
  bool fixed_transponder = false;       // RAB: a field monitor, kept as a plot
  Origin where;                         // of the record
};

enum class ServiceKind : std::uint8_t { kNorthMarker, kSectorCrossing, kSouthMarker, kOther };
std::string_view to_string(ServiceKind kind);

/// A CAT002 / CAT034 service message.
struct ServiceMessage {
  std::uint8_t category = 0;  // 2 or 34
  std::uint32_t sensor = 0;
  ServiceKind kind = ServiceKind::kOther;
  std::uint8_t message_type = 0;                  // I002/000, I034/000 as sent
  std::optional<double> time;                     // [s] time of day, continued past midnight
  std::optional<double> azimuth;                  // [rad] the sector's (0 for a north marker)
  std::optional<double> rotation_period;          // [s] I002/041, I034/041
  std::optional<std::array<double, 3>> position;  // I034/120: lat, lon [deg], height [m]
  Origin where;
};

/// Why a record or block could not be decoded (bad input), counted by reason.
enum class ErrorReason : std::uint8_t {
  kTruncatedBlock,     // fewer than 3 bytes left for a block header
  kBadBlockLength,     // LEN below 3 (or below the header and an FSPEC)
  kLengthPastEnd,      // LEN runs past the datagram or file
  kFspecPastEnd,       // the FSPEC runs past the block
  kFspecTooLong,       // FX set beyond the last item of the category's UAP
  kUndefinedItem,      // an FSPEC bit for a spare / undefined item: its length is unknown
  kItemPastEnd,        // an item runs past the block
  kRepetitionPastEnd,  // a repetition count (or explicit length) runs past the block
  kValueOutOfRange,    // a value the specification does not allow; the record is dropped
  kMissingItem,        // a mandatory item (data source, time, message type) is absent
  kNoTimeReference,    // CAT001 truncated time with no CAT002 time nor reception time
  kCount
};
std::string_view to_string(ErrorReason reason);

/// Why a well-formed record is not given out as a plot, counted by reason.
enum class DropReason : std::uint8_t {
  kNoDetection,  // I048/020 TYP 0, I001/020 SSR/PSR 00
  kNoPosition,   // no measured polar position
  kSimulated,    // SIM (kept with keep_tests)
  kTest,         // TST (kept with keep_tests)
  kOtherSensor,  // not the selected SAC/SIC
  kCount
};
std::string_view to_string(DropReason reason);

/// A decoding error: what, where, and in which category (0 when no block was read).
struct DecodeError {
  ErrorReason reason = ErrorReason::kTruncatedBlock;
  std::uint8_t category = 0;
  Origin where;
  std::string detail;
};
std::string to_string(const DecodeError& error);  // "byte 1234: CAT048: item past end (...)"

}  // namespace skytrack::asterix
