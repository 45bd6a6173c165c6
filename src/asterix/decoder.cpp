// Data blocks (CAT, LEN, records) of one datagram, each record walked by its category's UAP
// and read by the category decoders; the per-sensor clocks complete and continue times.
#include "skytrack/asterix/decoder.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "category_decoders.hpp"
#include "record_walker.hpp"
#include "sensor_clock.hpp"
#include "uaps.hpp"

namespace skytrack::asterix {

using namespace detail;

std::uint64_t DecodeCounters::total_errors() const {
  std::uint64_t n = 0;
  for (const auto v : errors) n += v;
  return n;
}
std::uint64_t DecodeCounters::total_dropped() const {
  std::uint64_t n = 0;
  for (const auto v : dropped) n += v;
  return n;
}

namespace {

/// FRNs each category decoder reads; the others present are counted as skipped.
constexpr std::uint64_t bits(std::initializer_list<int> frns) {
  std::uint64_t b = 0;
  for (const int f : frns) b |= 1ull << f;
  return b;
}
constexpr std::uint64_t kRead048 = bits({1, 2, 3, 4, 5, 6, 8});
constexpr std::uint64_t kRead001Plot = bits({1, 2, 3, 4, 5, 7});
constexpr std::uint64_t kRead001Track = bits({1, 2, 4, 7, 8, 9});
constexpr std::uint64_t kRead002 = bits({1, 2, 3, 4, 5});
constexpr std::uint64_t kRead034 = bits({1, 2, 3, 4, 5, 11});

}  // namespace

struct Decoder::Impl {
  DecoderOptions options;
  DecodeCounters counters;
  std::vector<SensorClock> clocks;  // few sensors: a linear search beats hashing
  RecordSink* sink = nullptr;
  Origin where;                     // of the datagram's first byte
  std::optional<double> reception;  // [s] time of day of the datagram

  SensorClock& clock_of(std::uint32_t sensor) {
    for (SensorClock& c : clocks) {
      if (c.sensor() == sensor) return c;
    }
    return clocks.emplace_back(sensor);
  }
  Origin at(std::size_t pos) const { return {where.offset + pos, where.datagram}; }

  void error(ErrorReason reason, std::uint8_t category, std::size_t pos, std::string detail) {
    ++counters.errors[static_cast<std::size_t>(reason)];
    sink->on_error(DecodeError{reason, category, at(pos), std::move(detail)});
  }
  void drop(DropReason reason) { ++counters.dropped[static_cast<std::size_t>(reason)]; }

