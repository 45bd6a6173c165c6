// TrackFrame <-> TrackBatch. Buffers are allocated with dds_alloc and marked _release, so
// dds_sample_free frees them.
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

// ---- tracks ---------------------------------------------------------------------------------

// The core enums and the IDL enums list the same values in the same order.
static_assert(skytrack_dds_TRACK_TENTATIVE == static_cast<int>(TrackStatus::kTentative) &&
              skytrack_dds_TRACK_CONFIRMED == static_cast<int>(TrackStatus::kConfirmed) &&
              skytrack_dds_TRACK_COASTING == static_cast<int>(TrackStatus::kCoasting) &&
              skytrack_dds_TRACK_DELETED == static_cast<int>(TrackStatus::kDeleted));
static_assert(skytrack_dds_OBJECT_POINT == static_cast<int>(ObjectKind::kPoint) &&
              skytrack_dds_OBJECT_GROUP == static_cast<int>(ObjectKind::kGroup) &&
              skytrack_dds_OBJECT_EXTENDED == static_cast<int>(ObjectKind::kExtended));

/// An enum's raw 32-bit value: a received value outside the enum must not be loaded as one.
template <class Enum>
std::uint32_t raw_enum(const Enum& value) {
  static_assert(sizeof(Enum) == sizeof(std::uint32_t));
  std::uint32_t raw = 0;
  std::memcpy(&raw, &value, sizeof raw);
  return raw;
}

/// A received boolean; any non-zero byte counts as true.
bool raw_bool(const bool& value) {
  unsigned char raw = 0;
  std::memcpy(&raw, &value, 1);
  return raw != 0;
}

/// The model names all tracks with modes share, in the first such track's order.
Expected<const TrackReport*> mode_reference(const TrackFrame& frame) {
  for (std::size_t t = 0; t < frame.tracks.size(); ++t) {
    const TrackReport& track = frame.tracks[t];
    if (track.modes.empty()) continue;
    for (std::size_t i = 0; i < track.modes.size(); ++i) {
      for (std::size_t j = 0; j < i; ++j) {
        if (track.modes[i].first == track.modes[j].first) {
          return make_error(field("TrackFrame.tracks", t, "modes") + ": duplicate model name '" +
                            track.modes[i].first + "'");
        }
      }
    }
    return &track;
  }
  return nullptr;
}

Expected<void> encode_modes(const TrackReport& track, const TrackReport* reference,
                            const std::string& what, skytrack_dds_Track& out) {
  if (track.modes.empty()) return {};
  if (track.modes.size() != reference->modes.size()) {
    return make_error(what + ": " + std::to_string(track.modes.size()) + " models, the batch has " +
                      std::to_string(reference->modes.size()));
  }
  if (!alloc_zeroed(out.mode_probabilities, track.modes.size()))
    return unexpected(out_of_memory(what));
  for (std::size_t i = 0; i < reference->modes.size(); ++i) {
    const std::string& name = reference->modes[i].first;
    const auto it = std::find_if(track.modes.begin(), track.modes.end(),
                                 [&](const auto& mode) { return mode.first == name; });
    if (it == track.modes.end()) {
      return make_error(what + ": no model '" + name + "' (all tracks must share one model set)");
    }
    out.mode_probabilities._buffer[i] = it->second;
  }
  return {};
}

Expected<void> encode_track(const TrackReport& track, const TrackReport* reference,
                            std::size_t index, skytrack_dds_Track& out) {
  const auto status = static_cast<std::uint32_t>(track.status);
  const auto kind = static_cast<std::uint32_t>(track.kind);
  if (status > skytrack_dds_TRACK_DELETED || kind > skytrack_dds_OBJECT_EXTENDED) {
    return make_error(field("TrackFrame.tracks", index, "status/kind") + ": not an IDL value");
  }
  if (track.dims != 2 && track.dims != 3) {
    return make_error(field("TrackFrame.tracks", index, "dims: ") + std::to_string(track.dims) +
                      ", expected 2 or 3");
  }
  const std::size_t n = 2 * static_cast<std::size_t>(track.dims);
  if (!track.covariance.empty() && track.covariance.size() != n * n) {
    return make_error(field("TrackFrame.tracks", index, "covariance: ") +
                      std::to_string(track.covariance.size()) + " values, expected 0 or " +
                      std::to_string(n * n));
  }
  if (track.members && *track.members < 0) {
    return make_error(field("TrackFrame.tracks", index, "members: ") +
                      std::to_string(*track.members) + ", expected >= 0");
  }
  out.id = track.id;
  out.status = static_cast<skytrack_dds_TrackStatus>(status);
  out.kind = static_cast<skytrack_dds_ObjectKind>(kind);
  out.dims = static_cast<std::uint8_t>(track.dims);
  copy3(track.position, out.position);
  copy3(track.velocity, out.velocity);
  out.covariance_dim = track.covariance.empty() ? 0 : static_cast<std::uint8_t>(n);
  std::copy(track.covariance.begin(), track.covariance.end(), out.covariance);
  out.has_quality = track.quality.has_value();
  out.quality = track.quality.value_or(0.0);
  out.has_extent = track.extent.has_value();
  if (track.extent) {
    const Eigen::Matrix2d& x = *track.extent;
    out.extent[0] = x(0, 0);
    out.extent[1] = x(0, 1);
    out.extent[2] = x(1, 0);
    out.extent[3] = x(1, 1);
  }
  out.members = track.members.value_or(-1);
  return encode_modes(track, reference, field("TrackFrame.tracks", index, "modes"), out);
}

