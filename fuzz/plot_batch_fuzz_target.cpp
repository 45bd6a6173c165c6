// Fuzz target: DDS PlotBatch samples built from the bytes, as a DDS reader hands them over
// (every sequence's length matches the memory behind it; the lengths may disagree with each
// other), through skytrack::dds::from_dds and, when converted, Pipeline::process. Up to
// kMaxBatches batches share one pipeline, so gating and association see earlier tracks.
// No DDS entity is created: nothing leaves the process.
//
// Input: one byte picks a profile variant; then per batch a control byte (bit 0: sensor,
// scan and time follow the previous batch; 1: platform state; 2: scan-level sigmas; 3:
// coverage; 4: lengths read from the input instead of made consistent; 5-7: transponder
// sequences present), the header, the plot count, and per plot a byte choosing raw doubles
// (any bit pattern: NaN, infinities, 1e308) or scaled 16-bit values (a radar's numbers).
#include <algorithm>
#include <span>
#include <vector>

#include "fuzz_support.hpp"
#include "fuzz_targets.hpp"
#include "skytrack/config/profile.hpp"
#include "skytrack/dds/conversion.hpp"
#include "skytrack/pipeline/pipeline.hpp"

namespace {

using skytrack::fuzz::FuzzInput;
namespace config = skytrack::config;
namespace sd = skytrack::dds;

constexpr int kMaxBatches = 4;
constexpr std::size_t kMaxPlots = 32;
constexpr std::size_t kStride = sd::kPlotStride;

/// The profiles the batches are tracked with: the defaults and a few departures from them.
const std::vector<config::TrackingProfile>& profiles() {
  static const std::vector<config::TrackingProfile> all = [] {
    config::TrackingProfile base;
    base.identity = {"fuzz", "1", "built-in defaults"};
    std::vector<config::TrackingProfile> out(7, base);
    out[1].association.method = config::AssociationMethod::kGnn;
    out[2].clutter_rejection.enabled = true;
    out[3].dimension = 3;
    out[4].point.track_life.confirmation = config::ConfirmationMethod::kMOfN;
    out[4].point.branching.enabled = false;
    out[5].antenna.rotation = config::AntennaRotation::kRotating;
    out[5].antenna.period = 4.0;
    out[6].association.clutter_density = 1e-9;
    out[6].association.clutter_map.enabled = false;
    return out;
  }();
  return all;
}

/// The sequences of one batch; the sample points into them.
struct Buffers {
  std::vector<std::int64_t> ids;
  std::vector<std::uint32_t> flags;
  std::vector<double> values;
  std::vector<std::int32_t> mode3a, mode_s;
  std::vector<double> flight_level;
};

template <class Seq, class T>
void point(Seq& seq, std::vector<T>& buffer) {
  seq._maximum = seq._length = static_cast<std::uint32_t>(buffer.size());
  seq._buffer = buffer.empty() ? nullptr : buffer.data();
  seq._release = false;
}

/// A value of plot value slot `k`: raw bits, or a 16-bit number at the slot's scale.
double plot_value(FuzzInput& in, bool raw, std::size_t k, double batch_time) {
  if (raw) return in.take<double>();
  const auto v = static_cast<double>(in.take<std::int16_t>());
  switch (k) {
    case sd::kPlotTime:
      return batch_time + 1e-3 * v;
    case sd::kPlotRange:
      return 4.0 * (v + 32768.0);
    case sd::kPlotAzimuth:
      return 1e-4 * v;
    case sd::kPlotElevation:
      return 2e-5 * v;
    case sd::kPlotX:
    case sd::kPlotY:
      return 10.0 * v;
    case sd::kPlotZ:
      return v;
    default:
      return k >= sd::kPlotSigmaRange ? 1e-3 * v : 0.01 * v;
  }
}

void fill_plots(FuzzInput& in, std::uint8_t control, double time, Buffers& b) {
  std::size_t n = in.byte() % (kMaxPlots + 1);
  std::size_t n_flags = n, n_values = n * kStride;
  std::size_t n_transponder[3] = {control & 0x20 ? n : 0, control & 0x40 ? n : 0,
                                  control & 0x80 ? n : 0};
  if (control & 0x10) {  // lengths of the input's choosing, each with its buffer
    n_flags = in.byte() % (kMaxPlots + 1);
    n_values = in.take<std::uint16_t>() % ((kMaxPlots + 1) * kStride);
    for (std::size_t& t : n_transponder) t = in.byte() % (kMaxPlots + 1);
  }
  b.ids.assign(n, 0);
  b.flags.assign(n_flags, 0);
  b.values.assign(n_values, 0.0);
  for (std::size_t i = 0; i < std::max({n, n_flags, n_values / kStride}); ++i) {
    const bool raw = (in.byte() & 1) != 0;
    if (i < n) b.ids[i] = raw ? in.take<std::int64_t>() : in.byte();
    if (i < n_flags) b.flags[i] = in.take<std::uint32_t>();
    for (std::size_t k = 0; k < kStride && i * kStride + k < n_values; ++k) {
      b.values[i * kStride + k] = plot_value(in, raw, k, time);
    }
  }
  b.mode3a.assign(n_transponder[0], 0);
  b.mode_s.assign(n_transponder[1], 0);
  b.flight_level.assign(n_transponder[2], 0.0);
  for (auto& v : b.mode3a) v = in.take<std::int16_t>();
  for (auto& v : b.mode_s) v = in.take<std::int32_t>();
  for (auto& v : b.flight_level) v = 0.1 * in.take<std::int16_t>();
}

/// The next batch from the input; `last` holds the previous batch's sensor, scan and time.
void build_batch(FuzzInput& in, skytrack_dds_PlotBatch& s, Buffers& b,
                 const skytrack_dds_PlotBatch& last) {
  s = skytrack_dds_PlotBatch{};
  const std::uint8_t control = in.byte();
  if (control & 0x01) {
    s.sensor = last.sensor;
    s.scan = last.scan + 1;
    s.time = last.time + 0.25 * in.byte();
  } else {
    s.sensor = in.take<std::uint32_t>();
    s.scan = in.take<std::uint64_t>();
    s.time = in.take<double>();
  }
  if (control & 0x02) {
    for (double& v : s.platform_position) v = in.take<double>();
    for (double& v : s.platform_velocity) v = in.take<double>();
    for (double& v : s.platform_attitude) v = in.take<double>();
  }
  if (control & 0x04) {
    for (double& v : s.sigma) v = in.take<double>();
    s.sigma_flags = in.take<std::uint32_t>();
  }
  if (control & 0x08) {
    s.has_coverage = true;
    s.coverage[0] = in.take<double>();
    s.coverage[1] = in.take<double>();
  }
  fill_plots(in, control, s.time, b);
  point(s.plot_ids, b.ids);
  point(s.plot_flags, b.flags);
  point(s.plot_values, b.values);
  point(s.plot_mode3a, b.mode3a);
  point(s.plot_mode_s, b.mode_s);
  point(s.plot_flight_level, b.flight_level);
}

}  // namespace

int skytrack_plot_batch_fuzz_one(const std::uint8_t* data, std::size_t size) {
  FuzzInput in(std::span<const std::uint8_t>(data, size));
  const auto& variants = profiles();
  auto pipeline = skytrack::Pipeline::create(variants[in.byte() % variants.size()]);
  SKYTRACK_FUZZ_CHECK(pipeline.has_value());
  skytrack_dds_PlotBatch sample{}, last{};
  Buffers buffers;
  skytrack::PlotScan scan;
  std::uint64_t processed = 0;
  for (int k = 0; k < kMaxBatches && !in.empty(); ++k) {
    build_batch(in, sample, buffers, last);
    last = sample;
    if (!sd::from_dds(sample, scan)) continue;
    SKYTRACK_FUZZ_CHECK(scan.plots.size() == sample.plot_ids._length);
    const skytrack::ScanResult& result = pipeline->process(scan);
    ++processed;
    SKYTRACK_FUZZ_CHECK(result.accepted != !result.rejection.empty());
    const skytrack::PipelineCounters& c = pipeline->counters();
    SKYTRACK_FUZZ_CHECK(c.scans_processed + c.scans_rejected == processed);
  }
  return 0;
}