  void block(std::uint8_t category, std::span<const std::uint8_t> data, std::size_t base);
  void target(const RecordItems& items, std::uint8_t category, bool track, std::size_t pos);
  void service(const RecordItems& items, std::uint8_t category, std::size_t pos);
};

void Decoder::Impl::block(std::uint8_t category, std::span<const std::uint8_t> data,
                          std::size_t base) {
  const Uap* uap = nullptr;
  std::uint64_t read = 0;
  switch (category) {
    case 48:
      uap = &kCat048Uap, read = kRead048;
      break;
    case 1:
      uap = &kCat001PlotUap, read = kRead001Plot;
      break;
    case 2:
      uap = &kCat002Uap, read = kRead002;
      break;
    case 34:
      uap = &kCat034Uap, read = kRead034;
      break;
    default:
      ++counters.unknown_category_blocks;
      return;
  }
  RecordItems items;
  std::size_t pos = 3;
  while (pos < data.size()) {
    ++counters.records_by_category[category];
    bool track = false;
    const Uap* record_uap = uap;
    if (category == 1) {
      track = cat001_is_track(data, pos).value_or(false);
      if (track)
        record_uap = &kCat001TrackUap, read = kRead001Track;
      else
        read = kRead001Plot;
    }
    if (data[pos] == 0) {  // an empty FSPEC: padding, or garbage; nothing after it is a record
      error(ErrorReason::kMissingItem, category, base + pos, "empty FSPEC");
      return;
    }
    const WalkResult walked = walk_record(data, pos, *record_uap, items);
    if (!walked.ok) {
      error(walked.error, category, base + walked.end,
            std::string(item_name(*record_uap, walked.frn)) + "; the rest of the block is skipped");
      return;
    }
    counters.items_skipped +=
        static_cast<std::uint64_t>(__builtin_popcountll(items.present & ~read));
    if (category == 1 || category == 48) {
      target(items, category, track, base + pos);
    } else {
      service(items, category, base + pos);
    }
    pos = walked.end;
  }
}

void Decoder::Impl::target(const RecordItems& items, std::uint8_t category, bool track,
                           std::size_t pos) {
  TargetReport report;
  report.where = at(pos);
  const RecordOutcome outcome =
      category == 48 ? decode_cat048(items, report) : decode_cat001(items, track, report);
  if (outcome.kind == RecordOutcome::Kind::kError) {
    error(outcome.error, category, pos, outcome.detail);
    return;
  }
  if (options.sensor && report.sensor != *options.sensor) return drop(DropReason::kOtherSensor);
  if (outcome.kind == RecordOutcome::Kind::kDropped) return drop(outcome.drop);
  SensorClock& clock = clock_of(report.sensor);
  if (outcome.time_of_day) {
    report.time = clock.continued(*outcome.time_of_day);
  } else if (const auto full = clock.complete(*outcome.truncated_time, reception)) {
    report.time = *full;
  } else {
    error(ErrorReason::kNoTimeReference, category, pos,
          "I001/141 before any CAT002 time, with no reception time");
    return;
  }
  if (outcome.bad_flight_level) {
    error(ErrorReason::kValueOutOfRange, category, pos,
          "flight level outside -15..1500; the plot is kept without it");
  }
  if (report.simulated && !options.keep_tests) return drop(DropReason::kSimulated);
  if (report.test && !options.keep_tests) return drop(DropReason::kTest);
  ++counters.plots;
  sink->on_report(report);
}

void Decoder::Impl::service(const RecordItems& items, std::uint8_t category, std::size_t pos) {
  ServiceMessage message;
  message.where = at(pos);
  const RecordOutcome outcome =
      category == 2 ? decode_cat002(items, message) : decode_cat034(items, message);
  if (outcome.kind == RecordOutcome::Kind::kError) {
    error(outcome.error, category, pos, outcome.detail);
    return;
  }
  if (options.sensor && message.sensor != *options.sensor) return drop(DropReason::kOtherSensor);
  SensorClock& clock = clock_of(message.sensor);
  if (outcome.time_of_day) {
    message.time = clock.continued(*outcome.time_of_day);
    if (category == 2) clock.set_reference(*message.time, reception);
  }
  ++counters.services[static_cast<std::size_t>(message.kind)];
  sink->on_service(message);
}

Decoder::Decoder(DecoderOptions options) : impl_(std::make_unique<Impl>()) {
  impl_->options = options;
}
Decoder::~Decoder() = default;
Decoder::Decoder(Decoder&&) noexcept = default;
Decoder& Decoder::operator=(Decoder&&) noexcept = default;
const DecodeCounters& Decoder::counters() const {
  return impl_->counters;
}
const DecoderOptions& Decoder::options() const {
  return impl_->options;
}

void Decoder::decode(std::span<const std::uint8_t> data, Origin where,
                     std::optional<double> reception_time, RecordSink& sink) noexcept {
  Impl& d = *impl_;
  d.sink = &sink;
  d.where = where;
  d.reception.reset();
  if (reception_time && std::isfinite(*reception_time) && *reception_time >= 0.0) {
    d.reception = std::fmod(*reception_time, kSecondsPerDay);
  }
  ++d.counters.datagrams;
  d.counters.bytes += data.size();
  std::size_t pos = 0;
  while (pos < data.size()) {
    if (data.size() - pos < 3) {
      d.error(ErrorReason::kTruncatedBlock, 0, pos,
              std::to_string(data.size() - pos) + " bytes left, a block header needs 3");
      return;
    }
    const std::uint8_t category = data[pos];
    const std::size_t length = be16(&data[pos + 1]);
    if (length < 4) {  // a header and at least one FSPEC octet
      d.error(ErrorReason::kBadBlockLength, category, pos,
              "LEN " + std::to_string(length) + "; the rest of the input is skipped");
      return;
    }
    if (pos + length > data.size()) {
      d.error(ErrorReason::kLengthPastEnd, category, pos,
              "LEN " + std::to_string(length) + ", " + std::to_string(data.size() - pos) +
                  " bytes left; the block is skipped");
      return;
    }
    ++d.counters.blocks;
    ++d.counters.blocks_by_category[category];
    d.block(category, data.subspan(pos, length), pos);
    pos += length;
  }
}

}  // namespace skytrack::asterix
