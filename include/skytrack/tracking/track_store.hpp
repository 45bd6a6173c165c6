#pragma once
// The point tracker's tracks (fathers and, with branching, their sons and grandsons) and their
// numbering. A track's number is given when it is confirmed, in the order of the plots that
// confirmed it, so neither tentative tracks of clutter nor the grouping of plots into looks
// shifts the numbers; until then a track (and a branch, until it replaces its father)
// carries a provisional number from kProvisionalNumber on.
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "skytrack/core/track_report.hpp"
#include "skytrack/tracking/point_track.hpp"

namespace skytrack {

class TrackStore {
 public:
  std::vector<PointTrack>& all() { return tracks_; }
  const std::vector<PointTrack>& all() const { return tracks_; }
  std::size_t size() const { return tracks_.size(); }
  PointTrack& operator[](std::size_t t) { return tracks_[t]; }
  const PointTrack& operator[](std::size_t t) const { return tracks_[t]; }

  /// The next provisional number (a track or branch not yet confirmed).
  std::int64_t provisional() { return next_provisional_++; }
  /// Appends a track; returns its slot.
  int add(PointTrack track);
  /// The slot of the track numbered `number`, or -1.
  int slot(std::int64_t number) const;
  /// Track t now carries `number` (a branch that replaced its father takes the father's).
  void renumber(int t, std::int64_t number);

  /// Gives the fathers confirmed with a provisional number their numbers, in the order of
  /// their latest plots; this frame's associations and events name them by it. `renamed`
  /// gets (provisional, number) per track renamed.
  void number_confirmed(TrackFrame& frame,
                        std::vector<std::pair<std::int64_t, std::int64_t>>& renamed);
  /// Drops the deleted tracks (reported once, in the look that deleted them).
  void erase_deleted();

 private:
  std::vector<PointTrack> tracks_;
  std::unordered_map<std::int64_t, int> slots_;  // track number -> index in tracks_
  std::int64_t next_number_ = 1;
  std::int64_t next_provisional_ = kProvisionalNumber;
};

}  // namespace skytrack
