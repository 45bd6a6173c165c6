#include "skytrack/core/transponder.hpp"

#include <cstdio>

namespace skytrack {

std::optional<std::uint16_t> parse_mode3a(std::string_view text) {
  if (text.size() != 4) return std::nullopt;
  std::uint16_t code = 0;
  for (const char c : text) {
    if (c < '0' || c > '7') return std::nullopt;
    code = static_cast<std::uint16_t>(code * 8 + (c - '0'));
  }
  return code;
}

std::string format_mode3a(std::uint16_t code) {
  char out[8];
  std::snprintf(out, sizeof out, "%04o", static_cast<unsigned>(code & kMaxMode3a));
  return out;
}

std::optional<std::uint32_t> parse_mode_s(std::string_view text) {
  if (text.size() != 6) return std::nullopt;
  std::uint32_t address = 0;
  for (const char c : text) {
    int digit = -1;
    if (c >= '0' && c <= '9') digit = c - '0';
    if (c >= 'A' && c <= 'F') digit = c - 'A' + 10;
    if (c >= 'a' && c <= 'f') digit = c - 'a' + 10;
    if (digit < 0) return std::nullopt;
    address = address * 16 + static_cast<std::uint32_t>(digit);
  }
  return address;
}

std::string format_mode_s(std::uint32_t address) {
  char out[8];
  std::snprintf(out, sizeof out, "%06X", static_cast<unsigned>(address & kMaxModeS));
  return out;
}

}  // namespace skytrack
