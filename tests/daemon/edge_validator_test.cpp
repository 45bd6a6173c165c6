#include "skytrack/daemon/edge_validator.hpp"

#include <cmath>
#include <limits>

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

TEST(EdgeValidator, AcceptsIncreasingScansPerSensorIndependently) {
  EdgeValidator v;
  EXPECT_FALSE(v.check(scan_of(1, 1, 0.0)));
  EXPECT_FALSE(v.check(scan_of(2, 7, 100.0)));
  EXPECT_FALSE(v.check(scan_of(1, 2, 4.0)));
  EXPECT_FALSE(v.check(scan_of(2, 8, 104.0)));
}

TEST(EdgeValidator, NamesDuplicateOutOfOrderAndBackwardScans) {
  EdgeValidator v;
  ASSERT_FALSE(v.check(scan_of(1, 5, 20.0)));
  EXPECT_EQ(v.check(scan_of(1, 5, 20.0)), reason::kDuplicateScan);
  EXPECT_EQ(v.check(scan_of(1, 3, 12.0)), reason::kOutOfOrderScan);
  EXPECT_EQ(v.check(scan_of(1, 6, 19.0)), reason::kTimeBackwards);
  // a rejected scan does not advance the clock: scan 6 at a later time is still fine
  EXPECT_FALSE(v.check(scan_of(1, 6, 24.0)));
}

TEST(EdgeValidator, RejectsUnknownSensorsOnlyWhenSensorsAreListed) {
  EdgeValidator listed({1, 4});
  EXPECT_FALSE(listed.check(scan_of(4, 1, 0.0)));
  EXPECT_EQ(listed.check(scan_of(2, 1, 0.0)), reason::kUnknownSensor);
  EdgeValidator any;
  EXPECT_FALSE(any.check(scan_of(2, 1, 0.0)));
}

TEST(EdgeValidator, RejectsNonFiniteTimeAndPlatform) {
  EdgeValidator v;
  EXPECT_EQ(v.check(scan_of(1, 1, std::nan(""))), reason::kNonFiniteTime);
  PlotScan bad = scan_of(1, 1, 0.0);
  bad.platform.velocity.x() = std::numeric_limits<double>::infinity();
  EXPECT_EQ(v.check(bad), reason::kNonFinitePlatform);
  EXPECT_FALSE(v.check(scan_of(1, 1, 0.0)));  // the bad ones left no trace
}

}  // namespace
}  // namespace skytrack::daemon
