#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "skytrack/geometry/angles.hpp"
#include "skytrack/geometry/frames.hpp"

namespace skytrack {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTol = 1e-9;

void expect_near(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double tol = kTol) {
  EXPECT_NEAR((a - b).norm(), 0.0, tol) << "got " << a.transpose() << " expected " << b.transpose();
}

TEST(Frames, AzimuthIsClockwiseFromNorthForALevelPlatform) {
  const PlatformState level;
  expect_near(polar_to_enu({1000.0, 0.0, 0.0}, level), {0.0, 1000.0, 0.0});        // north
  expect_near(polar_to_enu({1000.0, kPi / 2, 0.0}, level), {1000.0, 0.0, 0.0});    // east
  expect_near(polar_to_enu({1000.0, kPi, 0.0}, level), {0.0, -1000.0, 0.0});       // south
  expect_near(polar_to_enu({1000.0, -kPi / 2, 0.0}, level), {-1000.0, 0.0, 0.0});  // west
  // az 30 deg, el 10 deg by hand: x = r sin(az) cos(el), y = r cos(az) cos(el), z = r sin(el)
  const double r = 5000.0, az = kPi / 6, el = kPi / 18;
  expect_near(polar_to_enu({r, az, el}, level),
              {r * 0.5 * std::cos(el), r * std::sqrt(3.0) / 2 * std::cos(el), r * std::sin(el)});
}

TEST(Frames, PlatformPositionOffsetsThePlot) {
  PlatformState platform;
  platform.position = {100.0, -200.0, 8000.0};
  expect_near(polar_to_enu({1000.0, kPi / 2, 0.0}, platform), {1100.0, -200.0, 8000.0});
}

TEST(Frames, HeadingRotatesTheBodyClockwise) {
  // A platform heading east (90 deg): a plot on its nose lies east, one on its right south.
  PlatformState platform;
  platform.attitude = {kPi / 2, 0.0, 0.0};
  expect_near(polar_to_enu({1000.0, 0.0, 0.0}, platform), {1000.0, 0.0, 0.0});
  expect_near(polar_to_enu({1000.0, kPi / 2, 0.0}, platform), {0.0, -1000.0, 0.0});
}

TEST(Frames, PitchRaisesTheNoseAndRollLowersTheRightWing) {
  PlatformState pitched;
  pitched.attitude = {0.0, kPi / 6, 0.0};  // nose 30 deg up
  expect_near(polar_to_enu({1000.0, 0.0, 0.0}, pitched), {0.0, 1000.0 * std::sqrt(3.0) / 2, 500.0});
  PlatformState rolled;
  rolled.attitude = {0.0, 0.0, kPi / 6};  // right wing 30 deg down
  expect_near(polar_to_enu({1000.0, kPi / 2, 0.0}, rolled),
              {1000.0 * std::sqrt(3.0) / 2, 0.0, -500.0});
}

TEST(Frames, HeadingThenPitchComposeInYawPitchRollOrder) {
  // Heading east and nose 30 deg up: the nose points east and up.
  PlatformState platform;
  platform.attitude = {kPi / 2, kPi / 6, 0.0};
  expect_near(polar_to_enu({1000.0, 0.0, 0.0}, platform),
              {1000.0 * std::sqrt(3.0) / 2, 0.0, 500.0});
}

TEST(Frames, EnuToPolarInvertsPolarToEnu) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  std::uniform_real_distribution<double> small(-0.5, 0.5);
  for (int i = 0; i < 200; ++i) {
    PlatformState platform;
    platform.position = {angle(rng) * 1e3, angle(rng) * 1e3, 8000.0};
    platform.attitude = {angle(rng), small(rng), small(rng)};
    const PolarPoint polar{1000.0 + 5e4 * (angle(rng) + kPi), angle(rng), small(rng) * 2.0};
    const PolarPoint back = enu_to_polar(polar_to_enu(polar, platform), platform);
    EXPECT_NEAR(back.range, polar.range, 1e-6);
    EXPECT_NEAR(wrap_angle(back.azimuth - polar.azimuth), 0.0, 1e-12);
    EXPECT_NEAR(back.elevation, polar.elevation, 1e-12);
  }
}

TEST(Frames, RangeRateUsesTheRelativeVelocity) {
  PlatformState platform;
  platform.velocity = {0.0, 200.0, 0.0};  // flying north at 200 m/s
  // Target 10 km north flying south at 300 m/s: closing at 500 m/s.
  EXPECT_NEAR(range_rate({0.0, 10000.0, 0.0}, {0.0, -300.0, 0.0}, platform), -500.0, 1e-12);
  // Target due east, flying north as fast as the platform: range constant.
  EXPECT_NEAR(range_rate({10000.0, 0.0, 0.0}, {0.0, 200.0, 0.0}, platform), 0.0, 1e-12);
}

TEST(Angles, WrapToPlusMinusPi) {
  EXPECT_NEAR(wrap_angle(3 * kPi / 2), -kPi / 2, 1e-15);
  EXPECT_NEAR(wrap_angle(-3 * kPi / 2), kPi / 2, 1e-15);
  EXPECT_NEAR(wrap_angle(kPi - 0.01 - (-kPi + 0.01)), -0.02, 1e-12);
  EXPECT_NEAR(wrap_angle_positive(-0.5), 2 * kPi - 0.5, 1e-15);
}

}  // namespace
}  // namespace skytrack
