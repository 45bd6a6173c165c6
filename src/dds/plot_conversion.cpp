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
#include "skytrack/core/transponder.hpp"

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

/// The transponder attributes as parallel sequences, each left empty when no plot has it.
Expected<void> put_transponder(const std::vector<Plot>& plots, skytrack_dds_PlotBatch& b) {
  const std::size_t n = plots.size();
  const auto any = [&](auto member) {
    return std::any_of(plots.begin(), plots.end(),
                       [&](const Plot& p) { return (p.*member).has_value(); });
  };
  const std::size_t n3a = any(&Plot::mode3a) ? n : 0, ns = any(&Plot::mode_s) ? n : 0,
                    nfl = any(&Plot::flight_level) ? n : 0;
  if (!reserve_primitive(b.plot_mode3a, n3a) || !reserve_primitive(b.plot_mode_s, ns) ||
      !reserve_primitive(b.plot_flight_level, nfl)) {
    return unexpected(out_of_memory("PlotBatch.plot_mode3a"));
  }
  for (std::size_t i = 0; i < n3a; ++i)
    b.plot_mode3a._buffer[i] = plots[i].mode3a ? *plots[i].mode3a : -1;
  for (std::size_t i = 0; i < ns; ++i) {
    b.plot_mode_s._buffer[i] = plots[i].mode_s ? static_cast<std::int32_t>(*plots[i].mode_s) : -1;
  }
  for (std::size_t i = 0; i < nfl; ++i)
    b.plot_flight_level._buffer[i] = plots[i].flight_level.value_or(kNaN);
  return {};
}

/// Reads the transponder sequences back; a sequence of the wrong length or a value out of
/// range is an error naming the field.
Expected<void> get_transponder(const skytrack_dds_PlotBatch& b, std::vector<Plot>& plots) {
  const std::size_t n = plots.size();
  const auto length_ok = [n](std::uint32_t length) { return length == 0 || length == n; };
  if (!length_ok(b.plot_mode3a._length) || !length_ok(b.plot_mode_s._length) ||
      !length_ok(b.plot_flight_level._length)) {
    return make_error("PlotBatch transponder sequences: length neither 0 nor " + std::to_string(n));
  }
  if (auto e = missing_buffer(b.plot_mode3a, "PlotBatch.plot_mode3a")) return unexpected(*e);
  if (auto e = missing_buffer(b.plot_mode_s, "PlotBatch.plot_mode_s")) return unexpected(*e);
  if (auto e = missing_buffer(b.plot_flight_level, "PlotBatch.plot_flight_level")) {
    return unexpected(*e);
  }
  for (std::size_t i = 0; i < b.plot_mode3a._length; ++i) {
    const std::int32_t v = b.plot_mode3a._buffer[i];
    if (v < -1 || v > kMaxMode3a)
      return make_error("PlotBatch.plot_mode3a[" + std::to_string(i) + "]: out of range");
    if (v >= 0) plots[i].mode3a = static_cast<std::uint16_t>(v);
  }
  for (std::size_t i = 0; i < b.plot_mode_s._length; ++i) {
    const std::int32_t v = b.plot_mode_s._buffer[i];
    if (v < -1 || v > static_cast<std::int32_t>(kMaxModeS)) {
      return make_error("PlotBatch.plot_mode_s[" + std::to_string(i) + "]: out of range");
    }
    if (v >= 0) plots[i].mode_s = static_cast<std::uint32_t>(v);
  }
  for (std::size_t i = 0; i < b.plot_flight_level._length; ++i) {
    const double v = b.plot_flight_level._buffer[i];
    if (!std::isnan(v)) plots[i].flight_level = v;
  }
  return {};
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
  return put_transponder(scan.plots, b);
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
  return get_transponder(batch, out.plots);
}

Expected<PlotScan> from_dds(const skytrack_dds_PlotBatch& batch) {
  PlotScan out;
  if (auto ok = from_dds(batch, out); !ok) return unexpected(ok.error());
  return out;
}

}  // namespace skytrack::dds
