#include "skytrack/daemon/edge_validator.hpp"

#include <gtest/gtest.h>

namespace skytrack::daemon {
namespace {

PlotScan scan_of(std::uint32_t sensor, std::uint64_t number, double time) {
  PlotScan scan;
  scan.sensor = sensor;
  scan.scan = number;
  scan.time = time;
  return scan;
}

TEST(EdgeValidator, RejectsUnknownSensorsOnlyWhenSensorsAreListed) {
  const EdgeValidator listed({1, 4});
  EXPECT_FALSE(listed.check(scan_of(4, 1, 0.0), 0.0));
  EXPECT_EQ(listed.check(scan_of(2, 1, 0.0), 0.0), reason::kUnknownSensor);
  const EdgeValidator any;
  EXPECT_FALSE(any.check(scan_of(2, 1, 0.0), 0.0));
}

TEST(EdgeValidator, RefusesBatchesAheadOfTheHostClockOnlyWhenConfigured) {
  const double now = 1.7e9;  // 2023, UTC seconds since 1970
  const EdgeValidator bounded({}, 60.0);
  EXPECT_FALSE(bounded.check(scan_of(1, 1, now + 59.0), now));
  EXPECT_EQ(bounded.check(scan_of(1, 2, now + 50.0 * 3.156e7), now), reason::kAheadOfHost);
  // A recording replayed years later, or a clock since power-on, is behind: never refused.
  EXPECT_FALSE(bounded.check(scan_of(1, 3, 120.0), now));
  const EdgeValidator unbounded;
  EXPECT_FALSE(unbounded.check(scan_of(1, 4, now + 50.0 * 3.156e7), now));
}

}  // namespace
}  // namespace skytrack::daemon
