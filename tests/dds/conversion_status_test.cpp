// TrackerStatusReport -> TrackerStatus -> TrackerStatusReport round trips, and OwnedSample moves.
#include "skytrack/dds/conversion.hpp"

#include <utility>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace skytrack::dds {
namespace {

using ::testing::HasSubstr;

TrackerStatusReport status_report() {
  return {.instance = "skytrackd-1",
          .profile_name = "airspace_jpda",
          .profile_version = "3.1",
          .uptime = 3600.5,
          .scans_processed = 14400,
          .plots_processed = 1234567,
          .plots_rejected = {{"non_finite_range", 3}, {"no_form", 1}},
          .scans_rejected = {{"time_backwards", 2}},
          .scans_dropped = 5,
          .queue_depth = 2,
          .latency_p50 = 0.004,
          .latency_p99 = 0.020,
          .latency_max = 0.150,
          .tracks_tentative = 7,
          .tracks_confirmed = 31,
          .tracks_coasting = 4,
          .numeric_failures = 9};
}

TEST(TrackerStatusConversion, RoundTrips) {
  for (const TrackerStatusReport& status : {status_report(), TrackerStatusReport{}}) {
    auto sample = to_dds(status);
    ASSERT_TRUE(sample) << sample.error().message;
    auto back = from_dds(sample->get());
    ASSERT_TRUE(back) << back.error().message;
    EXPECT_EQ(*back, status);
  }
}

TEST(TrackerStatusConversion, LengthWithoutBufferIsAnErrorNamingTheField) {
  skytrack_dds_TrackerStatus s{};
  s.scans_rejected._length = 1;
  auto back = from_dds(s);
  ASSERT_FALSE(back);
  EXPECT_THAT(back.error().message, HasSubstr("scans_rejected"));
}

TEST(OwnedSample, MoveTransfersOwnership) {
  auto sample = to_dds(status_report());
  ASSERT_TRUE(sample);
  TrackerStatusSample moved = std::move(*sample);
  EXPECT_EQ(sample->get().instance, nullptr);
  EXPECT_STREQ(moved->instance, "skytrackd-1");
  TrackerStatusSample assigned;
  assigned = std::move(moved);
  EXPECT_STREQ(assigned->instance, "skytrackd-1");
  assigned.reset();
  EXPECT_EQ(assigned->plots_rejected._buffer, nullptr);
}

}  // namespace
}  // namespace skytrack::dds
