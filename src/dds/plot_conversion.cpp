// PlotScan <-> PlotBatch: plots travel as flat values with a presence bit mask per plot.
#include "skytrack/dds/conversion.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "sequence_helpers.hpp"

namespace skytrack::dds {
namespace {

using namespace detail;

// ---- plots ----------------------------------------------------------------------------------

void put_sigma(const MeasurementSigma& sigma, double* values, std::uint32_t& flags,
               std::uint32_t first_bit) {
  const std::optional<double>* items[] = {&sigma.range,      &sigma.azimuth, &sigma.elevation,
                                          &sigma.range_rate, &sigma.x,       &sigma.y,
                                          &sigma.z};
  for (std::uint32_t i = 0; i < 7; ++i) {
    if (*items[i]) {
      values[i] = **items[i];
      flags |= 1u << (first_bit + i);
    } else {
      values[i] = 0.0;
    }
  }
}

MeasurementSigma get_sigma(const double* values, std::uint32_t flags, std::uint32_t first_bit) {
  MeasurementSigma sigma;
  std::optional<double>* items[] = {&sigma.range,      &sigma.azimuth, &sigma.elevation,
                                    &sigma.range_rate, &sigma.x,       &sigma.y,
                                    &sigma.z};
  for (std::uint32_t i = 0; i < 7; ++i) {
    if (flags & (1u << (first_bit + i))) *items[i] = values[i];
  }
  return sigma;
}

std::uint32_t encode_plot(const Plot& plot, double* v) {
  std::uint32_t flags = 0;
  std::fill_n(v, kPlotSigmaRange, 0.0);
  const auto put = [&](PlotValue index, double value) {
    v[index] = value;
    flags |= 1u << index;
  };
  const auto put_optional = [&](PlotValue index, const std::optional<double>& value) {
    if (value) put(index, *value);
  };
  if (plot.form == PlotForm::kCartesian) {
    flags |= kPlotFlagCartesian;
    put(kPlotX, plot.x);
    put(kPlotY, plot.y);
  } else {
    put(kPlotRange, plot.range);
    put(kPlotAzimuth, plot.azimuth);
  }
  put_optional(kPlotTime, plot.time);
  put_optional(kPlotElevation, plot.elevation);
  put_optional(kPlotRangeRate, plot.range_rate);
  put_optional(kPlotZ, plot.z);
  put_optional(kPlotSnrDb, plot.snr_db);
  put_optional(kPlotAmplitude, plot.amplitude);
  put_sigma(plot.sigma, v + kPlotSigmaRange, flags, kPlotSigmaRange);
  return flags;
}

Plot decode_plot(std::int64_t id, std::uint32_t flags, const double* v) {
  const auto has = [flags](PlotValue index) { return (flags & (1u << index)) != 0; };
  const auto get = [&](PlotValue index) {
    return has(index) ? std::optional<double>(v[index]) : std::nullopt;
  };
  const auto required = [&](PlotValue index) { return has(index) ? v[index] : kNaN; };
  Plot plot;
  plot.id = id;
  if (flags & kPlotFlagCartesian) {
    plot.form = PlotForm::kCartesian;
    plot.x = required(kPlotX);
    plot.y = required(kPlotY);
  } else {
    plot.form = PlotForm::kPolar;
    plot.range = required(kPlotRange);
    plot.azimuth = required(kPlotAzimuth);
  }
  plot.time = get(kPlotTime);
  plot.elevation = get(kPlotElevation);
  plot.range_rate = get(kPlotRangeRate);
  plot.z = get(kPlotZ);
  plot.snr_db = get(kPlotSnrDb);
  plot.amplitude = get(kPlotAmplitude);
  plot.sigma = get_sigma(v + kPlotSigmaRange, flags, kPlotSigmaRange);
  return plot;
}

}  // namespace

// ---- PlotScan <-> PlotBatch -----------------------------------------------------------------

Expected<void> to_dds(const PlotScan& scan, PlotBatchSample& out) {
  const std::size_t n = scan.plots.size();
  if (n > kMaxSequence / kPlotStride) {
    return make_error("PlotScan.plots: " + std::to_string(n) + " plots do not fit a PlotBatch");
  }
  skytrack_dds_PlotBatch& b = out.get();
  b.sensor = scan.sensor;
  b.scan = scan.scan;
  b.time = scan.time;
  copy3(scan.platform.position, b.platform_position);
  copy3(scan.platform.velocity, b.platform_velocity);
  copy3(scan.platform.attitude, b.platform_attitude);
  b.sigma_flags = 0;
  put_sigma(scan.sigma, b.sigma, b.sigma_flags, 0);
  b.has_coverage = scan.coverage.has_value();
  b.coverage[0] = scan.coverage ? scan.coverage->from : 0.0;
  b.coverage[1] = scan.coverage ? scan.coverage->to : 0.0;
  if (!reserve_primitive(b.plot_ids, n) || !reserve_primitive(b.plot_flags, n) ||
      !reserve_primitive(b.plot_values, n * kPlotStride)) {
    return unexpected(out_of_memory("PlotBatch.plot_values"));
  }
  double* values = b.plot_values._buffer;
  for (std::size_t i = 0; i < n; ++i, values += kPlotStride) {
    b.plot_ids._buffer[i] = scan.plots[i].id;
    b.plot_flags._buffer[i] = encode_plot(scan.plots[i], values);
  }
  return {};
}

Expected<PlotBatchSample> to_dds(const PlotScan& scan) {
  PlotBatchSample out;
  if (auto ok = to_dds(scan, out); !ok) return unexpected(ok.error());
  return out;
}

Expected<void> from_dds(const skytrack_dds_PlotBatch& batch, PlotScan& out) {
  const std::uint64_t n = batch.plot_ids._length;
  if (auto e = missing_buffer(batch.plot_ids, "PlotBatch.plot_ids")) return unexpected(*e);
  if (auto e = missing_buffer(batch.plot_flags, "PlotBatch.plot_flags")) return unexpected(*e);
  if (auto e = missing_buffer(batch.plot_values, "PlotBatch.plot_values")) return unexpected(*e);
  if (batch.plot_flags._length != n) {
    return make_error("PlotBatch.plot_flags: length " + std::to_string(batch.plot_flags._length) +
                      ", expected " + std::to_string(n) + " (plot_ids length)");
  }
  if (batch.plot_values._length != n * kPlotStride) {
    return make_error("PlotBatch.plot_values: length " + std::to_string(batch.plot_values._length) +
                      ", expected " + std::to_string(n * kPlotStride) +
                      " (plot_ids length * PLOT_STRIDE)");
  }
  out.sensor = batch.sensor;
  out.scan = batch.scan;
  out.time = batch.time;
  out.platform.position = vector3(batch.platform_position);
  out.platform.velocity = vector3(batch.platform_velocity);
  out.platform.attitude = vector3(batch.platform_attitude);
  out.sigma = get_sigma(batch.sigma, batch.sigma_flags, 0);
  out.coverage.reset();
  if (batch.has_coverage) out.coverage = AzimuthSector{batch.coverage[0], batch.coverage[1]};
  out.plots.clear();
  out.plots.reserve(n);
  const double* values = batch.plot_values._buffer;
  for (std::uint64_t i = 0; i < n; ++i, values += kPlotStride) {
    out.plots.push_back(
        decode_plot(batch.plot_ids._buffer[i], batch.plot_flags._buffer[i], values));
  }
  return {};
}

Expected<PlotScan> from_dds(const skytrack_dds_PlotBatch& batch) {
  PlotScan out;
  if (auto ok = from_dds(batch, out); !ok) return unexpected(ok.error());
  return out;
}

}  // namespace skytrack::dds
