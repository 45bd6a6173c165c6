// CAT048 monoradar target reports (EUROCONTROL ASTERIX Part 4, Category 048).
// I048/020 TYP 0 (no detection) is not a plot; I048/040 is the measured slant polar position
// (RHO 1/256 NM, THETA 360/2^16 deg); I048/140 time of day in 1/128 s.
#include "category_decoders.hpp"
#include "target_fields.hpp"
#include "uaps.hpp"

namespace skytrack::asterix::detail {

RecordOutcome decode_cat048(const RecordItems& items, TargetReport& out) noexcept {
  using namespace cat048;
  if (!items.has(kDataSource)) {
    return RecordOutcome::failed(ErrorReason::kMissingItem, "no I048/010 data source");
  }
  out.category = 48;
  out.sensor = read_sensor(items.data(kDataSource));
  if (!items.has(kTimeOfDay)) {
    return RecordOutcome::failed(ErrorReason::kMissingItem, "no I048/140 time of day");
  }
  RecordOutcome outcome;
  const double tod = be24(items.data(kTimeOfDay)) / 128.0;
  if (tod >= kSecondsPerDay) {
    return RecordOutcome::failed(ErrorReason::kValueOutOfRange, "I048/140 time of day past 24 h");
  }
  outcome.time_of_day = tod;
  if (items.has(kDescriptor)) {
    const std::uint8_t* d = items.data(kDescriptor);
    if ((d[0] >> 5) == 0) return RecordOutcome::dropped(DropReason::kNoDetection);
    out.simulated = (d[0] & 0x10u) != 0;
    out.fixed_transponder = (d[0] & 0x02u) != 0;
    out.test = items.size(kDescriptor) > 1 && (d[1] & 0x80u) != 0;
  }
  if (!items.has(kPolarPosition)) return RecordOutcome::dropped(DropReason::kNoPosition);
  read_polar(items.data(kPolarPosition), 256.0, out);
  if (items.has(kMode3a)) out.mode3a = read_mode3a(items.data(kMode3a));
  if (items.has(kFlightLevel)) {
    out.flight_level = read_flight_level(items.data(kFlightLevel), outcome.bad_flight_level);
  }
  if (items.has(kAircraftAddress)) out.mode_s = be24(items.data(kAircraftAddress));
  return outcome;
}

}  // namespace skytrack::asterix::detail
