// Secondary-radar plots with a flight level and no elevation (plot_measurement.hpp).
#include <cmath>

#include <gtest/gtest.h>

#include "skytrack/core/transponder.hpp"
#include "skytrack/geometry/altitude.hpp"
#include "skytrack/geometry/frames.hpp"
#include "skytrack/measurement/plot_measurement.hpp"

namespace skytrack {
namespace {

const config::MeasurementSigmas kDefaults;  // height 15 m

/// The plot a secondary radar on `platform` reports for a target at `p` (no noise): slant
/// range, azimuth, and the target's altitude as a flight level.
Plot reply_from(const Eigen::Vector3d& p, const PlatformState& platform) {
  const PolarPoint polar = enu_to_polar(p, platform);
  Plot plot;
  plot.id = 3;
  plot.range = polar.range;
  plot.azimuth = polar.azimuth;
  plot.flight_level = altitude_of(p) / (100.0 * kFeetToMetres);
  return plot;
}

PlotScan scan_from(const PlatformState& platform) {
  PlotScan scan;
  scan.time = 4.0;
  scan.platform = platform;
  return scan;
}

TEST(Altitude, FarPointsOnTheFramePlaneLieAboveTheSea) {
  // GIVEN the frame's origin on the sea; THEN a point on the plane 270 km away is 5.7 km up
  EXPECT_NEAR(altitude_of({270e3, 0.0, 0.0}), 270e3 * 270e3 / (2.0 * kEarthRadius), 5.0);
  EXPECT_NEAR(altitude_of({0.0, 0.0, 1234.0}), 1234.0, 1e-6);
  // AND height_above_platform inverts it along a slant range from the origin
  const Eigen::Vector3d p{120e3, -50e3, 3000.0};
  EXPECT_NEAR(height_above_platform(p.norm(), altitude_of(p), Eigen::Vector3d::Zero()), p.z(),
              1e-3);
}

TEST(FlightLevel, ThreeDTrackerMeasuresSlantRangeAzimuthAndAltitude) {
  // GIVEN a reply at FL 350 with no elevation, seen by a 3-D tracker
  PlatformState platform;
  platform.position = {0.0, 0.0, 600.0};
  const Eigen::Vector3d aircraft{60e3, 80e3, 10e3};
  const auto m =
      measurement_from_plot(reply_from(aircraft, platform), scan_from(platform), kDefaults, 3);
  ASSERT_TRUE(m) << m.error().message;
  // THEN it is a (range, azimuth, altitude) measurement with the profile's height sigma
  EXPECT_EQ(m->model.kind, MeasurementKind::kPolarHeight);
  ASSERT_EQ(m->z.size(), 3);
  EXPECT_NEAR(m->z[2], altitude_of(aircraft), 1e-6);
  EXPECT_DOUBLE_EQ(m->model.sigma[2], kDefaults.height);
  // AND the model's prediction at the aircraft is the measurement itself
  StateLayout layout;
  layout.dims = 3;
  StateVec x = StateVec::Zero(layout.size());
  for (int a = 0; a < 3; ++a) x[StateLayout::position(a)] = aircraft[a];
  const MeasVec zhat = m->model.measure(layout, x);
  EXPECT_LT((m->model.residual(m->z, zhat)).cwiseAbs().maxCoeff(), 1e-6);
  // AND its approximate position is the aircraft's, within a metre
  EXPECT_LT((approximate_position(*m) - aircraft).norm(), 1.0);
}

TEST(FlightLevel, ApproximatePositionHoldsOnATiltedMovingPlatform) {
  // GIVEN an interrogator on a pitched, rolled aircraft away from the frame's origin
  PlatformState platform;
  platform.position = {-20e3, 5e3, 7000.0};
  platform.attitude = {0.8, 0.05, -0.1};
  const Eigen::Vector3d aircraft{25e3, 40e3, 9500.0};
  const auto m =
      measurement_from_plot(reply_from(aircraft, platform), scan_from(platform), kDefaults, 3);
  ASSERT_TRUE(m);
  // THEN the plot is placed on the aircraft, although the local vertical there tilts by
  // 3 mrad (180 m over the 57 km to the aircraft if ignored)
  EXPECT_LT((approximate_position(*m) - aircraft).norm(), 0.01);
}

TEST(FlightLevel, TwoDTrackerTurnsSlantRangeIntoHorizontalRange) {
  // GIVEN FL 220 (6.7 km) seen at 9.8 km slant range, and a 2-D tracker
  const PlatformState platform;
  const Eigen::Vector3d aircraft{0.0, 7230.0, 6706.0 - 7230.0 * 7230.0 / (2.0 * kEarthRadius)};
  const auto m =
      measurement_from_plot(reply_from(aircraft, platform), scan_from(platform), kDefaults, 2);
  ASSERT_TRUE(m);
  // THEN the horizontal range is the aircraft's, not the slant range
  EXPECT_EQ(m->model.kind, MeasurementKind::kPolar);
  EXPECT_NEAR(m->z[0], 7230.0, 0.01);
  EXPECT_GT(aircraft.norm() - m->z[0], 2500.0);
  // AND its sigma grows by r / rho and the height's share (first-order propagation)
  const double r = aircraft.norm();
  EXPECT_NEAR(m->model.sigma[0],
              std::hypot(kDefaults.range * r, aircraft.z() * kDefaults.height) / 7230.0, 1e-6);
}

TEST(FlightLevel, ElevationWinsOverTheFlightLevelAndCartesianPlotsIgnoreIt) {
  const PlatformState platform;
  Plot plot = reply_from({30e3, 30e3, 5000.0}, platform);
  plot.elevation = 0.1;
  // GIVEN a plot with both: THEN it is an ordinary 3-D polar plot
  auto m = measurement_from_plot(plot, scan_from(platform), kDefaults, 3);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->model.kind, MeasurementKind::kPolar);
  EXPECT_DOUBLE_EQ(m->z[2], 0.1);
  // GIVEN a Cartesian plot with a flight level: THEN the flight level is not a measurement
  Plot cartesian;
  cartesian.form = PlotForm::kCartesian;
  cartesian.x = 100.0;
  cartesian.y = 200.0;
  cartesian.flight_level = 100.0;
  m = measurement_from_plot(cartesian, scan_from(platform), kDefaults, 3);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->z.size(), 2);
}

TEST(FlightLevel, VolumeElementOfAltitudePlotsIsTheSlantRange) {
  // GIVEN dx dy dz = r dr daz dh (rho = sqrt(r^2 - dz^2)): THEN a density per m^3 converts by r
  const MeasurementModel model = MeasurementModel::polar_height({}, false, MeasVec::Ones(3));
  MeasVec z(3);
  z << 40e3, 0.3, 9000.0;
  EXPECT_DOUBLE_EQ(model.volume_element(z), 40e3);
  EXPECT_DOUBLE_EQ(MeasurementModel::cartesian(2, 2, MeasVec::Ones(2)).volume_element(z), 1.0);
}

}  // namespace
}  // namespace skytrack
