#include "skytrack/measurement/plot_measurement.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>

#include "skytrack/geometry/frames.hpp"

namespace skytrack {
namespace {

constexpr double kPi = std::numbers::pi;
const config::MeasurementSigmas kDefaults;  // range 30, az 0.003, el 0.006, rdot 2, x/y 50, z 100

StateLayout make_layout(int dims) {
  StateLayout layout;
  layout.dims = dims;
  return layout;
}

Plot cartesian_plot(double x, double y, std::optional<double> z = std::nullopt) {
  Plot plot;
  plot.id = 7;
  plot.form = PlotForm::kCartesian;
  plot.x = x;
  plot.y = y;
  plot.z = z;
  return plot;
}

Plot polar_plot(double range, double azimuth, std::optional<double> elevation = std::nullopt,
                std::optional<double> range_rate = std::nullopt) {
  Plot plot;
  plot.id = 11;
  plot.form = PlotForm::kPolar;
  plot.range = range;
  plot.azimuth = azimuth;
  plot.elevation = elevation;
  plot.range_rate = range_rate;
  return plot;
}

PlotScan scan_at(double time) {
  PlotScan scan;
  scan.time = time;
  return scan;
}

TEST(PlotMeasurement, CartesianPlotsFollowTheTrackerDimension) {
  const PlotScan scan = scan_at(10.0);
  // GIVEN x, y, z: a 3-D tracker measures all three, a 2-D tracker drops z
  auto m3 = measurement_from_plot(cartesian_plot(1, 2, 3), scan, kDefaults, 3);
  ASSERT_TRUE(m3);
  EXPECT_EQ(m3->model.kind, MeasurementKind::kCartesian);
  EXPECT_EQ(m3->z.size(), 3);
  EXPECT_EQ(m3->z[2], 3.0);
  EXPECT_EQ(m3->model.sigma[2], 100.0);
  auto m2 = measurement_from_plot(cartesian_plot(1, 2, 3), scan, kDefaults, 2);
  ASSERT_TRUE(m2);
  EXPECT_EQ(m2->z.size(), 2);
  // GIVEN only x, y: a 3-D tracker measures x, y of its 3-D state
  auto xy3 = measurement_from_plot(cartesian_plot(1, 2), scan, kDefaults, 3);
  ASSERT_TRUE(xy3);
  EXPECT_EQ(xy3->z.size(), 2);
  const MeasJacobian H = xy3->model.jacobian(make_layout(3), StateVec::Zero(6));
  EXPECT_EQ(H(0, 0), 1.0);
  EXPECT_EQ(H(1, 2), 1.0);
  EXPECT_EQ(H.row(0).sum() + H.row(1).sum(), 2.0);
  EXPECT_EQ(xy3->plot_id, 7);
  EXPECT_EQ(xy3->time, 10.0);
}

TEST(PlotMeasurement, PolarPlotsKeepTheirComponentsInOrder) {
  PlotScan scan = scan_at(3.0);
  Plot plot = polar_plot(25000.0, 4.0, 0.05, -120.0);  // azimuth 4 rad wraps to 4 - 2 pi
  plot.time = 3.25;
  auto m = measurement_from_plot(plot, scan, kDefaults, 3);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->model.kind, MeasurementKind::kPolar);
  ASSERT_EQ(m->z.size(), 4);
  EXPECT_EQ(m->z[0], 25000.0);
  EXPECT_NEAR(m->z[1], 4.0 - 2.0 * kPi, 1e-12);
  EXPECT_EQ(m->z[2], 0.05);
  EXPECT_EQ(m->z[3], -120.0);
  EXPECT_EQ(m->model.sigma, (MeasVec(4) << 30.0, 0.003, 0.006, 2.0).finished());
  EXPECT_EQ(m->time, 3.25);  // the plot's own time wins over the scan's
  auto ra = measurement_from_plot(polar_plot(25000.0, 0.3), scan, kDefaults, 3);
  ASSERT_TRUE(ra);
  EXPECT_EQ(ra->z.size(), 2);
  EXPECT_FALSE(ra->model.has_range_rate);
  auto rar =
      measurement_from_plot(polar_plot(25000.0, 0.3, std::nullopt, 15.0), scan, kDefaults, 3);
  ASSERT_TRUE(rar);
  EXPECT_EQ(rar->z.size(), 3);
  EXPECT_TRUE(rar->model.has_range_rate);
  EXPECT_EQ(rar->model.position_components, 2);
}

TEST(PlotMeasurement, SigmaPrecedenceIsPlotThenScanThenProfile) {
  // GIVEN a scan sigma for range and azimuth and a plot sigma for range only
  PlotScan scan = scan_at(0.0);
  scan.sigma.range = 15.0;
  scan.sigma.azimuth = 0.002;
  Plot plot = polar_plot(10000.0, 0.1, 0.02);
  plot.sigma.range = 5.0;
  // WHEN converted; THEN range from the plot, azimuth from the scan, elevation default
  auto m = measurement_from_plot(plot, scan, kDefaults, 3);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->model.sigma[0], 5.0);
  EXPECT_EQ(m->model.sigma[1], 0.002);
  EXPECT_EQ(m->model.sigma[2], 0.006);
  // AND for Cartesian plots the same chain holds
  scan.sigma.x = 7.0;
  Plot cart = cartesian_plot(1, 2);
  cart.sigma.y = 3.0;
  auto c = measurement_from_plot(cart, scan, kDefaults, 2);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->model.sigma[0], 7.0);
  EXPECT_EQ(c->model.sigma[1], 3.0);
}

