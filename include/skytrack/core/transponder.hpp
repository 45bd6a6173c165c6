#pragma once
// Text forms of the transponder attributes of a plot (CONTRACTS.md §1): the Mode 3/A code as
// 4 octal digits ("2270"), the Mode S address as 6 hex digits ("4CA2D7"), and the pressure
// altitude of a flight level.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace skytrack {

inline constexpr std::uint16_t kMaxMode3a = 07777;
inline constexpr std::uint32_t kMaxModeS = 0xFFFFFF;
inline constexpr double kFeetToMetres = 0.3048;

/// "2270" for the code 02270; nullopt unless the text is exactly 4 octal digits.
std::optional<std::uint16_t> parse_mode3a(std::string_view text);
std::string format_mode3a(std::uint16_t code);

/// 0x4CA2D7 for "4CA2D7" (either case); nullopt unless exactly 6 hex digits.
std::optional<std::uint32_t> parse_mode_s(std::string_view text);
std::string format_mode_s(std::uint32_t address);

/// Pressure altitude [m] of a flight level [100 ft] (standard atmosphere, not geometric).
inline double flight_level_to_metres(double flight_level) {
  return flight_level * 100.0 * kFeetToMetres;
}

/// Flight levels a transponder can report: Mode C spans -12 to 1267 (-1 200 to 126 700 ft).
inline bool plausible_flight_level(double flight_level) {
  return flight_level >= -15.0 && flight_level <= 1500.0;
}

}  // namespace skytrack
