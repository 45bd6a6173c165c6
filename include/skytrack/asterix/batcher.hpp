#pragma once
// Turns a radar's plots into batches (PlotScan) per sensor, the way the feed reports them:
//  - sector: closed by each north-marker / sector-crossing message; the batch covers the
//    sector swept since the previous one (absent when that is a whole turn, or unknown for the
//    first batch) and is timed by the message, when the antenna had reached the sector's end.
//    Plots that arrive after the message but lie just behind its azimuth and were measured by
//    its time (radars send a sector's last cells late) still join the batch it closed, which
//    is held until a plot measured `late` after the message arrives, or the next message.
//    A sensor that sends no such message within `marker_wait` of plot time is batched by
//    revolution instead, until one arrives.
//  - revolution: the plots' azimuths are unwrapped forward in time (the antenna turns
//    clockwise), a revolution ends when a plot is past north by `lead`; its time is the north
//    crossing of a least-squares fit of unwrapped azimuth against time.
//  - block:N: every N plots, timed by the latest plot, no coverage.
// Batch times never go backwards per sensor; scan numbers count up from 0 per sensor.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "skytrack/asterix/records.hpp"
#include "skytrack/core/expected.hpp"
#include "skytrack/core/plot.hpp"

namespace skytrack::asterix {

enum class BatchMode : std::uint8_t { kSector, kRevolution, kBlock };

struct BatchOptions {
  BatchMode mode = BatchMode::kSector;
  std::size_t block_plots = 0;  // kBlock
  double marker_wait = 20.0;    // [s] of plot time without a sector message -> revolution
  double lead = 0.1;            // [rad] past north before a revolution is closed
  double late = 0.1;            // [s] sector mode: how long a closed batch waits for late plots
};
/// "sector", "revolution" or "block:N" (N >= 1).
Expected<BatchOptions> parse_batch_mode(const std::string& text);
std::string to_string(const BatchOptions& options);

class Batcher {
 public:
  using ScanSink = std::function<void(PlotScan&& scan)>;
  Batcher(BatchOptions options, ScanSink sink);
  ~Batcher();
  Batcher(Batcher&&) noexcept;
  Batcher& operator=(Batcher&&) noexcept;

  void add(const TargetReport& report);
  void add(const ServiceMessage& message);
  /// Closes every open batch (end of the input).
  void finish();

  std::uint64_t batches() const { return batches_; }
  const BatchOptions& options() const { return options_; }
  /// The sensor's antenna rotation period: sent (I002/041, I034/041) or fitted.
  std::optional<double> rotation_period(std::uint32_t sensor) const;

 private:
  struct SensorState;
  SensorState& state(std::uint32_t sensor);
  void add_revolution(SensorState& s, Plot plot);
  /// Closes the open batch; `hold` keeps it for late plots (sector mode) until release().
  void close(SensorState& s, double time, std::optional<AzimuthSector> coverage, bool hold = false);
  void release(SensorState& s);
  bool late_for(const SensorState& s, const TargetReport& report) const;
  void close_revolution(SensorState& s, std::optional<double> next_time);

  BatchOptions options_;
  ScanSink sink_;
  std::vector<SensorState> sensors_;
  std::uint64_t batches_ = 0;
};

}  // namespace skytrack::asterix
