// CAT002 and CAT034 monoradar service messages (EUROCONTROL ASTERIX Part 2b, Category 002
// ed. 1.0; Category 034 ed. 1.2x): north markers and sector crossings with their time of day
// (1/128 s), sector azimuth (360/2^8 deg), antenna rotation period (1/128 s) and, in CAT034,
// the radar's position (I034/120: height in m, latitude and longitude 180/2^23 deg).
#include "category_decoders.hpp"
#include "target_fields.hpp"
#include "uaps.hpp"

namespace skytrack::asterix::detail {
namespace {

constexpr double kPi = kTwoPi / 2.0;

/// Reads time of day, sector and rotation period, which both categories share in format.
RecordOutcome read_common(const RecordItems& items, int time, int sector, int period,
                          const char* category_time, ServiceMessage& out) {
  RecordOutcome outcome;
  if (items.has(time)) {
    const double tod = be24(items.data(time)) / 128.0;
    if (tod >= kSecondsPerDay) {
      return RecordOutcome::failed(ErrorReason::kValueOutOfRange, category_time);
    }
    outcome.time_of_day = tod;
  }
  if (out.kind == ServiceKind::kNorthMarker) out.azimuth = 0.0;
  if (out.kind == ServiceKind::kSouthMarker) out.azimuth = kPi;
  if (out.kind == ServiceKind::kSectorCrossing) {
    if (!items.has(sector)) {
      return RecordOutcome::failed(ErrorReason::kMissingItem, "sector crossing without sector");
    }
    out.azimuth = items.data(sector)[0] * (kTwoPi / 256.0);
  }
  if (items.has(period)) {
    const double seconds = be16(items.data(period)) / 128.0;
    if (seconds <= 0.0) {
      return RecordOutcome::failed(ErrorReason::kValueOutOfRange, "antenna rotation period 0");
    }
    out.rotation_period = seconds;
  }
  return outcome;
}

}  // namespace

RecordOutcome decode_cat002(const RecordItems& items, ServiceMessage& out) noexcept {
  using namespace cat002;
  if (!items.has(kDataSource) || !items.has(kMessageType)) {
    return RecordOutcome::failed(ErrorReason::kMissingItem, "no I002/010 or I002/000");
  }
  out.category = 2;
  out.sensor = read_sensor(items.data(kDataSource));
  out.message_type = items.data(kMessageType)[0];
  switch (out.message_type) {
    case 1:
      out.kind = ServiceKind::kNorthMarker;
      break;
    case 2:
      out.kind = ServiceKind::kSectorCrossing;
      break;
    case 3:
      out.kind = ServiceKind::kSouthMarker;
      break;
    case 8:  // activation / stop of blind zone filtering
    case 9:
      out.kind = ServiceKind::kOther;
      break;
    default:
      return RecordOutcome::failed(ErrorReason::kValueOutOfRange, "I002/000 message type");
  }
  return read_common(items, kTimeOfDay, kSector, kRotationPeriod, "I002/030 time of day past 24 h",
                     out);
}

RecordOutcome decode_cat034(const RecordItems& items, ServiceMessage& out) noexcept {
  using namespace cat034;
  if (!items.has(kDataSource) || !items.has(kMessageType)) {
    return RecordOutcome::failed(ErrorReason::kMissingItem, "no I034/010 or I034/000");
  }
  out.category = 34;
  out.sensor = read_sensor(items.data(kDataSource));
  out.message_type = items.data(kMessageType)[0];
  switch (out.message_type) {
    case 1:
      out.kind = ServiceKind::kNorthMarker;
      break;
    case 2:
      out.kind = ServiceKind::kSectorCrossing;
      break;
    case 3:  // geographical filtering, jamming strobe, solar storm, SSR / Mode S jamming
    case 4:
    case 5:
    case 6:
    case 7:
      out.kind = ServiceKind::kOther;
      break;
    default:
      return RecordOutcome::failed(ErrorReason::kValueOutOfRange, "I034/000 message type");
  }
  RecordOutcome outcome = read_common(items, kTimeOfDay, kSector, kRotationPeriod,
                                      "I034/030 time of day past 24 h", out);
  if (outcome.kind == RecordOutcome::Kind::kKept && items.has(kPosition)) {
    const std::uint8_t* p = items.data(kPosition);
    const double lat = signed_bits(be24(p + 2), 24) * (180.0 / 8388608.0);
    const double lon = signed_bits(be24(p + 5), 24) * (180.0 / 8388608.0);
    if (lat < -90.0 || lat > 90.0) {
      return RecordOutcome::failed(ErrorReason::kValueOutOfRange, "I034/120 latitude");
    }
    out.position = std::array<double, 3>{lat, lon, static_cast<double>(signed_bits(be16(p), 16))};
  }
  return outcome;
}

}  // namespace skytrack::asterix::detail
