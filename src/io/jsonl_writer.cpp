// JSON Lines output. fmt's "{}" prints the shortest decimal that reads back bit-identical
// (Dragonbox), so files round-trip exactly; non-finite numbers (never produced by a healthy
// pipeline) are written as null to keep every line valid JSON.
#include "skytrack/io/jsonl_writer.hpp"

#include <cmath>
#include <iterator>

#include <fmt/compile.h>
#include <fmt/format.h>

#include "skytrack/core/transponder.hpp"

namespace skytrack::io {
namespace {

using Buffer = fmt::memory_buffer;

void put_number(Buffer& out, double value) {
  // The compiled "{}" writes what the run-time one does, without parsing the format per
  // number (a frame holds thousands: every track's covariance).
  if (std::isfinite(value)) {
    fmt::format_to(fmt::appender(out), FMT_COMPILE("{}"), value);
  } else {
    out.append(std::string_view("null"));
  }
}

void put_string(Buffer& out, std::string_view text) {
  out.push_back('"');
  for (const char c : text) {
    switch (c) {
      case '"':
        fmt::format_to(std::back_inserter(out), "\\\"");
        break;
      case '\\':
        fmt::format_to(std::back_inserter(out), "\\\\");
        break;
      case '\n':
        fmt::format_to(std::back_inserter(out), "\\n");
        break;
      case '\r':
        fmt::format_to(std::back_inserter(out), "\\r");
        break;
      case '\t':
        fmt::format_to(std::back_inserter(out), "\\t");
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          fmt::format_to(std::back_inserter(out), "\\u{:04x}", static_cast<unsigned>(c));
        } else {
          out.push_back(c);
        }
    }
  }
  out.push_back('"');
}

void put_key(Buffer& out, std::string_view key, bool& first) {
  if (!first) out.push_back(',');
  first = false;
  put_string(out, key);
  out.push_back(':');
}

void put_vector(Buffer& out, const Eigen::Vector3d& v, int dims) {
  out.push_back('[');
  for (int i = 0; i < dims; ++i) {
    if (i) out.push_back(',');
    put_number(out, v[i]);
  }
  out.push_back(']');
}

void put_extent(Buffer& out, const Eigen::Matrix2d& m) {
  out.push_back('[');
  for (int r = 0; r < 2; ++r) {
    if (r) out.push_back(',');
    out.push_back('[');
    put_number(out, m(r, 0));
    out.push_back(',');
    put_number(out, m(r, 1));
    out.push_back(']');
  }
  out.push_back(']');
}

void put_optional(Buffer& out, std::string_view key, const std::optional<double>& value,
                  bool& first) {
  if (!value) return;
  put_key(out, key, first);
  put_number(out, *value);
}

void put_sigma(Buffer& out, std::string_view key, const MeasurementSigma& sigma, bool& first) {
  if (sigma == MeasurementSigma{}) return;
  put_key(out, key, first);
  out.push_back('{');
  bool inner = true;
  put_optional(out, "range", sigma.range, inner);
  put_optional(out, "azimuth", sigma.azimuth, inner);
  put_optional(out, "elevation", sigma.elevation, inner);
  put_optional(out, "range_rate", sigma.range_rate, inner);
  put_optional(out, "x", sigma.x, inner);
  put_optional(out, "y", sigma.y, inner);
  put_optional(out, "z", sigma.z, inner);
  out.push_back('}');
}

void put_plot(Buffer& out, const Plot& plot) {
  out.push_back('{');
  bool first = true;
  put_key(out, "id", first);
  fmt::format_to(std::back_inserter(out), "{}", plot.id);
  put_optional(out, "time", plot.time, first);
  if (plot.form == PlotForm::kPolar) {
    put_optional(out, "range", plot.range, first);
    put_optional(out, "azimuth", plot.azimuth, first);
    put_optional(out, "elevation", plot.elevation, first);
    put_optional(out, "range_rate", plot.range_rate, first);
  } else {
    put_optional(out, "x", plot.x, first);
    put_optional(out, "y", plot.y, first);
    put_optional(out, "z", plot.z, first);
  }
  put_optional(out, "snr_db", plot.snr_db, first);
  put_optional(out, "amplitude", plot.amplitude, first);
  put_sigma(out, "sigma", plot.sigma, first);
  if (plot.mode3a) {
    put_key(out, "mode3a", first);
    put_string(out, format_mode3a(*plot.mode3a));
  }
  if (plot.mode_s) {
    put_key(out, "mode_s", first);
    put_string(out, format_mode_s(*plot.mode_s));
  }
  put_optional(out, "flight_level", plot.flight_level, first);
  out.push_back('}');
}

void put_header(Buffer& out, std::uint32_t sensor, std::uint64_t scan, double time, bool& first) {
  put_key(out, "sensor", first);
  fmt::format_to(std::back_inserter(out), "{}", sensor);
  put_key(out, "scan", first);
  fmt::format_to(std::back_inserter(out), "{}", scan);
  put_key(out, "time", first);
  put_number(out, time);
}

void put_track(Buffer& out, const TrackReport& track) {
  out.push_back('{');
  bool first = true;
  put_key(out, "id", first);
  fmt::format_to(std::back_inserter(out), "{}", track.id);
  put_key(out, "status", first);
  put_string(out, to_string(track.status));
  put_key(out, "kind", first);
  put_string(out, to_string(track.kind));
  put_key(out, "position", first);
  put_vector(out, track.position, track.dims);
  put_key(out, "velocity", first);
  put_vector(out, track.velocity, track.dims);
  if (!track.covariance.empty()) {
    put_key(out, "covariance", first);
    out.push_back('[');
    for (std::size_t i = 0; i < track.covariance.size(); ++i) {
      if (i) out.push_back(',');
      put_number(out, track.covariance[i]);
    }
    out.push_back(']');
  }
  if (!track.modes.empty()) {
    put_key(out, "modes", first);
    out.push_back('{');
    bool inner = true;
    for (const auto& [name, p] : track.modes) {
      put_key(out, name, inner);
      put_number(out, p);
    }
    out.push_back('}');
  }
  put_optional(out, "quality", track.quality, first);
  if (track.extent) {
    put_key(out, "extent", first);
    put_extent(out, *track.extent);
  }
  if (track.members) {
    put_key(out, "members", first);
    fmt::format_to(std::back_inserter(out), "{}", *track.members);
  }
  if (!track.sources.empty()) {
    put_key(out, "sources", first);
    out.push_back('[');
    for (std::size_t i = 0; i < track.sources.size(); ++i) {
      if (i) out.push_back(',');
      fmt::format_to(std::back_inserter(out), "{{\"sensor\":{},\"track\":{}}}",
                     track.sources[i].sensor, track.sources[i].track);
    }
    out.push_back(']');
  }
  out.push_back('}');
}

template <class T, class Put>
void put_list(Buffer& out, std::string_view key, const std::vector<T>& items, Put put,
              bool& first) {
  put_key(out, key, first);
  out.push_back('[');
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i) out.push_back(',');
    put(out, items[i]);
  }
  out.push_back(']');
}

}  // namespace

