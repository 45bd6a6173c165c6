#pragma once
// `skytrack eval`: which track frames are scored at each truth time.
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <utility>

#include "skytrack/core/track_report.hpp"

namespace skytrack::tool {

inline constexpr double kTimeTolerance = 1e-6;  // [s] a track frame belongs to a truth time

struct RunCounts {
  std::size_t truth_rejected = 0, track_rejected = 0;
  std::size_t track_frames = 0, track_frames_without_truth = 0;
  std::optional<double> first_orphan_time;
};

/// Merges the track frames at each truth time. Track frames arrive in time order (several
/// sensors may share a time): those before the truth time have no truth and are counted,
/// those at it are merged, the first later one is kept pending. With `hold`, each truth time
/// is scored against every sensor's latest frame at or before it instead, its tracks moved
/// on by their velocity to the truth time (outputs stamped at sector or block times).
class TrackFrameMatcher {
 public:
  using Source = std::function<std::optional<TrackFrame>()>;
  TrackFrameMatcher(Source source, RunCounts& counts, bool hold)
      : source_(std::move(source)), counts_(counts), hold_(hold) {
    advance();
  }

  /// The merged tracks at `time`, or null when no track frame has that time. A repeated
  /// truth time gets the tracks already merged for it.
  const TrackFrame* at(double time) {
    if (merged_time_ && std::abs(*merged_time_ - time) <= kTimeTolerance) {
      return merged_any_ ? &merged_ : nullptr;
    }
    merged_.tracks.clear();
    merged_.time = time;
    merged_time_ = time;
    merged_any_ = false;
    if (hold_) return held_at(time);
    while (pending_ && pending_->time < time - kTimeTolerance) orphan();
    while (pending_ && std::abs(pending_->time - time) <= kTimeTolerance) {
      merged_.tracks.insert(merged_.tracks.end(), pending_->tracks.begin(), pending_->tracks.end());
      merged_any_ = true;
      advance();
    }
    return merged_any_ ? &merged_ : nullptr;
  }

  /// Counts the track frames after the last truth time.
  void finish() {
    while (pending_) orphan();
  }

 private:
  const TrackFrame* held_at(double time) {
    while (pending_ && pending_->time <= time + kTimeTolerance) {
      const std::uint32_t sensor = pending_->sensor;
      latest_[sensor] = std::move(*pending_);
      advance();
    }
    for (const auto& [sensor, frame] : latest_) {
      for (TrackReport track : frame.tracks) {
        track.position += track.velocity * (time - frame.time);
        merged_.tracks.push_back(std::move(track));
      }
      merged_any_ = true;
    }
    return merged_any_ ? &merged_ : nullptr;
  }
  void advance() {
    pending_ = source_();
    if (pending_) ++counts_.track_frames;
  }
  void orphan() {
    ++counts_.track_frames_without_truth;
    if (!counts_.first_orphan_time) counts_.first_orphan_time = pending_->time;
    advance();
  }

  Source source_;
  RunCounts& counts_;
  bool hold_ = false;
  std::optional<TrackFrame> pending_;
  std::map<std::uint32_t, TrackFrame> latest_;  // hold: each sensor's latest frame
  TrackFrame merged_;
  std::optional<double> merged_time_;
  bool merged_any_ = false;
};

}  // namespace skytrack::tool
