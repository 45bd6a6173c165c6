#include "skytrack/tracking/track_store.hpp"

#include <algorithm>
#include <charconv>
#include <string>
#include <string_view>

namespace skytrack {

int TrackStore::add(PointTrack track) {
  const int t = static_cast<int>(tracks_.size());
  slots_[track.id] = t;
  tracks_.push_back(std::move(track));
  return t;
}

int TrackStore::slot(std::int64_t number) const {
  const auto it = slots_.find(number);
  return it == slots_.end() ? -1 : it->second;
}

void TrackStore::renumber(int t, std::int64_t number) {
  PointTrack& track = tracks_[static_cast<std::size_t>(t)];
  slots_.erase(track.id);
  track.id = number;
  slots_[number] = t;
}

void TrackStore::number_confirmed(TrackFrame& frame,
                                  std::vector<std::pair<std::int64_t, std::int64_t>>& renamed) {
  renamed.clear();
  std::vector<int> due;
  for (std::size_t t = 0; t < tracks_.size(); ++t) {
    const PointTrack& track = tracks_[t];
    if (track.id >= kProvisionalNumber && track.branch == BranchType::kFather &&
        is_reported_as_firm(track.life.status)) {
      due.push_back(static_cast<int>(t));
    }
  }
  if (due.empty()) return;
  const auto last_seen = [&](int t) {
    const PointTrack& track = tracks_[static_cast<std::size_t>(t)];
    return track.last_detected ? track.last_detected->time : track.estimate.time;
  };
  std::stable_sort(due.begin(), due.end(),
                   [&](int a, int b) { return last_seen(a) < last_seen(b); });
  for (const int t : due) {
    const std::int64_t provisional = tracks_[static_cast<std::size_t>(t)].id;
    renumber(t, next_number_++);
    renamed.emplace_back(provisional, tracks_[static_cast<std::size_t>(t)].id);
  }
  // One pass over the look's associations and events for all of them (many tracks are
  // confirmed in one look when a load starts).
  std::unordered_map<std::int64_t, std::int64_t> number_of(renamed.begin(), renamed.end());
  const auto renumbered = [&](std::int64_t track) {
    const auto it = number_of.find(track);
    return it == number_of.end() ? track : it->second;
  };
  for (Association& a : frame.associations) a.track = renumbered(a.track);
  static constexpr std::string_view kName = "track ";
  for (TrackEvent& e : frame.events) {
    // This look's events name it by its number too ("son ... of track N").
    for (std::size_t at = e.detail.find(kName); at != std::string::npos;
         at = e.detail.find(kName, at + kName.size())) {
      const std::size_t from = at + kName.size();
      std::int64_t named = 0;
      const char* begin = e.detail.data() + from;
      const auto [end, error] = std::from_chars(begin, e.detail.data() + e.detail.size(), named);
      if (error != std::errc{}) continue;
      const std::int64_t number = renumbered(named);
      if (number != named) {
        e.detail.replace(from, static_cast<std::size_t>(end - begin), std::to_string(number));
      }
    }
    const std::int64_t number = renumbered(e.track);
    if (number == e.track) continue;
    if (e.type == TrackEventType::kConfirmed) e.detail = "tentative " + std::to_string(e.track);
    e.track = number;
  }
}

void TrackStore::erase_deleted() {
  // Deleted tracks are reported once, in the look that deletes them.
  const auto deleted = [](const PointTrack& t) { return t.life.status == TrackStatus::kDeleted; };
  const auto first = std::find_if(tracks_.begin(), tracks_.end(), deleted);
  if (first == tracks_.end()) return;
  const auto from = static_cast<std::size_t>(first - tracks_.begin());
  for (auto it = first; it != tracks_.end(); ++it) {
    if (deleted(*it)) slots_.erase(it->id);
  }
  tracks_.erase(std::remove_if(first, tracks_.end(), deleted), tracks_.end());
  // Only the tracks behind the first deleted one moved; their numbers are already keys.
  for (std::size_t i = from; i < tracks_.size(); ++i) slots_[tracks_[i].id] = static_cast<int>(i);
}

}  // namespace skytrack
