#include "adversary_batches.hpp"

#include <array>
#include <cmath>
#include <limits>

#include "skytrack/geometry/angles.hpp"

namespace skytrack::adversary {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

// Noise of the adversary's plots when the good sensor's batches name none.
constexpr double kRangeSigma = 30.0;     // [m]
constexpr double kAzimuthSigma = 0.002;  // [rad]
constexpr double kElevationSigma = 0.003;
constexpr double kRangeRateSigma = 2.0;  // [m/s]

}  // namespace

std::string_view to_string(Malformation kind) {
  static constexpr std::array<std::string_view, static_cast<std::size_t>(Malformation::kCount)>
      kNames{"plot_flags shorter than plot_ids",
             "plot_values not plot_ids x PLOT_STRIDE",
             "plot_mode3a one short",
             "NaN range, azimuth, elevation",
             "infinite range",
             "range 5e22 m",
             "NaN batch time",
             "NaN platform position",
             "time 50 years ahead",
             "out-of-order scan number",
             "duplicate scan number"};
  const auto i = static_cast<std::size_t>(kind);
  return i < kNames.size() ? kNames[i] : "?";
}

AdversaryBatches::AdversaryBatches(const AdversaryGeometry& geometry, std::uint32_t sensor,
                                   std::uint64_t seed)
    : geometry_(geometry), sensor_(sensor), rng_(seed) {}

PlotScan AdversaryBatches::base(double time, std::uint64_t scan) const {
  PlotScan s;
  s.sensor = sensor_;
  s.scan = scan;
  s.time = time;
  s.platform = geometry_.site;
  s.sigma = geometry_.sigma;
  s.coverage = geometry_.sector;
  return s;
}

Plot AdversaryBatches::polar(std::int64_t id, double range, double azimuth, double elevation) {
  Plot p;
  p.id = id;
  p.range = range;
  p.azimuth = azimuth;
  if (geometry_.elevation) p.elevation = elevation;
  if (geometry_.range_rate) {
    std::normal_distribution<double> rr(0.0, geometry_.sigma.range_rate.value_or(kRangeRateSigma));
    p.range_rate = rr(rng_);
  }
  return p;
}

PlotScan AdversaryBatches::cloud(double time, int plots) {
  PlotScan s = base(time, next_scan_++);
  std::normal_distribution<double> range(geometry_.cloud_range,
                                         geometry_.sigma.range.value_or(kRangeSigma));
  std::normal_distribution<double> azimuth(geometry_.centre_azimuth(),
                                           geometry_.sigma.azimuth.value_or(kAzimuthSigma));
  std::normal_distribution<double> elevation(geometry_.cloud_elevation,
                                             geometry_.sigma.elevation.value_or(kElevationSigma));
  s.plots.reserve(static_cast<std::size_t>(plots));
  for (int k = 0; k < plots; ++k) {
    const double r = range(rng_), a = azimuth(rng_), e = elevation(rng_);
    s.plots.push_back(polar(k, r, wrap_angle(a), e));
  }
  return s;
}

PlotScan AdversaryBatches::spread(double time, int plots) {
  PlotScan s = base(time, next_scan_++);
  std::uniform_real_distribution<double> range(geometry_.range_min, geometry_.range_max);
  std::uniform_real_distribution<double> azimuth(
      geometry_.sector.from,
      geometry_.sector.from + wrap_angle_positive(geometry_.sector.to - geometry_.sector.from));
  std::uniform_real_distribution<double> elevation(0.0, 0.05);
  s.plots.reserve(static_cast<std::size_t>(plots));
  for (int k = 0; k < plots; ++k) {
    const double r = range(rng_), a = azimuth(rng_), e = elevation(rng_);
    s.plots.push_back(polar(k, r, wrap_angle(a), e));
  }
  return s;
}

Expected<dds::PlotBatchSample> AdversaryBatches::malformed(Malformation kind, double time) {
  // Numbered as the next valid batch unless the malformation is the number itself.
  std::uint64_t scan = next_scan_;
  if (kind == Malformation::kOutOfOrder) scan = latest_scan() > 0 ? latest_scan() - 1 : 0;
  if (kind == Malformation::kDuplicate) scan = latest_scan();
  PlotScan s = spread(time, 6);
  --next_scan_;  // spread() took a number that this sample may not
  s.scan = scan;
  switch (kind) {
    case Malformation::kShortTransponder:
      for (Plot& p : s.plots) p.mode3a = 01200;
      break;
    case Malformation::kNanPlots:
      s.plots[0].range = kNan;
      s.plots[1].azimuth = kNan;
      if (geometry_.elevation) s.plots[2].elevation = kNan;
      break;
    case Malformation::kInfPlots:
      s.plots[0].range = std::numeric_limits<double>::infinity();
      break;
    case Malformation::kAbsurdRange:
      s.plots[0].range = 5e22;
      break;
    case Malformation::kNanTime:
      s.time = kNan;
      break;
    case Malformation::kNanPlatform:
      s.platform.position.x() = kNan;
      break;
    case Malformation::kFarFuture:
      s.time += kFiftyYears;
      break;
    default:
      break;
  }
  // Bad plots inside an otherwise good batch leave the batch valid: it takes its number.
  if (kind == Malformation::kNanPlots || kind == Malformation::kInfPlots ||
      kind == Malformation::kAbsurdRange) {
    ++next_scan_;
  }
  dds::PlotBatchSample sample;
  if (auto ok = dds::to_dds(s, sample); !ok) return unexpected(ok.error());
  auto& b = sample.get();
  if (kind == Malformation::kShortFlags) b.plot_flags._length -= 1;
  if (kind == Malformation::kShortValues) b.plot_values._length -= 5;
  if (kind == Malformation::kShortTransponder) b.plot_mode3a._length -= 1;
  return sample;
}

}  // namespace skytrack::adversary
