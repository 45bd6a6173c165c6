#include "skytrack/tracking/track_store.hpp"

#include <algorithm>
#include <string>

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
    const std::int64_t number = tracks_[static_cast<std::size_t>(t)].id;
    renamed.emplace_back(provisional, number);
    for (Association& a : frame.associations) {
      if (a.track == provisional) a.track = number;
    }
    const std::string old_name = "track " + std::to_string(provisional);
    const std::string new_name = "track " + std::to_string(number);
    for (TrackEvent& e : frame.events) {
      // This look's events name it by its number too ("son ... of track N").
      for (std::size_t at = e.detail.find(old_name); at != std::string::npos;
           at = e.detail.find(old_name, at + new_name.size())) {
        e.detail.replace(at, old_name.size(), new_name);
      }
      if (e.track != provisional) continue;
      e.track = number;
      if (e.type == TrackEventType::kConfirmed)
        e.detail = "tentative " + std::to_string(provisional);
    }
  }
}

void TrackStore::erase_deleted() {
  // Deleted tracks are reported once, in the look that deletes them.
  std::erase_if(tracks_,
                [](const PointTrack& t) { return t.life.status == TrackStatus::kDeleted; });
  slots_.clear();
  for (std::size_t i = 0; i < tracks_.size(); ++i) slots_[tracks_[i].id] = static_cast<int>(i);
}

}  // namespace skytrack
