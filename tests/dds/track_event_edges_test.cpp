// The event types cross both edges by name: every enumerator, and a name the core does not
// know, come back from the JSON Lines writer/parser and the DDS conversion unchanged, under
// the names CONTRACTS.md §3 gives them.
#include <string>

#include <gtest/gtest.h>

#include "skytrack/core/track_event.hpp"
#include "skytrack/dds/conversion.hpp"
#include "skytrack/io/jsonl_reader.hpp"
#include "skytrack/io/jsonl_writer.hpp"

namespace skytrack {
namespace {

TrackFrame frame_of_every_event_type() {
  TrackFrame frame;
  frame.scan = 7;
  frame.time = 12.5;
  std::int64_t track = 1;
  for (const TrackEventType type : kTrackEventTypes) {
    frame.events.push_back({type, track++, "detail of " + std::string(to_string(type)), {}});
  }
  frame.events.push_back(event_from_name("a_newer_writers_type", track, "kept as read"));
  return frame;
}

TEST(TrackEventType, NamesParseBackToTheirType) {
  for (const TrackEventType type : kTrackEventTypes) {
    ASSERT_FALSE(to_string(type).empty());
    EXPECT_EQ(parse_track_event_type(to_string(type)), type) << to_string(type);
  }
  EXPECT_FALSE(parse_track_event_type("").has_value());
  EXPECT_FALSE(parse_track_event_type("Initiated").has_value());
}

TEST(TrackEventType, UnknownNameIsKeptAsOther) {
  const TrackEvent e = event_from_name("merged", 4, "x");
  EXPECT_EQ(e.type, TrackEventType::kOther);
  EXPECT_EQ(type_name(e), "merged");
  EXPECT_EQ(type_name(event_from_name("deleted", 4, "")), "deleted");
  EXPECT_TRUE(event_from_name("deleted", 4, "").other_type.empty());
}

TEST(TrackEventType, EveryTypeRoundTripsThroughJsonLines) {
  const TrackFrame frame = frame_of_every_event_type();
  const std::string line = io::to_json(frame);
  // GIVEN the names of the contract in the line
  EXPECT_NE(line.find(R"({"type":"branch_created","track":5,)"), std::string::npos) << line;
  EXPECT_NE(line.find(R"({"type":"a_newer_writers_type",)"), std::string::npos) << line;
  const auto back = io::parse_track_frame(line);
  ASSERT_TRUE(back) << back.error().message;
  EXPECT_EQ(*back, frame);
  EXPECT_EQ(io::to_json(*back), line);
}

TEST(TrackEventType, EveryTypeRoundTripsThroughDds) {
  const TrackFrame frame = frame_of_every_event_type();
  auto sample = dds::to_dds(frame);
  ASSERT_TRUE(sample) << sample.error().message;
  const auto& events = sample->get().events;
  ASSERT_EQ(events._length, frame.events.size());
  for (std::uint32_t i = 0; i < events._length; ++i) {
    EXPECT_EQ(std::string(events._buffer[i].type), type_name(frame.events[i]));
  }
  const auto back = dds::from_dds(sample->get());
  ASSERT_TRUE(back) << back.error().message;
  EXPECT_EQ(*back, frame);
}

}  // namespace
}  // namespace skytrack