std::string to_json(const PlotScan& scan) {
  Buffer out;
  out.push_back('{');
  bool first = true;
  put_header(out, scan.sensor, scan.scan, scan.time, first);
  if (scan.platform != PlatformState{}) {
    put_key(out, "platform", first);
    out.push_back('{');
    bool inner = true;
    put_key(out, "position", inner);
    put_vector(out, scan.platform.position, 3);
    put_key(out, "velocity", inner);
    put_vector(out, scan.platform.velocity, 3);
    put_key(out, "attitude", inner);
    put_vector(out, scan.platform.attitude, 3);
    out.push_back('}');
  }
  put_sigma(out, "sigma", scan.sigma, first);
  if (scan.coverage) {
    put_key(out, "coverage", first);
    out.push_back('{');
    bool inner = true;
    put_key(out, "azimuth", inner);
    out.push_back('[');
    put_number(out, scan.coverage->from);
    out.push_back(',');
    put_number(out, scan.coverage->to);
    out.push_back(']');
    out.push_back('}');
  }
  put_list(out, "plots", scan.plots, put_plot, first);
  out.push_back('}');
  return fmt::to_string(out);
}

std::string to_json(const TruthFrame& frame) {
  Buffer out;
  out.push_back('{');
  bool first = true;
  put_key(out, "time", first);
  put_number(out, frame.time);
  const auto put_object = [](Buffer& b, const TruthObject& object) {
    b.push_back('{');
    bool f = true;
    put_key(b, "id", f);
    fmt::format_to(std::back_inserter(b), "{}", object.id);
    put_key(b, "kind", f);
    put_string(b, to_string(object.kind));
    put_key(b, "position", f);
    put_vector(b, object.position, object.dims);
    put_key(b, "velocity", f);
    put_vector(b, object.velocity, object.dims);
    if (object.extent) {
      put_key(b, "extent", f);
      put_extent(b, *object.extent);
    }
    if (object.members) {
      put_key(b, "members", f);
      fmt::format_to(std::back_inserter(b), "{}", *object.members);
    }
    b.push_back('}');
  };
  put_list(out, "objects", frame.objects, put_object, first);
  out.push_back('}');
  return fmt::to_string(out);
}