TEST(PlotMeasurement, ThreeDimensionalTrackerMeasuresSlantRangeWithoutElevation) {
  // GIVEN a platform at 8 km and a target at ground level; the plot has no elevation
  PlotScan scan = scan_at(0.0);
  scan.platform.position = {0.0, 0.0, 8000.0};
  const Eigen::Vector3d truth{6000.0, 0.0, 0.0};
  Plot plot = polar_plot(10000.0, kPi / 2);  // slant range 10 km, due east
  auto m = measurement_from_plot(plot, scan, kDefaults, 3);
  ASSERT_TRUE(m);
  // THEN h of the true 3-D state reproduces the plot (slant range, azimuth)
  StateVec x = StateVec::Zero(6);
  x[0] = truth.x();
  x[4] = truth.z();
  const MeasVec zhat = m->model.measure(make_layout(3), x);
  EXPECT_NEAR(zhat[0], 10000.0, 1e-9);
  EXPECT_NEAR(zhat[1], kPi / 2, 1e-12);
}

TEST(PlotMeasurement, TwoDimensionalTrackerProjectsA3dPolarPlot) {
  // GIVEN a level platform flying north-east and climbing, and a level target seen at
  // (r, az, el) whose true 3-D range-rate is in the plot
  PlotScan scan = scan_at(0.0);
  scan.platform.position = {500.0, -300.0, 7000.0};
  scan.platform.velocity = {100.0, 100.0, 10.0};
  scan.platform.attitude = {0.4, 0.0, 0.0};
  const double r = 20000.0, az = 0.8, el = -0.3;
  const Eigen::Vector3d p = polar_to_enu({r, az, el}, scan.platform);
  const Eigen::Vector3d v{-200.0, 50.0, 0.0};
  const double rdot = range_rate(p, v, scan.platform);
  auto m = measurement_from_plot(polar_plot(r, az, el, rdot), scan, kDefaults, 2);
  ASSERT_TRUE(m);
  // THEN it becomes the horizontal polar measurement (r cos el, az, rdot_h)
  ASSERT_EQ(m->z.size(), 3);
  EXPECT_NEAR(m->z[0], r * std::cos(el), 1e-9);
  EXPECT_NEAR(m->z[1], az, 1e-12);
  const double dz = r * std::sin(el);
  EXPECT_NEAR(m->z[2], (r * rdot + dz * 10.0) / (r * std::cos(el)), 1e-9);
  // AND sigmas: rho from range and elevation, rdot scaled by r / rho
  EXPECT_NEAR(m->model.sigma[0], std::hypot(30.0 * std::cos(el), dz * 0.006), 1e-9);
  EXPECT_EQ(m->model.sigma[1], 0.003);
  EXPECT_NEAR(m->model.sigma[2], 2.0 / std::cos(el), 1e-12);
  EXPECT_EQ(m->model.state_dims, 2);
  // AND h of the target's 2-D state reproduces all three components
  StateVec x(4);
  x << p.x(), v.x(), p.y(), v.y();
  const MeasVec zhat = m->model.measure(make_layout(2), x);
  EXPECT_NEAR(zhat[0], m->z[0], 1e-7);
  EXPECT_NEAR(zhat[1], m->z[1], 1e-12);
  EXPECT_NEAR(zhat[2], m->z[2], 1e-9);
}

