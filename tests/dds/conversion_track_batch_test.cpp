// TrackFrame -> TrackBatch -> TrackFrame round trips and errors for malformed TrackBatch samples.
#include "skytrack/dds/conversion.hpp"

#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "conversion_test_support.hpp"

namespace skytrack::dds {
namespace {

using test::frame_with;
using test::group_track;
using test::track_2d;
using test::track_3d;
using ::testing::HasSubstr;

TrackFrame round_trip(const TrackFrame& frame) {
  auto sample = to_dds(frame);
  EXPECT_TRUE(sample) << sample.error().message;
  if (!sample) return {};
  auto back = from_dds(sample->get());
  EXPECT_TRUE(back) << back.error().message;
  return back ? *back : TrackFrame{};
}

TEST(TrackBatchConversion, TracksAssociationsAndEventsRoundTrip) {
  TrackReport extended = group_track();
  extended.id = 21;
  extended.kind = ObjectKind::kExtended;
  extended.status = TrackStatus::kDeleted;
  extended.members.reset();
  extended.quality = 0.0;
  const TrackFrame frame = frame_with({track_2d(), track_3d(), group_track(), extended});
  EXPECT_EQ(round_trip(frame), frame);
}

TEST(TrackBatchConversion, FusedTracksKeepTheirSources) {
  TrackReport fused = track_2d();
  fused.sources = {{1, 12}, {2, 7}};
  TrackReport single = group_track();
  single.sources = {{3, 1099511627776}};
  const TrackFrame frame = frame_with({track_3d(), fused, single});
  const TrackFrame back = round_trip(frame);
  EXPECT_EQ(back, frame);
  EXPECT_TRUE(back.tracks[0].sources.empty());
}

TEST(TrackBatchConversion, SourceNamingNoTrackIsRefused) {
  TrackReport fused = track_2d();
  fused.sources = {{1, 12}};
  auto sample = to_dds(frame_with({fused}));
  ASSERT_TRUE(sample);
  sample->get().track_sources._buffer[0].track_index = 5;
  const auto back = from_dds(sample->get());
  ASSERT_FALSE(back);
  EXPECT_THAT(back.error().message,
              HasSubstr("track_sources[0].track_index: 5 is not a track index"));
}

TEST(TrackBatchConversion, ThreeDimensionalTrackWithoutCovarianceRoundTrips) {
  TrackReport t = track_3d();
  t.covariance.clear();
  t.modes.clear();
  const TrackFrame frame = frame_with({t});
  auto sample = to_dds(frame);
  ASSERT_TRUE(sample);
  EXPECT_EQ(sample->get().tracks._buffer[0].covariance_dim, 0);
  EXPECT_EQ(sample->get().mode_names._length, 0u);
  EXPECT_EQ(round_trip(frame), frame);
}

TEST(TrackBatchConversion, EmptyFrameRoundTrips) {
  TrackFrame frame;
  frame.sensor = 3;
  frame.scan = 1;
  frame.time = 0.5;
  EXPECT_EQ(round_trip(frame), frame);
}

TEST(TrackBatchConversion, ModesAreSentOnceAndReorderedToTheBatchOrder) {
  TrackReport reordered = track_3d();
  reordered.modes = {{"ct_right", 0.2}, {"cv", 0.7}, {"ct_left", 0.1}};
  auto sample = to_dds(frame_with({track_2d(), reordered}));
  ASSERT_TRUE(sample);
  ASSERT_EQ(sample->get().mode_names._length, 3u);
  EXPECT_STREQ(sample->get().mode_names._buffer[2], "ct_right");
  auto back = from_dds(sample->get());
  ASSERT_TRUE(back);
  const std::vector<std::pair<std::string, double>> expected = {
      {"cv", 0.7}, {"ct_left", 0.1}, {"ct_right", 0.2}};
  EXPECT_EQ(back->tracks[1].modes, expected);
}

TEST(TrackBatchConversion, CoreValuesTheIdlCannotCarryAreErrorsNamingTheField) {
  const auto error_of = [](TrackFrame frame) {
    auto sample = to_dds(frame);
    return sample ? std::string("no error") : sample.error().message;
  };
  TrackReport bad_dims = track_2d();
  bad_dims.dims = 4;
  EXPECT_THAT(error_of(frame_with({bad_dims})), HasSubstr("tracks[0].dims"));
  TrackReport bad_cov = track_3d();
  bad_cov.covariance.resize(16);  // a 2-D covariance on a 3-D track
  EXPECT_THAT(error_of(frame_with({track_2d(), bad_cov})), HasSubstr("tracks[1].covariance"));
  TrackReport other_models = track_3d();
  other_models.modes = {{"cv", 0.5}, {"ca", 0.25}, {"ct_right", 0.25}};
  EXPECT_THAT(error_of(frame_with({track_2d(), other_models})), HasSubstr("tracks[1].modes"));
  TrackReport negative = group_track();
  negative.members = -2;
  EXPECT_THAT(error_of(frame_with({negative})), HasSubstr("tracks[0].members"));
  TrackFrame nul = frame_with({});
  nul.events[1].detail = std::string("a\0b", 3);
  EXPECT_THAT(error_of(nul), HasSubstr("events[1].detail"));
}

TEST(TrackBatchConversion, MalformedSamplesAreErrorsNamingTheField) {
  // GIVEN a valid sample, WHEN one field is corrupted, THEN the error names it
  auto sample = to_dds(frame_with({track_2d(), track_3d()}));
  ASSERT_TRUE(sample);
  skytrack_dds_Track& t = sample->get().tracks._buffer[1];
  const auto error_of = [&] {
    auto back = from_dds(sample->get());
    return back ? std::string("no error") : back.error().message;
  };
  t.dims = 5;
  EXPECT_THAT(error_of(), HasSubstr("tracks[1].dims"));
  t.dims = 3;
  t.covariance_dim = 5;
  EXPECT_THAT(error_of(), HasSubstr("tracks[1].covariance_dim"));
  t.covariance_dim = 4;  // a 4x4 covariance on a 3-D track
  EXPECT_THAT(error_of(), HasSubstr("tracks[1].covariance_dim"));
  t.covariance_dim = 6;
  t.mode_probabilities._length = 2;
  EXPECT_THAT(error_of(), HasSubstr("tracks[1].mode_probabilities"));
  t.mode_probabilities._length = 3;
  const std::uint32_t bad_status = 9;
  std::memcpy(&t.status, &bad_status, sizeof bad_status);
  EXPECT_THAT(error_of(), HasSubstr("tracks[1].status"));
  t.status = skytrack_dds_TRACK_DELETED;
  std::memcpy(&t.kind, &bad_status, sizeof bad_status);
  EXPECT_THAT(error_of(), HasSubstr("tracks[1].kind"));
  t.kind = skytrack_dds_OBJECT_POINT;
  t.members = -3;
  EXPECT_THAT(error_of(), HasSubstr("tracks[1].members"));
  t.members = -1;
  EXPECT_EQ(error_of(), "no error");
}

}  // namespace
}  // namespace skytrack::dds
