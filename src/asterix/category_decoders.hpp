#pragma once
// What each category's interpreted items mean. Each function reads one walked record into a
// report or service message and says what became of it; times are left raw (of the day, or
// truncated) for the decoder, which keeps the per-sensor clocks.
#include <optional>

#include "record_walker.hpp"
#include "skytrack/asterix/records.hpp"

namespace skytrack::asterix::detail {

inline constexpr double kNauticalMile = 1852.0;  // [m]
inline constexpr double kTwoPi = 6.283185307179586476925286766559;
inline constexpr double kSecondsPerDay = 86400.0;
inline constexpr double kTruncatedTimeSpan = 512.0;  // I001/141 wraps every 2^16 / 128 s

struct RecordOutcome {
  enum class Kind : std::uint8_t { kKept, kDropped, kError };
  Kind kind = Kind::kKept;
  DropReason drop = DropReason::kCount;
  ErrorReason error = ErrorReason::kCount;
  const char* detail = "";
  std::optional<double> time_of_day;     // [s] as sent, [0, 86 400)
  std::optional<double> truncated_time;  // [s] I001/141, [0, 512)
  bool bad_flight_level = false;         // a flight level out of range was left out

  static RecordOutcome dropped(DropReason why) {
    RecordOutcome o;
    o.kind = Kind::kDropped;
    o.drop = why;
    return o;
  }
  static RecordOutcome failed(ErrorReason why, const char* detail) {
    RecordOutcome o;
    o.kind = Kind::kError;
    o.error = why;
    o.detail = detail;
    return o;
  }
};

/// Reads the common items of target reports: I0xx/010 (sensor), polar position, Mode 3/A
/// (validated codes only), flight level (validated and plausible).
RecordOutcome decode_cat048(const RecordItems& items, TargetReport& out) noexcept;
/// `track`: the record uses the track UAP (I001/020 TYP = 1).
RecordOutcome decode_cat001(const RecordItems& items, bool track, TargetReport& out) noexcept;
RecordOutcome decode_cat002(const RecordItems& items, ServiceMessage& out) noexcept;
RecordOutcome decode_cat034(const RecordItems& items, ServiceMessage& out) noexcept;

/// Whether the CAT001 record at `pos` is a track report: TYP of I001/020, which both UAPs
/// place after I001/010. nullopt when the FSPEC is bad or I001/020 is absent or past the end.
std::optional<bool> cat001_is_track(std::span<const std::uint8_t> block, std::size_t pos);

}  // namespace skytrack::asterix::detail