TEST(PlotMeasurement, TwoDimensionalTrackerUsesTheAttitudeToPlaceThePlot) {
  // GIVEN a pitched, rolled platform and a 2-D tracker
  PlotScan scan = scan_at(0.0);
  scan.platform.position = {1000.0, 2000.0, 5000.0};
  scan.platform.attitude = {2.0, 0.15, -0.2};
  const Plot plot = polar_plot(30000.0, -1.0, -0.12);
  auto m = measurement_from_plot(plot, scan, kDefaults, 2);
  ASSERT_TRUE(m);
  // THEN its position is the horizontal projection of the plot's ENU position
  const Eigen::Vector3d enu = plot_position_enu(plot, scan.platform);
  const Eigen::Vector3d approx = approximate_position(*m);
  EXPECT_NEAR(approx.x(), enu.x(), 1e-7);
  EXPECT_NEAR(approx.y(), enu.y(), 1e-7);
  EXPECT_EQ(approx.z(), 0.0);
}

TEST(PlotMeasurement, ApproximatePositionInvertsEachForm) {
  PlotScan scan = scan_at(0.0);
  scan.platform.position = {-500.0, 800.0, 3000.0};
  scan.platform.attitude = {0.3, -0.05, 0.1};
  for (const Plot& plot : {polar_plot(15000.0, 2.9, 0.04), polar_plot(15000.0, -2.9),
                           cartesian_plot(4000, -1000, 900), cartesian_plot(4000, -1000)}) {
    auto m = measurement_from_plot(plot, scan, kDefaults, 3);
    ASSERT_TRUE(m);
    EXPECT_LT((approximate_position(*m) - plot_position_enu(plot, scan.platform)).norm(), 1e-7);
  }
}

TEST(PlotMeasurement, RejectsBadPlots) {
  const PlotScan scan = scan_at(0.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(measurement_from_plot(polar_plot(0.0, 0.1), scan, kDefaults, 3));
  EXPECT_FALSE(measurement_from_plot(polar_plot(-5.0, 0.1), scan, kDefaults, 3));
  EXPECT_FALSE(measurement_from_plot(polar_plot(5000.0, nan), scan, kDefaults, 3));
  EXPECT_FALSE(measurement_from_plot(polar_plot(5000.0, 0.1, 2.0), scan, kDefaults, 3));
  EXPECT_FALSE(measurement_from_plot(cartesian_plot(nan, 1.0), scan, kDefaults, 2));
  EXPECT_FALSE(measurement_from_plot(cartesian_plot(1.0, 1.0), scan, kDefaults, 4));
  Plot bad_sigma = polar_plot(5000.0, 0.1);
  bad_sigma.sigma.azimuth = 0.0;
  const auto result = measurement_from_plot(bad_sigma, scan, kDefaults, 3);
  ASSERT_FALSE(result);
  EXPECT_NE(result.error().message.find("azimuth"), std::string::npos);
  // A plot straight below the platform has no horizontal position for a 2-D tracker.
  EXPECT_FALSE(measurement_from_plot(polar_plot(5000.0, 0.0, -kPi / 2), scan, kDefaults, 2));
}

}  // namespace
}  // namespace skytrack
