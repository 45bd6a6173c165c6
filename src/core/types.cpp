#include <cmath>

#include "skytrack/core/plot.hpp"
#include "skytrack/core/track_report.hpp"
#include "skytrack/core/truth.hpp"

namespace skytrack {

bool AzimuthSector::contains(double azimuth) const {
  constexpr double kTwoPi = 2.0 * 3.141592653589793;
  const auto clockwise = [&](double a) {  // angle from `from` to a, in [0, 2 pi)
    double d = std::fmod(a - from, kTwoPi);
    return d < 0.0 ? d + kTwoPi : d;
  };
  return clockwise(azimuth) <= clockwise(to);
}

MeasurementSigma merged(const MeasurementSigma& primary, const MeasurementSigma& fallback) {
  MeasurementSigma out = primary;
  if (!out.range) out.range = fallback.range;
  if (!out.azimuth) out.azimuth = fallback.azimuth;
  if (!out.elevation) out.elevation = fallback.elevation;
  if (!out.range_rate) out.range_rate = fallback.range_rate;
  if (!out.x) out.x = fallback.x;
  if (!out.y) out.y = fallback.y;
  if (!out.z) out.z = fallback.z;
  return out;
}

std::string_view to_string(ObjectKind kind) {
  switch (kind) {
    case ObjectKind::kPoint:
      return "point";
    case ObjectKind::kGroup:
      return "group";
    case ObjectKind::kExtended:
      return "extended";
  }
  return "point";
}

std::optional<ObjectKind> parse_object_kind(std::string_view text) {
  if (text == "point") return ObjectKind::kPoint;
  if (text == "group") return ObjectKind::kGroup;
  if (text == "extended") return ObjectKind::kExtended;
  return std::nullopt;
}

std::string_view to_string(TrackStatus status) {
  switch (status) {
    case TrackStatus::kTentative:
      return "tentative";
    case TrackStatus::kConfirmed:
      return "confirmed";
    case TrackStatus::kCoasting:
      return "coasting";
    case TrackStatus::kDeleted:
      return "deleted";
  }
  return "tentative";
}

std::optional<TrackStatus> parse_track_status(std::string_view text) {
  if (text == "tentative") return TrackStatus::kTentative;
  if (text == "confirmed") return TrackStatus::kConfirmed;
  if (text == "coasting") return TrackStatus::kCoasting;
  if (text == "deleted") return TrackStatus::kDeleted;
  return std::nullopt;
}

}  // namespace skytrack
