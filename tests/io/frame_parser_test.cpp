#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "skytrack/io/jsonl_reader.hpp"
#include "skytrack/io/jsonl_writer.hpp"

namespace skytrack::io {
namespace {

using ::testing::HasSubstr;

TEST(TruthFrameParser, ReadsTheContractExample) {
  const auto frame = parse_truth_frame(R"({"time": 420.0, "objects": [
  {"id": 7, "kind": "point", "position": [1000.0, 2000.0, 8000.0], "velocity": [250.0, 0.0, 0.0]},
  {"id": 9, "kind": "group", "position": [-500.0, 300.0], "velocity": [40.0, -40.0],
   "extent": [[400.0, 0.0], [0.0, 400.0]], "members": 15},
  {"id": 11, "kind": "extended", "position": [800.0, -200.0], "velocity": [9.8, -9.8],
   "extent": [[2500.0, 300.0], [300.0, 900.0]]}]})");
  ASSERT_TRUE(frame) << frame.error().message;
  ASSERT_EQ(frame->objects.size(), 3u);
  EXPECT_EQ(frame->objects[0].dims, 3);
  EXPECT_EQ(frame->objects[1].dims, 2);
  EXPECT_EQ(frame->objects[1].kind, ObjectKind::kGroup);
  EXPECT_EQ(frame->objects[1].members, 15);
  ASSERT_TRUE(frame->objects[2].extent);
  EXPECT_DOUBLE_EQ((*frame->objects[2].extent)(0, 1), 300.0);
}

TEST(TruthFrameParser, RejectsInvalidObjects) {
  const struct {
    const char* line;
    const char* reason;
  } cases[] = {
      {R"({"objects":[]})", "time: missing"},
      {R"({"time":1,"objects":[{"id":1,"kind":"blob","position":[0,0]}]})",
       "objects[0].kind: expected point, group or extended"},
      {R"({"time":1,"objects":[{"id":1,"position":[0]}]})",
       "objects[0].position: expected 2 or 3 numbers"},
      {R"({"time":1,"objects":[{"id":1,"position":[0,0],"velocity":[1,2,3]}]})", "dims differ"},
      {R"({"time":1,"objects":[{"id":1,"position":[0,0],"extent":[[1,2],[2,1]]}]})",
       "not positive definite"},
      {R"({"time":1,"objects":[{"id":1,"position":[0,0],"extent":[[1,0.5],[0,1]]}]})",
       "not symmetric"},
      // beyond int: was cast unchecked (fuzz finding, fuzz/seeds/truth_line)
      {R"({"time":1,"objects":[{"id":1,"position":[0,0],"members":10995113138}]})",
       "objects[0].members: 10995113138 is beyond 2147483647"},
  };
  for (const auto& c : cases) {
    const auto frame = parse_truth_frame(c.line);
    ASSERT_FALSE(frame) << c.line;
    EXPECT_THAT(frame.error().message, HasSubstr(c.reason)) << c.line;
  }
}

TEST(TrackFrameParser, ReadsTheContractExample) {
  const auto frame = parse_track_frame(R"({"sensor": 1, "scan": 42, "time": 420.0,
 "tracks": [
  {"id": 12, "status": "confirmed", "kind": "point",
   "position": [1003.1, 1996.2, 8010.0], "velocity": [248.7, 1.2, 0.0],
   "covariance": [100.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 25.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 100.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 25.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 100.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 25.0],
   "modes": {"cv": 0.91, "ct_left": 0.06, "ct_right": 0.03}, "quality": 0.97}],
 "associations": [{"track": 12, "plot": 3, "probability": 0.93}],
 "events": [{"type": "branch_created", "track": 12, "detail": "son 2 from plot 5"}]})");
  ASSERT_TRUE(frame) << frame.error().message;
  ASSERT_EQ(frame->tracks.size(), 1u);
  const TrackReport& track = frame->tracks[0];
  EXPECT_EQ(track.status, TrackStatus::kConfirmed);
  EXPECT_EQ(track.covariance.size(), 36u);
  ASSERT_EQ(track.modes.size(), 3u);
  EXPECT_EQ(track.modes[1].first, "ct_left");
  EXPECT_EQ(track.quality, 0.97);
  EXPECT_EQ(frame->associations[0], (Association{12, 3, 0.93, std::nullopt}));
  EXPECT_EQ(frame->events[0].detail, "son 2 from plot 5");
}

