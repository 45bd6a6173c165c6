#include "skytrack/asterix/records.hpp"

#include <charconv>

namespace skytrack::asterix {

std::optional<std::uint32_t> parse_sac_sic(std::string_view text) {
  const auto slash = text.find('/');
  if (slash == std::string_view::npos) return std::nullopt;
  const auto number = [](std::string_view part) -> std::optional<unsigned> {
    unsigned v = 0;
    const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), v);
    if (part.empty() || ec != std::errc() || end != part.data() + part.size() || v > 255) {
      return std::nullopt;
    }
    return v;
  };
  const auto sac = number(text.substr(0, slash));
  const auto sic = number(text.substr(slash + 1));
  if (!sac || !sic) return std::nullopt;
  return sensor_id(static_cast<std::uint8_t>(*sac), static_cast<std::uint8_t>(*sic));
}

std::string format_sac_sic(std::uint32_t sensor) {
  return std::to_string(sensor / 256) + "/" + std::to_string(sensor % 256);
}

std::string to_string(const Origin& where) {
  if (where.datagram == 0) return "byte " + std::to_string(where.offset);
  return "datagram " + std::to_string(where.datagram) + ", byte " + std::to_string(where.offset);
}

std::string_view to_string(ServiceKind kind) {
  switch (kind) {
    case ServiceKind::kNorthMarker:
      return "north marker";
    case ServiceKind::kSectorCrossing:
      return "sector crossing";
    case ServiceKind::kSouthMarker:
      return "south marker";
    case ServiceKind::kOther:
      break;
  }
  return "other";
}

std::string_view to_string(ErrorReason reason) {
  switch (reason) {
    case ErrorReason::kTruncatedBlock:
      return "truncated block";
    case ErrorReason::kBadBlockLength:
      return "bad block length";
    case ErrorReason::kLengthPastEnd:
      return "length past end";
    case ErrorReason::kFspecPastEnd:
      return "FSPEC past end";
    case ErrorReason::kFspecTooLong:
      return "FSPEC too long";
    case ErrorReason::kUndefinedItem:
      return "undefined item";
    case ErrorReason::kItemPastEnd:
      return "item past end";
    case ErrorReason::kRepetitionPastEnd:
      return "repetition past end";
    case ErrorReason::kValueOutOfRange:
      return "value out of range";
    case ErrorReason::kMissingItem:
      return "missing item";
    case ErrorReason::kNoTimeReference:
      return "no time reference";
    case ErrorReason::kCount:
      break;
  }
  return "unknown";
}

std::string_view to_string(DropReason reason) {
  switch (reason) {
    case DropReason::kNoDetection:
      return "no detection";
    case DropReason::kNoPosition:
      return "no position";
    case DropReason::kSimulated:
      return "simulated";
    case DropReason::kTest:
      return "test target";
    case DropReason::kOtherSensor:
      return "other sensor";
    case DropReason::kCount:
      break;
  }
  return "unknown";
}

std::string to_string(const DecodeError& error) {
  std::string out = to_string(error.where) + ": ";
  if (error.category != 0) {
    const unsigned c = error.category;
    out += "CAT" + std::string(c < 100 ? "0" : "") + std::string(c < 10 ? "0" : "") +
           std::to_string(c) + ": ";
  }
  out += to_string(error.reason);
  if (!error.detail.empty()) out += " (" + error.detail + ")";
  return out;
}

}  // namespace skytrack::asterix
