#include "skytrack/measurement/measurement_model.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "skytrack/geometry/frames.hpp"

namespace skytrack {
namespace {

constexpr double kPi = std::numbers::pi;

StateLayout make_layout(int dims, bool acceleration = false, bool turn_rate = false) {
  StateLayout layout;
  layout.dims = dims;
  layout.acceleration = acceleration;
  layout.turn_rate = turn_rate;
  return layout;
}

/// A target state at position p with velocity v (extra states filled with junk).
StateVec target(const StateLayout& layout, const Eigen::Vector3d& p, const Eigen::Vector3d& v) {
  StateVec x = StateVec::Constant(layout.size(), 0.37);
  for (int axis = 0; axis < layout.dims; ++axis) {
    x[StateLayout::position(axis)] = p[axis];
    x[StateLayout::velocity(axis)] = v[axis];
  }
  return x;
}

MeasVec sigmas(int n) {
  return MeasVec::LinSpaced(n, 1.0, 2.0);
}

PlatformState moving_platform() {
  PlatformState platform;
  platform.position = {-2000.0, 1500.0, 6000.0};
  platform.velocity = {150.0, 200.0, -5.0};
  platform.attitude = {0.7, 0.1, -0.15};  // heading, pitch, roll
  return platform;
}

MeasJacobian numerical_jacobian(const MeasurementModel& model, const StateLayout& layout,
                                const StateVec& x) {
  MeasJacobian J(model.size(), layout.size());
  for (int k = 0; k < layout.size(); ++k) {
    const double h = 1e-4 * std::max(1.0, std::abs(x[k]));
    StateVec plus = x, minus = x;
    plus[k] += h;
    minus[k] -= h;
    J.col(k) =
        model.residual(model.measure(layout, plus), model.measure(layout, minus)) / (2.0 * h);
  }
  return J;
}

struct JacobianCase {
  std::string name;
  MeasurementModel model;
  StateLayout layout;
};

TEST(MeasurementModel, AnalyticJacobiansEqualNumericalOnesForEveryKind) {
  const PlatformState level;
  const PlatformState moving = moving_platform();
  const StateLayout l2 = make_layout(2), l3 = make_layout(3), full3 = make_layout(3, true, true);
  const std::vector<JacobianCase> cases = {
      {"cartesian 2 on 2-D", MeasurementModel::cartesian(2, 2, sigmas(2)), l2},
      {"cartesian 3 on 3-D", MeasurementModel::cartesian(3, 3, sigmas(3)), l3},
      {"cartesian 2 on 3-D", MeasurementModel::cartesian(2, 3, sigmas(2)), full3},
      {"polar 2 on 2-D", MeasurementModel::polar(level, false, false, 2, sigmas(2)), l2},
      {"polar 2 + rdot on 2-D moving", MeasurementModel::polar(moving, false, true, 2, sigmas(3)),
       l2},
      {"polar 2 (slant) on 3-D", MeasurementModel::polar(level, false, false, 3, sigmas(2)), l3},
      {"polar 3 on 3-D", MeasurementModel::polar(level, true, false, 3, sigmas(3)), l3},
      {"polar 3 + rdot on 3-D", MeasurementModel::polar(level, true, true, 3, sigmas(4)), l3},
      {"polar 3 + rdot, moving platform with attitude",
       MeasurementModel::polar(moving, true, true, 3, sigmas(4)), l3},
      {"polar 2 + rdot, attitude, full layout",
       MeasurementModel::polar(moving, false, true, 3, sigmas(3)), full3},
      {"polar height on 3-D", MeasurementModel::polar_height(level, false, sigmas(3)), l3},
      {"polar height + rdot, moving platform, full layout",
       MeasurementModel::polar_height(moving, true, sigmas(4)), full3},
  };
  const Eigen::Vector3d positions[] = {
      {12000.0, 30000.0, 2000.0}, {-25000.0, -4000.0, 9000.0}, {300.0, -800.0, 5800.0}};
  const Eigen::Vector3d velocity{-220.0, 35.0, 12.0};
  for (const JacobianCase& c : cases) {
    for (const Eigen::Vector3d& p : positions) {
      // GIVEN a model and a target; WHEN H is built analytically
      const StateVec x = target(c.layout, p, velocity);
      const MeasJacobian analytic = c.model.jacobian(c.layout, x);
      const MeasJacobian numeric = numerical_jacobian(c.model, c.layout, x);
      // THEN it matches central differences (relative to the row scale)
      ASSERT_EQ(analytic.rows(), c.model.size()) << c.name;
      ASSERT_EQ(analytic.cols(), c.layout.size()) << c.name;
      for (int r = 0; r < analytic.rows(); ++r) {
        const double scale = std::max(1e-12, numeric.row(r).cwiseAbs().maxCoeff());
        EXPECT_LT((analytic.row(r) - numeric.row(r)).cwiseAbs().maxCoeff() / scale, 1e-6)
            << c.name << " row " << r << "\n"
            << analytic << "\n\n"
            << numeric;
      }
    }
  }
}

TEST(MeasurementModel, PolarMeasuresAzimuthClockwiseFromNorth) {
  // GIVEN a level platform at the origin and a target 3000 m east, 4000 m north, 1000 m up
  const MeasurementModel model = MeasurementModel::polar({}, true, false, 3, sigmas(3));
  const StateLayout layout = make_layout(3);
  const MeasVec z = model.measure(layout, target(layout, {3000, 4000, 1000}, {0, 0, 0}));
  // THEN r = sqrt(26e6), az = atan2(3000, 4000) (east of north), el = atan2(1000, 5000)
  EXPECT_NEAR(z[0], std::sqrt(26e6), 1e-9);
  EXPECT_NEAR(z[1], std::atan2(3000.0, 4000.0), 1e-12);
  EXPECT_NEAR(z[2], std::atan2(1000.0, 5000.0), 1e-12);
}

TEST(MeasurementModel, PolarAgreesWithTheFrameConversion) {
  // GIVEN a moving, rotated platform; THEN h(x) = enu_to_polar(p) and h inverts polar_to_enu
  const PlatformState platform = moving_platform();
  const MeasurementModel model = MeasurementModel::polar(platform, true, false, 3, sigmas(3));
  const StateLayout layout = make_layout(3);
  const Eigen::Vector3d p = polar_to_enu({40000.0, -2.5, -0.1}, platform);
  const MeasVec z = model.measure(layout, target(layout, p, {0, 0, 0}));
  EXPECT_NEAR(z[0], 40000.0, 1e-7);
  EXPECT_NEAR(z[1], -2.5, 1e-12);
  EXPECT_NEAR(z[2], -0.1, 1e-12);
}

TEST(MeasurementModel, AzimuthResidualWrapsAcrossPi) {
  // GIVEN z = 3.13 and zhat = -3.13 (both near south, 0.0232 rad apart across +-pi)
  const MeasurementModel model = MeasurementModel::polar({}, false, false, 2, sigmas(2));
  MeasVec z(2), zhat(2);
  z << 1000.0, 3.13;
  zhat << 990.0, -3.13;
  // WHEN the residual is taken; THEN it is the short way round, -0.0232, and range is plain
  const MeasVec nu = model.residual(z, zhat);
  EXPECT_NEAR(nu[1], 6.26 - 2.0 * kPi, 1e-12);
  EXPECT_NEAR(nu[1], -0.0232, 1e-4);
  EXPECT_DOUBLE_EQ(nu[0], 10.0);
  // AND the other way round it is +0.0232
  EXPECT_NEAR(model.residual(zhat, z)[1], 2.0 * kPi - 6.26, 1e-12);
}

TEST(MeasurementModel, RangeRateUsesTheRelativeVelocity) {
  PlatformState platform;
  platform.velocity = {0.0, 250.0, 0.0};  // flying north at 250 m/s
  const MeasurementModel model = MeasurementModel::polar(platform, true, true, 3, sigmas(4));
  const StateLayout layout = make_layout(3);
  // GIVEN a target due north flying with the platform: THEN the range does not change
  EXPECT_NEAR(model.measure(layout, target(layout, {0, 10000, 0}, {0, 250, 0}))[3], 0.0, 1e-12);
  // GIVEN a stationary target due north: THEN the range closes at 250 m/s
  EXPECT_NEAR(model.measure(layout, target(layout, {0, 10000, 0}, {0, 0, 0}))[3], -250.0, 1e-12);
  // GIVEN a target due east flying east at 100 m/s: THEN only its own motion opens the range
  EXPECT_NEAR(model.measure(layout, target(layout, {10000, 0, 0}, {100, 250, 0}))[3], 100.0, 1e-12);
}

TEST(MeasurementModel, NoiseIsDiagonalOfSquaredSigmas) {
  MeasVec s(3);
  s << 30.0, 0.003, 2.0;
  const MeasMat R = MeasurementModel::polar({}, false, true, 3, s).noise();
  EXPECT_DOUBLE_EQ(R(0, 0), 900.0);
  EXPECT_DOUBLE_EQ(R(1, 1), 9e-6);
  EXPECT_DOUBLE_EQ(R(2, 2), 4.0);
  EXPECT_EQ(R(0, 1), 0.0);
}

TEST(MeasurementModel, TwoDimensionalPolarIsHorizontalAndLevelled) {
  // GIVEN a pitched and rolled platform at 6 km heading east, and a 2-D tracker
  PlatformState platform;
  platform.position = {100.0, 200.0, 6000.0};
  platform.attitude = {kPi / 2, 0.2, 0.3};
  const MeasurementModel model = MeasurementModel::polar(platform, false, false, 2, sigmas(2));
  const StateLayout layout = make_layout(2);
  // WHEN a target 4000 m north of the platform is measured
  const MeasVec z = model.measure(layout, target(layout, {100, 4200, 0}, {0, 0, 0}));
  // THEN range is horizontal and azimuth is from the heading only (north = -90 deg)
  EXPECT_NEAR(z[0], 4000.0, 1e-9);
  EXPECT_NEAR(z[1], -kPi / 2, 1e-12);
}

}  // namespace
}  // namespace skytrack