TEST(TrackFrameParser, RejectsInvalidTracks) {
  const struct {
    const char* line;
    const char* reason;
  } cases[] = {
      {R"({"sensor":0,"scan":0,"time":0})", "tracks: missing"},
      {R"({"sensor":0,"scan":0,"time":0,"tracks":[{"id":1,"position":[0,0]}]})",
       "tracks[0].status: missing"},
      {R"({"sensor":0,"scan":0,"time":0,"tracks":[{"id":1,"status":"lost","position":[0,0]}]})",
       "tracks[0].status: expected"},
      {R"({"sensor":0,"scan":0,"time":0,"tracks":[{"id":1,"status":"confirmed","position":[0,0],"covariance":[1,2,3]}]})",
       "expected 16 numbers for 2-D"},
      {R"({"sensor":0,"scan":0,"time":0,"tracks":[],"associations":[{"track":1,"plot":2,"probability":1.5}]})",
       "associations[0].probability: not in [0, 1]"},
      {R"({"sensor":0,"scan":0,"time":0,"tracks":[],"events":[{"track":1}]})",
       "events[0].type: missing"},
      // beyond int: was cast unchecked (fuzz finding, fuzz/seeds/track_line)
      {R"({"sensor":0,"scan":0,"time":0,"tracks":[{"id":1,"status":"confirmed","position":[0,0],"members":10995113138}]})",
       "tracks[0].members: 10995113138 is beyond 2147483647"},
      {R"({"sensor":0,"scan":0,"time":0,"tracks":[{"id":1,"status":"confirmed","position":[0,0],"sources":[{"sensor":1}]}]})",
       "tracks[0].sources[0].track: missing"},
      {R"({"sensor":0,"scan":0,"time":0,"tracks":[{"id":1,"status":"confirmed","position":[0,0],"sources":[{"sensor":-1,"track":2}]}]})",
       "tracks[0].sources[0].sensor: out of range"},
  };
  for (const auto& c : cases) {
    const auto frame = parse_track_frame(c.line);
    ASSERT_FALSE(frame) << c.line;
    EXPECT_THAT(frame.error().message, HasSubstr(c.reason)) << c.line;
  }
}

TEST(TrackFrameWriter, RoundTripsBitExactly) {
  TrackFrame frame;
  frame.sensor = 2;
  frame.scan = 99;
  frame.time = 990.1;
  TrackReport point;
  point.id = 12;
  point.status = TrackStatus::kCoasting;
  point.dims = 3;
  point.position = {1003.1, 1996.2, 8010.0 / 3.0};
  point.velocity = {248.7, 1.2, -0.3};
  point.covariance.assign(36, 0.0);
  for (int i = 0; i < 6; ++i) point.covariance[i * 7] = 10.0 + i / 7.0;
  point.modes = {{"cv", 0.91}, {"ct_left", 0.06}, {"ct_right", 0.03}};
  point.quality = 0.97;
  TrackReport group;
  group.id = 13;
  group.status = TrackStatus::kConfirmed;
  group.kind = ObjectKind::kGroup;
  group.position = {-500.0, 300.0, 0.0};
  group.extent = (Eigen::Matrix2d() << 400.0, 10.0, 10.0, 300.0).finished();
  group.members = 15;
  group.sources = {{1, 12}, {4, 1099511627777}};
  frame.tracks = {point, group};
  frame.associations = {{12, 3, 0.93, std::nullopt}, {13, 4, 1.0, 41}};
  frame.events = {{TrackEventType::kBranchCreated, 12, "son 2 from \"plot\" 5\n", {}}};

  const auto parsed = parse_track_frame(to_json(frame));
  ASSERT_TRUE(parsed) << parsed.error().message;
  EXPECT_EQ(*parsed, frame);
}

TEST(TruthFrameWriter, RoundTripsBitExactly) {
  TruthFrame frame;
  frame.time = 12.3;
  TruthObject object;
  object.id = 4;
  object.kind = ObjectKind::kExtended;
  object.position = {800.0, -200.0, 0.0};
  object.velocity = {9.82, -9.82, 0.0};
  object.extent = (Eigen::Matrix2d() << 2500.0, 300.0, 300.0, 900.0).finished();
  frame.objects = {object};
  const auto parsed = parse_truth_frame(to_json(frame));
  ASSERT_TRUE(parsed) << parsed.error().message;
  EXPECT_EQ(*parsed, frame);
}

}  // namespace
}  // namespace skytrack::io
