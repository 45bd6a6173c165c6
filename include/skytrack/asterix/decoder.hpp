#pragma once
// ASTERIX decoder for monoradar data: CAT048 and CAT001 target reports (plots), CAT002 and
// CAT034 service messages, written to the EUROCONTROL category specifications (CAT001 ed. 1.1,
// CAT002 ed. 1.0, CAT034 ed. 1.2x, CAT048 ed. 1.2x). Other categories, and items that are not
// interpreted, are skipped by their length and counted. Bad input (truncated blocks, a LEN past
// the end, an endless FSPEC, repetitions past the end, values out of range) is reported with
// its origin, counted by reason and skipped; the rest of the datagram is decoded where the
// structure allows. Nothing here throws or allocates per record in the normal case.
//
// The decoder is stateful per sensor: times of day continue past midnight, and the CAT001
// truncated time of day (I001/141, 1/128 s modulo 512 s) is completed from the sensor's latest
// CAT002 time of day, else from the datagram's reception time.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>

#include "skytrack/asterix/records.hpp"

namespace skytrack::asterix {

struct DecoderOptions {
  bool keep_tests = false;              // give out SIM and TST reports too
  std::optional<std::uint32_t> sensor;  // only this SAC * 256 + SIC
};

struct DecodeCounters {
  std::uint64_t bytes = 0;
  std::uint64_t datagrams = 0;
  std::uint64_t blocks = 0;
  std::array<std::uint64_t, 256> blocks_by_category{};
  std::array<std::uint64_t, 256> records_by_category{};  // records read (decoded or not)
  std::uint64_t unknown_category_blocks = 0;             // skipped by LEN
  std::uint64_t items_skipped = 0;                       // present, not interpreted
  std::uint64_t plots = 0;                               // target reports given out
  std::array<std::uint64_t, 4> services{};               // by ServiceKind
  std::array<std::uint64_t, static_cast<std::size_t>(DropReason::kCount)> dropped{};
  std::array<std::uint64_t, static_cast<std::size_t>(ErrorReason::kCount)> errors{};

  std::uint64_t total_errors() const;
  std::uint64_t total_dropped() const;
};

/// Receives what the decoder finds, in input order.
class RecordSink {
 public:
  virtual ~RecordSink() = default;
  virtual void on_report(const TargetReport& report) = 0;
  virtual void on_service(const ServiceMessage& message) = 0;
  virtual void on_error(const DecodeError& error) = 0;
};

class Decoder {
 public:
  explicit Decoder(DecoderOptions options = {});
  ~Decoder();
  Decoder(Decoder&&) noexcept;
  Decoder& operator=(Decoder&&) noexcept;
  Decoder(const Decoder&) = delete;
  Decoder& operator=(const Decoder&) = delete;

  /// Decodes the data blocks of one datagram (or one block of a raw file). `where` is the
  /// origin of data[0]; `reception_time` [s] (a capture time stamp: seconds since the epoch or
  /// of the day) completes CAT001 truncated times when no CAT002 time is known yet.
  void decode(std::span<const std::uint8_t> data, Origin where,
              std::optional<double> reception_time, RecordSink& sink) noexcept;

  const DecodeCounters& counters() const;
  const DecoderOptions& options() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace skytrack::asterix
