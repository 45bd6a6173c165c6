#include "picture_json.hpp"

#include <cmath>
#include <iterator>
#include <string_view>

#include <fmt/format.h>

namespace skytrack::display {
namespace {

using Buffer = fmt::memory_buffer;

void put(Buffer& out, std::string_view text) {
  out.append(text);
}

void put_string(Buffer& out, std::string_view text) {
  out.push_back('"');
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out.push_back('\\');
      out.push_back(c);
    } else if (static_cast<unsigned char>(c) < 0x20) {
      fmt::format_to(std::back_inserter(out), "\\u{:04x}", static_cast<unsigned char>(c));
    } else {
      out.push_back(c);
    }
  }
  out.push_back('"');
}

// Fixed-point metres: the page draws pixels. Non-finite values become null (valid JSON).
void put_metres(Buffer& out, double value) {
  if (std::isfinite(value)) {
    fmt::format_to(std::back_inserter(out), "{:.1f}", value);
  } else {
    put(out, "null");
  }
}

void put_number(Buffer& out, double value) {
  if (std::isfinite(value)) {
    fmt::format_to(std::back_inserter(out), "{:.4g}", value);
  } else {
    put(out, "null");
  }
}

char status_code(TrackStatus s) {
  switch (s) {
    case TrackStatus::kTentative:
      return 't';
    case TrackStatus::kConfirmed:
      return 'c';
    case TrackStatus::kCoasting:
      return 'k';
    case TrackStatus::kDeleted:
      return 'd';
  }
  return 't';
}

// Position covariance [Pxx, Pxy, Pyy] from the row-major [x, vx, y, vy(, z, vz)] matrix.
void put_position_covariance(Buffer& out, const TrackReport& t) {
  const std::size_t n = static_cast<std::size_t>(2 * t.dims);
  if (t.covariance.size() != n * n) return;
  put(out, ",\"c\":[");
  put_number(out, t.covariance[0]);
  put(out, ",");
  put_number(out, t.covariance[2]);
  put(out, ",");
  put_number(out, t.covariance[2 * n + 2]);
  put(out, "]");
}

void put_track(Buffer& out, const TrackReport& t) {
  fmt::format_to(std::back_inserter(out), "{{\"i\":{},\"s\":\"{}\",\"k\":\"{}\",\"x\":", t.id,
                 status_code(t.status), to_string(t.kind).substr(0, 1));
  put_metres(out, t.position.x());
  put(out, ",\"y\":");
  put_metres(out, t.position.y());
  put(out, ",\"vx\":");
  put_metres(out, t.velocity.x());
  put(out, ",\"vy\":");
  put_metres(out, t.velocity.y());
  put_position_covariance(out, t);
  if (t.extent) {
    const Eigen::Matrix2d& e = *t.extent;
    put(out, ",\"e\":[");
    put_number(out, e(0, 0));
    put(out, ",");
    put_number(out, e(0, 1));
    put(out, ",");
    put_number(out, e(1, 1));
    put(out, "]");
  }
  if (t.members) fmt::format_to(std::back_inserter(out), ",\"m\":{}", *t.members);
  if (!t.sources.empty()) fmt::format_to(std::back_inserter(out), ",\"f\":{}", t.sources.size());
  put(out, "}");
}

// The events an operator looks for on the picture; the rest are in the track's details.
bool is_marked(TrackEventType type) {
  switch (type) {
    case TrackEventType::kBranchCreated:
    case TrackEventType::kBranchPromoted:
    case TrackEventType::kBranchPruned:
    case TrackEventType::kConfirmed:
    case TrackEventType::kDeleted:
      return true;
    default:
      return false;
  }
}

void put_tracks(Buffer& out, const TrackFrame& frame) {
  fmt::format_to(std::back_inserter(out), ",\"scan\":{},\"time\":", frame.scan);
  put_number(out, frame.time);
  put(out, ",\"tracks\":[");
  for (std::size_t i = 0; i < frame.tracks.size(); ++i) {
    if (i > 0) out.push_back(',');
    put_track(out, frame.tracks[i]);
  }
  put(out, "],\"events\":[");
  bool first = true;
  for (const TrackEvent& e : frame.events) {
    if (!is_marked(e.type)) continue;
    if (!first) out.push_back(',');
    first = false;
    put(out, "[");
    put_string(out, type_name(e));
    fmt::format_to(std::back_inserter(out), ",{}]", e.track);
  }
  put(out, "]");
}

