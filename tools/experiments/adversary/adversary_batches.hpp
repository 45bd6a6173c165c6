#pragma once
// The adversary's batches, generated: plot clouds (N plots within the sensor's noise of one
// point: chaff, a jammer's false plots, a dense swarm), plots spread over the flooded sector
// (bursts and huge batches), and malformed samples, each a different way a broken radar or a
// hostile writer on the domain can get a PlotBatch wrong. Every batch carries the sector as
// its coverage and is numbered after the adversary's latest valid batch. Seeded: the same
// seed gives the same batches.
#include <cstdint>
#include <random>
#include <string_view>

#include "adversary_geometry.hpp"
#include "skytrack/dds/conversion.hpp"

namespace skytrack::adversary {

/// The ways a sample is made malformed, in the order the malformed phase cycles through them.
enum class Malformation : std::uint8_t {
  kShortFlags,        // plot_flags one shorter than plot_ids (the end-to-end test's)
  kShortValues,       // plot_values not plot_ids x PLOT_STRIDE
  kShortTransponder,  // plot_mode3a neither empty nor one per plot
  kNanPlots,          // NaN range, azimuth, elevation in some plots
  kInfPlots,          // infinite range
  kAbsurdRange,       // a finite range of 5e22 m (beyond max_range)
  kNanTime,           // NaN batch time
  kNanPlatform,       // NaN platform position
  kFarFuture,         // dated 50 years ahead, once
  kOutOfOrder,        // the scan number before the latest valid one
  kDuplicate,         // the latest valid scan number again
  kCount
};
std::string_view to_string(Malformation kind);

inline constexpr double kFiftyYears = 50.0 * 365.25 * 86400.0;  // [s]

class AdversaryBatches {
 public:
  AdversaryBatches(const AdversaryGeometry& geometry, std::uint32_t sensor, std::uint64_t seed);

  /// `plots` plots round the cloud's centre, each off it by the sensor's own noise.
  PlotScan cloud(double time, int plots);
  /// `plots` plots uniform over the sector between range_min and range_max.
  PlotScan spread(double time, int plots);
  /// A sample malformed as `kind`, for a batch at `time` (a valid one must have gone before
  /// for kOutOfOrder and kDuplicate to mean what they say).
  Expected<dds::PlotBatchSample> malformed(Malformation kind, double time);

  /// Scan numbers: a valid batch takes the next; the latest valid one.
  std::uint64_t latest_scan() const { return next_scan_ == 0 ? 0 : next_scan_ - 1; }

 private:
  /// An empty batch from the site, numbered `scan`, covering the sector.
  PlotScan base(double time, std::uint64_t scan) const;
  Plot polar(std::int64_t id, double range, double azimuth, double elevation);

  AdversaryGeometry geometry_;
  std::uint32_t sensor_;
  std::mt19937_64 rng_;
  std::uint64_t next_scan_ = 0;
};

}  // namespace skytrack::adversary