std::string to_json(const TrackFrame& frame) {
  Buffer out;
  out.push_back('{');
  bool first = true;
  put_header(out, frame.sensor, frame.scan, frame.time, first);
  put_list(out, "tracks", frame.tracks, put_track, first);
  const auto put_association = [](Buffer& b, const Association& a) {
    fmt::format_to(std::back_inserter(b), "{{\"track\":{},\"plot\":{},\"probability\":", a.track,
                   a.plot);
    put_number(b, a.probability);
    if (a.scan) fmt::format_to(std::back_inserter(b), ",\"scan\":{}", *a.scan);
    b.push_back('}');
  };
  put_list(out, "associations", frame.associations, put_association, first);
  const auto put_event = [](Buffer& b, const TrackEvent& e) {
    fmt::format_to(std::back_inserter(b), "{{\"type\":");
    put_string(b, type_name(e));
    fmt::format_to(std::back_inserter(b), ",\"track\":{},\"detail\":", e.track);
    put_string(b, e.detail);
    b.push_back('}');
  };
  put_list(out, "events", frame.events, put_event, first);
  out.push_back('}');
  return fmt::to_string(out);
}

Expected<JsonLinesWriter> JsonLinesWriter::open(const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) return make_error(path + ": cannot open for writing");
  return JsonLinesWriter(file, path);
}

JsonLinesWriter::JsonLinesWriter(JsonLinesWriter&& other) noexcept
    : file_(std::exchange(other.file_, nullptr)), path_(std::move(other.path_)), ok_(other.ok_) {}

JsonLinesWriter& JsonLinesWriter::operator=(JsonLinesWriter&& other) noexcept {
  if (this != &other) {
    close();
    file_ = std::exchange(other.file_, nullptr);
    path_ = std::move(other.path_);
    ok_ = other.ok_;
  }
  return *this;
}

JsonLinesWriter::~JsonLinesWriter() {
  close();
}

bool JsonLinesWriter::write_line(const std::string& json) {
  if (!file_) return false;
  ok_ = ok_ && std::fwrite(json.data(), 1, json.size(), file_) == json.size() &&
        std::fputc('\n', file_) != EOF;
  return ok_;
}

bool JsonLinesWriter::close() {
  if (file_) {
    ok_ = (std::fflush(file_) == 0) && ok_;
    ok_ = (std::fclose(file_) == 0) && ok_;
    file_ = nullptr;
  }
  return ok_;
}

}  // namespace skytrack::io