Expected<TrackReport> decode_track(const skytrack_dds_Track& in, std::uint32_t mode_count,
                                   const dds_sequence_string& names, std::size_t index) {
  const auto bad = [index](std::string_view member, const std::string& why) {
    return make_error(field("TrackBatch.tracks", index, member) + ": " + why);
  };
  TrackReport track;
  track.id = in.id;
  const std::uint32_t status = raw_enum(in.status);
  if (status > skytrack_dds_TRACK_DELETED) {
    return bad("status", std::to_string(status) + " is not a TrackStatus");
  }
  track.status = static_cast<TrackStatus>(status);
  const std::uint32_t kind = raw_enum(in.kind);
  if (kind > skytrack_dds_OBJECT_EXTENDED) {
    return bad("kind", std::to_string(kind) + " is not an ObjectKind");
  }
  track.kind = static_cast<ObjectKind>(kind);
  if (in.dims != 2 && in.dims != 3)
    return bad("dims", std::to_string(in.dims) + ", expected 2 or 3");
  track.dims = in.dims;
  track.position = vector3(in.position);
  track.velocity = vector3(in.velocity);
  const std::uint32_t n = in.covariance_dim;
  if (n != 0 && n != 2u * in.dims) {
    return bad("covariance_dim", std::to_string(n) + ", expected 0 or " +
                                     std::to_string(2 * in.dims) + " for dims " +
                                     std::to_string(in.dims));
  }
  track.covariance.assign(in.covariance, in.covariance + n * n);
  if (auto e = missing_buffer(in.mode_probabilities,
                              field("TrackBatch.tracks", index, "mode_probabilities"))) {
    return unexpected(*e);
  }
  const std::uint32_t modes = in.mode_probabilities._length;
  if (modes != 0 && modes != mode_count) {
    return bad("mode_probabilities", "length " + std::to_string(modes) + ", expected 0 or " +
                                         std::to_string(mode_count) + " (mode_names length)");
  }
  track.modes.reserve(modes);
  for (std::uint32_t i = 0; i < modes; ++i) {
    track.modes.emplace_back(from_c_string(names._buffer[i]), in.mode_probabilities._buffer[i]);
  }
  if (raw_bool(in.has_quality)) track.quality = in.quality;
  if (raw_bool(in.has_extent)) {
    Eigen::Matrix2d x;
    x << in.extent[0], in.extent[1], in.extent[2], in.extent[3];
    track.extent = x;
  }
  if (in.members < -1) return bad("members", std::to_string(in.members) + ", expected >= -1");
  if (in.members >= 0) track.members = in.members;
  return track;
}

/// Fills a RejectionCount sequence.

}  // namespace

// ---- TrackFrame <-> TrackBatch --------------------------------------------------------------

