// Track output lines (CONTRACTS.md §3). Any invalid track, association or event rejects the
// line, so an evaluation never scores a partial picture.
#include <limits>
#include <string>

#include "json_fields.hpp"
#include "json_parser.hpp"

namespace skytrack::io {
namespace {

using namespace detail;

Expected<std::vector<double>> parse_covariance(const element& value, const std::string& path,
                                               int dims) {
  auto arr = as_array(value, path);
  if (!arr) return unexpected(arr.error());
  const std::size_t expected = dims == 3 ? 36 : 16;
  if (arr->size() != expected) {
    return make_error(path + ": expected " + std::to_string(expected) + " numbers for " +
                      std::to_string(dims) + "-D");
  }
  std::vector<double> out;
  out.reserve(expected);
  for (element item : *arr) {
    auto number = as_finite(item, indexed(path, out.size()));
    if (!number) return unexpected(number.error());
    out.push_back(*number);
  }
  return out;
}

Expected<std::vector<std::pair<std::string, double>>> parse_modes(const element& value,
                                                                  const std::string& path) {
  auto obj = as_object(value, path);
  if (!obj) return unexpected(obj.error());
  std::vector<std::pair<std::string, double>> modes;
  for (auto [key, item] : *obj) {
    auto p = as_finite(item, join(path, key));
    if (!p) return unexpected(p.error());
    if (*p < 0.0 || *p > 1.0) return make_error(join(path, key) + ": not a probability");
    modes.emplace_back(std::string(key), *p);
  }
  return modes;
}

Expected<TrackSource> parse_source(const element& value, const std::string& path) {
  auto obj = as_object(value, path);
  if (!obj) return unexpected(obj.error());
  auto sensor = required<std::int64_t>(*obj, path, "sensor", as_integer);
  if (!sensor) return unexpected(sensor.error());
  if (*sensor < 0 || *sensor > 0xFFFFFFFFLL)
    return make_error(join(path, "sensor") + ": out of range");
  auto track = required<std::int64_t>(*obj, path, "track", as_integer);
  if (!track) return unexpected(track.error());
  return TrackSource{static_cast<std::uint32_t>(*sensor), *track};
}

Expected<TrackReport> parse_track(const element& value, const std::string& path) {
  auto obj = as_object(value, path);
  if (!obj) return unexpected(obj.error());
  TrackReport track;
  auto id = required<std::int64_t>(*obj, path, "id", as_integer);
  if (!id) return unexpected(id.error());
  track.id = *id;
  auto status = required<std::string_view>(*obj, path, "status", as_string);
  if (!status) return unexpected(status.error());
  const auto parsed_status = parse_track_status(*status);
  if (!parsed_status) {
    return make_error(join(path, "status") +
                      ": expected tentative, confirmed, coasting or deleted");
  }
  track.status = *parsed_status;
  auto kind = optional_field<std::string_view>(*obj, path, "kind", as_string);
  if (!kind) return unexpected(kind.error());
  if (*kind) {
    const auto parsed = parse_object_kind(**kind);
    if (!parsed) return make_error(join(path, "kind") + ": expected point, group or extended");
    track.kind = *parsed;
  }
  const auto position = field(*obj, "position");
  if (!position) return make_error(join(path, "position") + ": missing required field");
  auto p = as_vector23(*position, join(path, "position"), &track.dims);
  if (!p) return unexpected(p.error());
  track.position = *p;
  if (const auto velocity = field(*obj, "velocity")) {
    int dims = 0;
    auto v = as_vector23(*velocity, join(path, "velocity"), &dims);
    if (!v) return unexpected(v.error());
    if (dims != track.dims)
      return make_error(join(path, "velocity") + ": dims differ from position");
    track.velocity = *v;
  }
  if (const auto covariance = field(*obj, "covariance")) {
    auto parsed = parse_covariance(*covariance, join(path, "covariance"), track.dims);
    if (!parsed) return unexpected(parsed.error());
    track.covariance = std::move(*parsed);
  }
  if (const auto modes = field(*obj, "modes")) {
    auto parsed = parse_modes(*modes, join(path, "modes"));
    if (!parsed) return unexpected(parsed.error());
    track.modes = std::move(*parsed);
  }
  auto quality = optional_field<double>(*obj, path, "quality", as_finite);
  if (!quality) return unexpected(quality.error());
  track.quality = *quality;
  auto extent = optional_field<Eigen::Matrix2d>(*obj, path, "extent", as_extent);
  if (!extent) return unexpected(extent.error());
  track.extent = *extent;
  auto members = optional_field<std::int64_t>(*obj, path, "members", as_integer);
  if (!members) return unexpected(members.error());
  if (*members) {
    if (**members < 0) return make_error(join(path, "members") + ": negative");
    if (**members > std::numeric_limits<int>::max()) {
      return make_error(join(path, "members") + ": " + std::to_string(**members) + " is beyond " +
                        std::to_string(std::numeric_limits<int>::max()));
    }
    track.members = static_cast<int>(**members);
  }
  if (const auto sources = field(*obj, "sources")) {
    auto arr = as_array(*sources, join(path, "sources"));
    if (!arr) return unexpected(arr.error());
    for (element item : *arr) {
      auto source = parse_source(item, indexed(join(path, "sources"), track.sources.size()));
      if (!source) return unexpected(source.error());
      track.sources.push_back(*source);
    }
  }
  return track;
}

Expected<Association> parse_association(const element& value, const std::string& path) {
  auto obj = as_object(value, path);
  if (!obj) return unexpected(obj.error());
  auto track = required<std::int64_t>(*obj, path, "track", as_integer);
  if (!track) return unexpected(track.error());
  auto plot = required<std::int64_t>(*obj, path, "plot", as_integer);
  if (!plot) return unexpected(plot.error());
  auto probability = required<double>(*obj, path, "probability", as_finite);
  if (!probability) return unexpected(probability.error());
  if (*probability < 0.0 || *probability > 1.0) {
    return make_error(join(path, "probability") + ": not in [0, 1]");
  }
  auto scan = optional_field<std::int64_t>(*obj, path, "scan", as_integer);
  if (!scan) return unexpected(scan.error());
  if (*scan && **scan < 0) return make_error(join(path, "scan") + ": negative");
  Association out{*track, *plot, *probability, std::nullopt};
  if (*scan) out.scan = static_cast<std::uint64_t>(**scan);
  return out;
}

Expected<TrackEvent> parse_event(const element& value, const std::string& path) {
  auto obj = as_object(value, path);
  if (!obj) return unexpected(obj.error());
  auto type = required<std::string_view>(*obj, path, "type", as_string);
  if (!type) return unexpected(type.error());
  auto track = optional_field<std::int64_t>(*obj, path, "track", as_integer);
  if (!track) return unexpected(track.error());
  auto detail = optional_field<std::string_view>(*obj, path, "detail", as_string);
  if (!detail) return unexpected(detail.error());
  return event_from_name(*type, track->value_or(0), std::string(detail->value_or("")));
}

/// Parses the optional array `key` of `obj` with `parse` into `out`.
template <class T, class Parse>
Expected<void> parse_list(const object& obj, std::string_view key, Parse parse,
                          std::vector<T>& out) {
  const auto value = field(obj, key);
  if (!value) return {};
  auto arr = as_array(*value, std::string(key));
  if (!arr) return unexpected(arr.error());
  out.reserve(arr->size());
  std::size_t index = 0;
  for (element item : *arr) {
    auto parsed = parse(item, indexed(key, index++));
    if (!parsed) return unexpected(parsed.error());
    out.push_back(std::move(*parsed));
  }
  return {};
}

}  // namespace

Expected<TrackFrame> parse_track_frame(const element& root) {
  auto obj = as_object(root, "line");
  if (!obj) return unexpected(obj.error());
  TrackFrame frame;
  auto sensor = required<std::int64_t>(*obj, "", "sensor", as_integer);
  if (!sensor) return unexpected(sensor.error());
  if (*sensor < 0 || *sensor > 0xFFFFFFFFLL) return make_error("sensor: out of range");
  auto scan = required<std::int64_t>(*obj, "", "scan", as_integer);
  if (!scan) return unexpected(scan.error());
  if (*scan < 0) return make_error("scan: negative");
  auto time = required<double>(*obj, "", "time", as_finite);
  if (!time) return unexpected(time.error());
  frame.sensor = static_cast<std::uint32_t>(*sensor);
  frame.scan = static_cast<std::uint64_t>(*scan);
  frame.time = *time;
  if (!field(*obj, "tracks")) return make_error("tracks: missing required field");
  if (auto r = parse_list(*obj, "tracks", parse_track, frame.tracks); !r) {
    return unexpected(r.error());
  }
  if (auto r = parse_list(*obj, "associations", parse_association, frame.associations); !r) {
    return unexpected(r.error());
  }
  if (auto r = parse_list(*obj, "events", parse_event, frame.events); !r) {
    return unexpected(r.error());
  }
  return frame;
}

Expected<TrackFrame> parse_track_frame(std::string_view line) {
  auto root = parse_json_line(line);
  if (!root) return unexpected(root.error());
  return parse_track_frame(*root);
}

}  // namespace skytrack::io