void put_plots(Buffer& out, const std::vector<std::shared_ptr<const PlotLayer>>& layers) {
  put(out, ",\"plots\":[");
  for (std::size_t i = 0; i < layers.size(); ++i) {
    const PlotLayer& layer = *layers[i];
    if (i > 0) out.push_back(',');
    fmt::format_to(std::back_inserter(out), "{{\"scan\":{},\"time\":", layer.scan);
    put_number(out, layer.time);
    put(out, ",\"platform\":[");
    put_metres(out, layer.platform_x);
    put(out, ",");
    put_metres(out, layer.platform_y);
    put(out, "],\"xy\":[");
    for (std::size_t k = 0; k < layer.xy.size(); ++k) {
      if (k > 0) out.push_back(',');
      // Whole metres: 5000 plots a scan stay about 60 kB.
      if (std::isfinite(layer.xy[k])) {
        fmt::format_to(std::back_inserter(out), "{}", std::lround(layer.xy[k]));
      } else {
        put(out, "0");
      }
    }
    put(out, "]}");
  }
  put(out, "]");
}

void put_counts(Buffer& out, const std::vector<RejectionCount>& counts) {
  put(out, "{");
  for (std::size_t i = 0; i < counts.size(); ++i) {
    if (i > 0) out.push_back(',');
    put_string(out, counts[i].reason);
    fmt::format_to(std::back_inserter(out), ":{}", counts[i].count);
  }
  put(out, "}");
}

void put_truth(Buffer& out, const TruthFrame& truth) {
  put(out, ",\"truth\":{\"time\":");
  put_number(out, truth.time);
  put(out, ",\"objects\":[");
  for (std::size_t i = 0; i < truth.objects.size(); ++i) {
    const TruthObject& o = truth.objects[i];
    if (i > 0) out.push_back(',');
    fmt::format_to(std::back_inserter(out), "{{\"i\":{},\"x\":", o.id);
    put_metres(out, o.position.x());
    put(out, ",\"y\":");
    put_metres(out, o.position.y());
    put(out, "}");
  }
  put(out, "]}");
}

}  // namespace

std::string to_json(const TrackerStatusReport& s) {
  Buffer out;
  put(out, "{\"instance\":");
  put_string(out, s.instance);
  put(out, ",\"profile\":");
  put_string(out, s.profile_name);
  put(out, ",\"uptime\":");
  put_number(out, s.uptime);
  fmt::format_to(std::back_inserter(out),
                 ",\"scans_processed\":{},\"plots_processed\":{},\"scans_dropped\":{},"
                 "\"queue_depth\":{},\"numeric_failures\":{}",
                 s.scans_processed, s.plots_processed, s.scans_dropped, s.queue_depth,
                 s.numeric_failures);
  put(out, ",\"latency\":{\"p50\":");
  put_number(out, s.latency_p50);
  put(out, ",\"p99\":");
  put_number(out, s.latency_p99);
  put(out, ",\"max\":");
  put_number(out, s.latency_max);
  fmt::format_to(std::back_inserter(out),
                 "}},\"tracks\":{{\"tentative\":{},\"confirmed\":{},\"coasting\":{}}}",
                 s.tracks_tentative, s.tracks_confirmed, s.tracks_coasting);
  put(out, ",\"plots_rejected\":");
  put_counts(out, s.plots_rejected);
  put(out, ",\"scans_rejected\":");
  put_counts(out, s.scans_rejected);
  put(out, "}");
  return fmt::to_string(out);
}

std::string to_json(const PictureSnapshot& snap) {
  Buffer out;
  fmt::format_to(std::back_inserter(out), "{{\"version\":{},\"mode\":", snap.version);
  put_string(out, snap.mode);
  put(out, ",\"replay\":");
  put(out, snap.replay_json);
  put(out, ",\"sensors\":[");
  for (std::size_t i = 0; i < snap.sensors.size(); ++i) {
    const auto& sensor = snap.sensors[i];
    if (i > 0) out.push_back(',');
    fmt::format_to(std::back_inserter(out), "{{\"sensor\":{}", sensor.id);
    if (sensor.tracks) put_tracks(out, *sensor.tracks);
    put_plots(out, sensor.plots);
    put(out, "}");
  }
  put(out, "],\"status\":[");
  for (std::size_t i = 0; i < snap.status.size(); ++i) {
    if (i > 0) out.push_back(',');
    put(out, to_json(*snap.status[i]));
  }
  put(out, "]");
  if (snap.truth) put_truth(out, *snap.truth);
  put(out, "}");
  return fmt::to_string(out);
}

}  // namespace skytrack::display