Expected<TrackBatchSample> to_dds(const TrackFrame& frame) {
  if (frame.tracks.size() > kMaxSequence || frame.associations.size() > kMaxSequence ||
      frame.events.size() > kMaxSequence) {
    return make_error("TrackFrame: too many tracks, associations or events for one TrackBatch");
  }
  const auto reference = mode_reference(frame);
  if (!reference) return unexpected(reference.error());
  TrackBatchSample out;  // frees whatever was built if a later step fails
  skytrack_dds_TrackBatch& b = out.get();
  b.sensor = frame.sensor;
  b.scan = frame.scan;
  b.time = frame.time;
  const std::size_t mode_count = *reference ? (*reference)->modes.size() : 0;
  if (!alloc_zeroed(b.mode_names, mode_count))
    return unexpected(out_of_memory("TrackBatch.mode_names"));
  for (std::size_t i = 0; i < mode_count; ++i) {
    auto name = dup_string((*reference)->modes[i].first, "TrackFrame.tracks[].modes");
    if (!name) return unexpected(name.error());
    b.mode_names._buffer[i] = *name;
  }
  if (!alloc_zeroed(b.tracks, frame.tracks.size()))
    return unexpected(out_of_memory("TrackBatch.tracks"));
  for (std::size_t i = 0; i < frame.tracks.size(); ++i) {
    if (auto ok = encode_track(frame.tracks[i], *reference, i, b.tracks._buffer[i]); !ok) {
      return unexpected(ok.error());
    }
  }
  if (!alloc_zeroed(b.associations, frame.associations.size())) {
    return unexpected(out_of_memory("TrackBatch.associations"));
  }
  for (std::size_t i = 0; i < frame.associations.size(); ++i) {
    const Association& a = frame.associations[i];
    b.associations._buffer[i] = {a.track, a.plot, a.probability};
  }
  const bool held_over = std::any_of(frame.associations.begin(), frame.associations.end(),
                                     [](const Association& a) { return a.scan.has_value(); });
  if (!reserve_primitive(b.association_scans, held_over ? frame.associations.size() : 0)) {
    return unexpected(out_of_memory("TrackBatch.association_scans"));
  }
  for (std::uint32_t i = 0; i < b.association_scans._length; ++i) {
    b.association_scans._buffer[i] = frame.associations[i].scan.value_or(frame.scan);
  }
  std::size_t sources = 0;
  for (const TrackReport& t : frame.tracks) sources += t.sources.size();
  if (!alloc_zeroed(b.track_sources, sources)) {
    return unexpected(out_of_memory("TrackBatch.track_sources"));
  }
  std::size_t next = 0;
  for (std::size_t i = 0; i < frame.tracks.size(); ++i) {
    for (const TrackSource& source : frame.tracks[i].sources) {
      b.track_sources._buffer[next++] = {static_cast<std::uint32_t>(i), source.sensor,
                                         source.track};
    }
  }
  if (!alloc_zeroed(b.events, frame.events.size()))
    return unexpected(out_of_memory("TrackBatch.events"));
  for (std::size_t i = 0; i < frame.events.size(); ++i) {
    const TrackEvent& e = frame.events[i];
    auto type = dup_string(type_name(e), field("TrackFrame.events", i, "type"));
    if (!type) return unexpected(type.error());
    b.events._buffer[i].type = *type;
    b.events._buffer[i].track = e.track;
    auto detail = dup_string(e.detail, field("TrackFrame.events", i, "detail"));
    if (!detail) return unexpected(detail.error());
    b.events._buffer[i].detail = *detail;
  }
  return out;
}

Expected<TrackFrame> from_dds(const skytrack_dds_TrackBatch& batch) {
  if (auto e = missing_buffer(batch.mode_names, "TrackBatch.mode_names")) return unexpected(*e);
  if (auto e = missing_buffer(batch.tracks, "TrackBatch.tracks")) return unexpected(*e);
  if (auto e = missing_buffer(batch.associations, "TrackBatch.associations")) {
    return unexpected(*e);
  }
  if (auto e = missing_buffer(batch.events, "TrackBatch.events")) return unexpected(*e);
  if (auto e = missing_buffer(batch.association_scans, "TrackBatch.association_scans")) {
    return unexpected(*e);
  }
  if (batch.association_scans._length != 0 &&
      batch.association_scans._length != batch.associations._length) {
    return make_error("TrackBatch.association_scans: length " +
                      std::to_string(batch.association_scans._length) + ", expected 0 or " +
                      std::to_string(batch.associations._length) + " (associations length)");
  }
  if (auto e = missing_buffer(batch.track_sources, "TrackBatch.track_sources")) {
    return unexpected(*e);
  }
  TrackFrame frame;
  frame.sensor = batch.sensor;
  frame.scan = batch.scan;
  frame.time = batch.time;
  frame.tracks.reserve(batch.tracks._length);
  for (std::uint32_t i = 0; i < batch.tracks._length; ++i) {
    auto track =
        decode_track(batch.tracks._buffer[i], batch.mode_names._length, batch.mode_names, i);
    if (!track) return unexpected(track.error());
    frame.tracks.push_back(std::move(*track));
  }
  frame.associations.reserve(batch.associations._length);
  for (std::uint32_t i = 0; i < batch.associations._length; ++i) {
    const skytrack_dds_Association& a = batch.associations._buffer[i];
    frame.associations.push_back({a.track, a.plot, a.probability, std::nullopt});
    if (i < batch.association_scans._length && batch.association_scans._buffer[i] != batch.scan) {
      frame.associations.back().scan = batch.association_scans._buffer[i];
    }
  }
  for (std::uint32_t i = 0; i < batch.track_sources._length; ++i) {
    const skytrack_dds_TrackSource& s = batch.track_sources._buffer[i];
    if (s.track_index >= frame.tracks.size()) {
      return make_error(field("TrackBatch.track_sources", i, "track_index") + ": " +
                        std::to_string(s.track_index) + " is not a track index (" +
                        std::to_string(frame.tracks.size()) + " tracks)");
    }
    frame.tracks[s.track_index].sources.push_back({s.sensor, s.track});
  }
  frame.events.reserve(batch.events._length);
  for (std::uint32_t i = 0; i < batch.events._length; ++i) {
    const skytrack_dds_TrackEvent& e = batch.events._buffer[i];
    frame.events.push_back(
        event_from_name(from_c_string(e.type), e.track, from_c_string(e.detail)));
  }
  return frame;
}

}  // namespace skytrack::dds
