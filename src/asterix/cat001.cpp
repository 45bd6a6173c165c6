// CAT001 monoradar plots and tracks (EUROCONTROL ASTERIX Part 2a, Category 001, ed. 1.1).
// I001/020 TYP selects the UAP (0 plot, 1 track); both carry the measured polar position
// I001/040 (RHO 1/128 NM, THETA 360/2^16 deg), which is what a track report's plot measured,
// so both give plots. I001/141 is the time of day truncated to 16 bits of 1/128 s.
#include "category_decoders.hpp"
#include "target_fields.hpp"
#include "uaps.hpp"

namespace skytrack::asterix::detail {

std::optional<bool> cat001_is_track(std::span<const std::uint8_t> block, std::size_t pos) {
  Fspec fspec;
  if (!read_fspec(block, pos, kCat001TrackUap, fspec).ok) return std::nullopt;
  if (((fspec.bits >> 2) & 1u) == 0) return std::nullopt;  // no I001/020
  std::size_t at = pos + fspec.length + (((fspec.bits >> 1) & 1u) ? 2 : 0);
  if (at >= block.size()) return std::nullopt;
  return (block[at] & 0x80u) != 0;
}

RecordOutcome decode_cat001(const RecordItems& items, bool track, TargetReport& out) noexcept {
  const int source = track ? cat001_track::kDataSource : cat001_plot::kDataSource;
  const int descriptor = track ? cat001_track::kDescriptor : cat001_plot::kDescriptor;
  const int position = track ? cat001_track::kPolarPosition : cat001_plot::kPolarPosition;
  const int mode3a = track ? cat001_track::kMode3a : cat001_plot::kMode3a;
  const int mode_c = track ? cat001_track::kModeC : cat001_plot::kModeC;
  const int time = track ? cat001_track::kTruncatedTime : cat001_plot::kTruncatedTime;
  if (!items.has(source)) {
    return RecordOutcome::failed(ErrorReason::kMissingItem, "no I001/010 data source");
  }
  out.category = 1;
  out.sensor = read_sensor(items.data(source));
  RecordOutcome outcome;
  if (items.has(descriptor)) {
    const std::uint8_t* d = items.data(descriptor);
    if (((d[0] >> 4) & 3u) == 0) return RecordOutcome::dropped(DropReason::kNoDetection);
    out.simulated = (d[0] & 0x40u) != 0;
    out.fixed_transponder = (d[0] & 0x02u) != 0;
    out.test = items.size(descriptor) > 1 && (d[1] & 0x80u) != 0;
  }
  if (!items.has(time)) {
    return RecordOutcome::failed(ErrorReason::kMissingItem, "no I001/141 truncated time");
  }
  outcome.truncated_time = be16(items.data(time)) / 128.0;
  if (!items.has(position)) return RecordOutcome::dropped(DropReason::kNoPosition);
  read_polar(items.data(position), 128.0, out);
  if (items.has(mode3a)) out.mode3a = read_mode3a(items.data(mode3a));
  if (items.has(mode_c)) {
    out.flight_level = read_flight_level(items.data(mode_c), outcome.bad_flight_level);
  }
  return outcome;
}

}  // namespace skytrack::asterix::detail
