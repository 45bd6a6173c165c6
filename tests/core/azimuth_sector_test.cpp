#include <gtest/gtest.h>

#include "skytrack/core/plot.hpp"

namespace skytrack {
namespace {

TEST(AzimuthSector, ContainsClockwiseFromFromToTo) {
  const AzimuthSector east{1.0, 2.0};
  EXPECT_TRUE(east.contains(1.5));
  EXPECT_TRUE(east.contains(1.0));
  EXPECT_FALSE(east.contains(2.5));
  EXPECT_FALSE(east.contains(-1.5));
  // A sector across +-pi (south): from 3.0 clockwise to -3.0.
  const AzimuthSector south{3.0, -3.0};
  EXPECT_TRUE(south.contains(3.1));
  EXPECT_TRUE(south.contains(-3.1));
  EXPECT_FALSE(south.contains(0.0));
}

}  // namespace
}  // namespace skytrack
