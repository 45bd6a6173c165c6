#include <cstdint>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "skytrack/tracking/track_store.hpp"

namespace skytrack {
namespace {

PointTrack tentative(std::int64_t id, double last_seen) {
  PointTrack track;
  track.id = id;
  track.estimate.time = last_seen;
  return track;
}

TEST(TrackStore, ConfirmedFathersAreNumberedInTheOrderOfTheirLatestPlots) {
  TrackStore store;  // GIVEN three tentative fathers, the later-made one seen first
  const std::int64_t a = store.provisional(), b = store.provisional(), c = store.provisional();
  store.add(tentative(a, 20.0));
  store.add(tentative(b, 10.0));
  store.add(tentative(c, 5.0));
  store[0].life.status = TrackStatus::kConfirmed;
  store[1].life.status = TrackStatus::kConfirmed;
  TrackFrame frame;
  frame.associations.push_back({a, 7, 1.0, std::nullopt});
  frame.events.push_back({TrackEventType::kConfirmed, a, "", {}});
  std::vector<std::pair<std::int64_t, std::int64_t>> renamed;
  store.number_confirmed(frame, renamed);  // WHEN two of them are confirmed
  // THEN the one seen earlier gets number 1, the tentative one keeps its provisional number,
  // and this frame names the renamed tracks by their numbers
  EXPECT_EQ(store[1].id, 1);
  EXPECT_EQ(store[0].id, 2);
  EXPECT_EQ(store[2].id, c);
  ASSERT_EQ(renamed.size(), 2u);
  EXPECT_EQ(renamed[0], std::make_pair(b, std::int64_t{1}));
  EXPECT_EQ(frame.associations[0].track, 2);
  EXPECT_EQ(frame.events[0].track, 2);
  EXPECT_EQ(store.slot(2), 0);
  EXPECT_EQ(store.slot(a), -1);
}

TEST(TrackStore, ErasingTheDeletedKeepsTheSlotsOfTheOthers) {
  TrackStore store;  // GIVEN three tracks, the middle one deleted
  for (std::int64_t id : {11, 12, 13}) store.add(tentative(id, 0.0));
  store[1].life.status = TrackStatus::kDeleted;
  store.erase_deleted();        // WHEN the deleted are dropped
  ASSERT_EQ(store.size(), 2u);  // THEN the others are found by number where they now are
  EXPECT_EQ(store.slot(11), 0);
  EXPECT_EQ(store.slot(12), -1);
  EXPECT_EQ(store.slot(13), 1);
}

TEST(TrackStore, ABranchTakingItsFathersNumberIsFoundUnderIt) {
  TrackStore store;  // GIVEN a father and a branch with a provisional number
  store.add(tentative(5, 0.0));
  const std::int64_t son = store.provisional();
  const int t = store.add(tentative(son, 0.0));
  store.renumber(t, 5);         // WHEN the branch replaces the father
  EXPECT_EQ(store.slot(5), t);  // THEN the number names the branch's slot
  EXPECT_EQ(store.slot(son), -1);
  EXPECT_EQ(store[static_cast<std::size_t>(t)].id, 5);
}

}  // namespace
}  // namespace skytrack
