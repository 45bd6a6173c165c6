// Plot stream lines (CONTRACTS.md §1). A structurally bad line is rejected whole; a bad plot
// (neither or both forms, non-finite or negative range, duplicate id) is dropped with a
// reason and the scan's other plots are kept.
#include <string>
#include <unordered_set>

#include "json_fields.hpp"
#include "json_parser.hpp"
#include "skytrack/core/transponder.hpp"
#include "skytrack/io/jsonl_reader.hpp"

namespace skytrack::io {
namespace {

using namespace detail;

Expected<MeasurementSigma> parse_sigma(const element& value, const std::string& path) {
  auto obj = as_object(value, path);
  if (!obj) return unexpected(obj.error());
  MeasurementSigma sigma;
  const auto positive = [](const element& v, const std::string& p) -> Expected<double> {
    auto number = as_finite(v, p);
    if (number && !(*number > 0.0)) return make_error(p + ": must be positive");
    return number;
  };
  struct Slot {
    const char* key;
    std::optional<double> MeasurementSigma::*member;
  };
  static constexpr Slot kSlots[] = {{"range", &MeasurementSigma::range},
                                    {"azimuth", &MeasurementSigma::azimuth},
                                    {"elevation", &MeasurementSigma::elevation},
                                    {"range_rate", &MeasurementSigma::range_rate},
                                    {"x", &MeasurementSigma::x},
                                    {"y", &MeasurementSigma::y},
                                    {"z", &MeasurementSigma::z}};
  for (const Slot& slot : kSlots) {
    auto number = optional_field<double>(*obj, path, slot.key, positive);
    if (!number) return unexpected(number.error());
    sigma.*slot.member = *number;
  }
  return sigma;
}

Expected<PlatformState> parse_platform(const element& value) {
  auto obj = as_object(value, "platform");
  if (!obj) return unexpected(obj.error());
  PlatformState platform;
  const auto vec = [](const element& v, const std::string& p) { return as_vector23(v, p); };
  const auto vec3 = [](const element& v, const std::string& p) -> Expected<Eigen::Vector3d> {
    int dims = 0;
    auto out = as_vector23(v, p, &dims);
    if (out && dims != 3) return make_error(p + ": expected 3 numbers");
    return out;
  };
  auto position = optional_field<Eigen::Vector3d>(*obj, "platform", "position", vec);
  if (!position) return unexpected(position.error());
  auto velocity = optional_field<Eigen::Vector3d>(*obj, "platform", "velocity", vec);
  if (!velocity) return unexpected(velocity.error());
  auto attitude = optional_field<Eigen::Vector3d>(*obj, "platform", "attitude", vec3);
  if (!attitude) return unexpected(attitude.error());
  if (*position) platform.position = **position;
  if (*velocity) platform.velocity = **velocity;
  if (*attitude) platform.attitude = **attitude;
  return platform;
}

/// The optional transponder attributes: mode3a (4 octal digits), mode_s (6 hex digits),
/// flight_level (a number of flight levels a transponder can report).
Expected<void> parse_transponder(const simdjson::dom::object& obj, const std::string& path,
                                 Plot& plot) {
  auto mode3a = optional_field<std::string_view>(obj, path, "mode3a", as_string);
  if (!mode3a) return unexpected(mode3a.error());
  if (*mode3a) {
    plot.mode3a = parse_mode3a(**mode3a);
    if (!plot.mode3a) return make_error(join(path, "mode3a") + ": expected 4 octal digits");
  }
  auto mode_s = optional_field<std::string_view>(obj, path, "mode_s", as_string);
  if (!mode_s) return unexpected(mode_s.error());
  if (*mode_s) {
    plot.mode_s = parse_mode_s(**mode_s);
    if (!plot.mode_s) return make_error(join(path, "mode_s") + ": expected 6 hex digits");
  }
  auto level = optional_field<double>(obj, path, "flight_level", as_finite);
  if (!level) return unexpected(level.error());
  if (*level && !plausible_flight_level(**level)) {
    return make_error(join(path, "flight_level") + ": outside -15 to 1500");
  }
  plot.flight_level = *level;
  return {};
}

Expected<Plot> parse_plot(const element& value, const std::string& path) {
  auto obj = as_object(value, path);
  if (!obj) return unexpected(obj.error());
  Plot plot;
  auto id = required<std::int64_t>(*obj, path, "id", as_integer);
  if (!id) return unexpected(id.error());
  plot.id = *id;

  const bool polar = field(*obj, "range") || field(*obj, "azimuth");
  const bool cartesian = field(*obj, "x") || field(*obj, "y");
  if (polar && cartesian) return make_error(path + ": has both polar and Cartesian fields");
  if (!polar && !cartesian) return make_error(path + ": has neither range/azimuth nor x/y");

  auto time = optional_field<double>(*obj, path, "time", as_finite);
  if (!time) return unexpected(time.error());
  plot.time = *time;
  if (polar) {
    plot.form = PlotForm::kPolar;
    auto range = required<double>(*obj, path, "range", as_finite);
    if (!range) return unexpected(range.error());
    if (*range < 0.0) return make_error(join(path, "range") + ": negative");
    auto azimuth = required<double>(*obj, path, "azimuth", as_finite);
    if (!azimuth) return unexpected(azimuth.error());
    auto elevation = optional_field<double>(*obj, path, "elevation", as_finite);
    if (!elevation) return unexpected(elevation.error());
    auto range_rate = optional_field<double>(*obj, path, "range_rate", as_finite);
    if (!range_rate) return unexpected(range_rate.error());
    plot.range = *range;
    plot.azimuth = *azimuth;
    plot.elevation = *elevation;
    plot.range_rate = *range_rate;
  } else {
    plot.form = PlotForm::kCartesian;
    auto x = required<double>(*obj, path, "x", as_finite);
    if (!x) return unexpected(x.error());
    auto y = required<double>(*obj, path, "y", as_finite);
    if (!y) return unexpected(y.error());
    auto z = optional_field<double>(*obj, path, "z", as_finite);
    if (!z) return unexpected(z.error());
    plot.x = *x;
    plot.y = *y;
    plot.z = *z;
  }
  auto snr = optional_field<double>(*obj, path, "snr_db", as_finite);
  if (!snr) return unexpected(snr.error());
  auto amplitude = optional_field<double>(*obj, path, "amplitude", as_finite);
  if (!amplitude) return unexpected(amplitude.error());
  plot.snr_db = *snr;
  plot.amplitude = *amplitude;
  if (auto ok = parse_transponder(*obj, path, plot); !ok) return unexpected(ok.error());
  if (const auto sigma = field(*obj, "sigma")) {
    auto parsed = parse_sigma(*sigma, join(path, "sigma"));
    if (!parsed) return unexpected(parsed.error());
    plot.sigma = *parsed;
  }
  return plot;
}

}  // namespace

Expected<ParsedPlotScan> parse_plot_scan(const element& root) {
  auto obj = as_object(root, "line");
  if (!obj) return unexpected(obj.error());
  ParsedPlotScan out;
  PlotScan& scan = out.scan;

  auto sensor = required<std::int64_t>(*obj, "", "sensor", as_integer);
  if (!sensor) return unexpected(sensor.error());
  if (*sensor < 0 || *sensor > 0xFFFFFFFFLL) return make_error("sensor: out of range");
  auto number = required<std::int64_t>(*obj, "", "scan", as_integer);
  if (!number) return unexpected(number.error());
  if (*number < 0) return make_error("scan: negative");
  auto time = required<double>(*obj, "", "time", as_finite);
  if (!time) return unexpected(time.error());
  scan.sensor = static_cast<std::uint32_t>(*sensor);
  scan.scan = static_cast<std::uint64_t>(*number);
  scan.time = *time;

  if (const auto platform = field(*obj, "platform")) {
    auto parsed = parse_platform(*platform);
    if (!parsed) return unexpected(parsed.error());
    scan.platform = *parsed;
  }
  if (const auto sigma = field(*obj, "sigma")) {
    auto parsed = parse_sigma(*sigma, "sigma");
    if (!parsed) return unexpected(parsed.error());
    scan.sigma = *parsed;
  }

  if (const auto coverage = field(*obj, "coverage")) {
    auto cov = as_object(*coverage, "coverage");
    if (!cov) return unexpected(cov.error());
    const auto azimuth = field(*cov, "azimuth");
    if (!azimuth) return make_error("coverage.azimuth: missing required field");
    auto arr = as_array(*azimuth, "coverage.azimuth");
    if (!arr || arr->size() != 2) return make_error("coverage.azimuth: expected [from, to]");
    AzimuthSector sector;
    double* ends[2] = {&sector.from, &sector.to};
    int k = 0;
    for (element item : *arr) {
      auto v = as_finite(item, indexed("coverage.azimuth", k));
      if (!v) return unexpected(v.error());
      *ends[k++] = *v;
    }
    scan.coverage = sector;
  }

  auto plots = required<simdjson::dom::array>(*obj, "", "plots", as_array);
  if (!plots) return unexpected(plots.error());
  scan.plots.reserve(plots->size());
  std::unordered_set<std::int64_t> ids;
  std::size_t index = 0;
  for (element item : *plots) {
    const std::string path = indexed("plots", index++);
    auto plot = parse_plot(item, path);
    if (!plot) {
      out.rejected_plots.push_back(plot.error().message);
    } else if (!ids.insert(plot->id).second) {
      out.rejected_plots.push_back(path + ": duplicate id " + std::to_string(plot->id));
    } else {
      scan.plots.push_back(std::move(*plot));
    }
  }
  return out;
}

Expected<ParsedPlotScan> parse_plot_scan(std::string_view line) {
  auto root = parse_json_line(line);
  if (!root) return unexpected(root.error());
  return parse_plot_scan(*root);
}

}  // namespace skytrack::io
