// Tests of the clutter map (local false-plot density in measurement space): a dense clutter
// area against the sky around it, the block's own elevation spread, plots it must not count,
// the azimuth wrap, and Cartesian plots.
#include "skytrack/clutter/clutter_map.hpp"

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace skytrack::clutter {
namespace {

constexpr double kPi = std::numbers::pi;

MeasVec vec(std::initializer_list<double> values) {
  MeasVec v = MeasVec::Zero(static_cast<Eigen::Index>(values.size()));
  Eigen::Index i = 0;
  for (const double x : values) v[i++] = x;
  return v;
}

PlotMeasurement polar(double range, double azimuth, double elevation) {
  PlotMeasurement p;
  p.model = MeasurementModel::polar(PlatformState{}, true, false, 3, vec({30.0, 0.004, 0.008}));
  p.z = vec({range, azimuth, elevation});
  return p;
}

PlotMeasurement cartesian(double x, double y) {
  PlotMeasurement p;
  p.model = MeasurementModel::cartesian(2, 2, vec({50.0, 50.0}));
  p.z = vec({x, y});
  return p;
}

struct Batch {
  std::vector<PlotMeasurement> plots;
  std::vector<std::uint8_t> counted;
  void add(PlotMeasurement p, bool counts = true) {
    plots.push_back(std::move(p));
    counted.push_back(counts ? 1 : 0);
  }
  std::vector<double> densities(const ClutterMapCells& cells = {}) const {
    std::vector<double> d(plots.size(), 0.0);
    raise_to_local_density(plots, counted, cells, d);
    return d;
  }
};

// Background: uniform over range [10, 150] km, every azimuth, elevation [-0.12, -0.02];
// a clutter area: range [70, 90] km, azimuth [-0.1, 0.1], elevation [-0.11, -0.07].
constexpr int kBackground = 4000, kArea = 400;
constexpr double kBackgroundDensity = kBackground / (140e3 * 2.0 * kPi * 0.10);
constexpr double kAreaDensity = kArea / (20e3 * 0.2 * 0.04);

Batch background_and_area(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> r(10e3, 150e3), az(-kPi, kPi), el(-0.12, -0.02);
  std::uniform_real_distribution<double> ra(70e3, 90e3), aza(-0.1, 0.1), ela(-0.11, -0.07);
  Batch b;
  for (int i = 0; i < kBackground; ++i) {
    // Each draw is its own step, last argument first: the order GCC used when the scenes were
    // measured (C++ leaves the evaluation order of arguments unspecified).
    const double elevation = el(rng), azimuth = az(rng), range = r(rng);
    b.add(polar(range, azimuth, elevation));
  }
  for (int i = 0; i < kArea; ++i) {
    const double elevation = ela(rng), azimuth = aza(rng), range = ra(rng);
    b.add(polar(range, azimuth, elevation));
  }
  return b;
}

TEST(ClutterMap, AreaPlotsGetTheAreasDensityAndTheSkyAroundItsOwn) {
  const Batch b = background_and_area(7);
  const std::vector<double> d = b.densities();
  double area = 0.0, sky = 0.0;
  int n_area = 0, n_sky = 0;
  for (std::size_t j = 0; j < b.plots.size(); ++j) {
    const PlotMeasurement& p = b.plots[j];
    // Well inside the area (a block spans 15 km x 0.15 rad), or well away from it.
    if (j >= kBackground && std::abs(p.z[0] - 80e3) < 2e3 && std::abs(p.z[1]) < 0.02) {
      area += d[j];
      ++n_area;
    } else if (j < kBackground && p.z[0] > 30e3 && p.z[0] < 130e3 && std::abs(p.z[1]) > 1.0) {
      sky += d[j];
      ++n_sky;
    }
  }
  ASSERT_GT(n_area, 5);
  ASSERT_GT(n_sky, 1000);
  // The area's density from its own spread in elevation (0.04 rad, not the batch's 0.1)
  // within 25 %, the sky's within 25 % on average (Poisson counts of about 9 per block).
  EXPECT_NEAR(area / n_area, kAreaDensity, 0.25 * kAreaDensity);
  EXPECT_NEAR(sky / n_sky, kBackgroundDensity, 0.25 * kBackgroundDensity);
  EXPECT_GT(area / n_area, 20.0 * kBackgroundDensity);
}

TEST(ClutterMap, NeverLowersADensityAndALonePlotKeepsIts) {
  Batch b;
  b.add(polar(80e3, 0.0, -0.05));
  b.add(polar(120e3, 2.0, -0.05));  // blocks apart
  std::vector<double> d = {3.0, 5.0};
  raise_to_local_density(b.plots, b.counted, {}, d);
  EXPECT_EQ(d[0], 3.0);
  EXPECT_EQ(d[1], 5.0);
}

TEST(ClutterMap, PlotsNotCountedDoNotAddToTheirNeighboursDensity) {
  Batch counted, uncounted;
  for (int i = 0; i < 10; ++i) {
    counted.add(polar(80e3 + 100.0 * i, 0.001 * i, -0.05));
    uncounted.add(polar(80e3 + 100.0 * i, 0.001 * i, -0.05), i == 0);
  }
  const std::vector<double> with = counted.densities();
  const std::vector<double> without = uncounted.densities();
  EXPECT_GT(with[0], 0.0);
  // Plot 0 is the only counted one: nothing else counts for it, and the others see one plot.
  EXPECT_EQ(without[0], 0.0);
  EXPECT_GT(without[1], 0.0);
  EXPECT_LT(without[1], with[1]);
}

TEST(ClutterMap, AzimuthWrapsRoundNorthAndSouth) {
  // Plots either side of azimuth +-pi are neighbours; the same plots round azimuth 0 give the
  // same densities.
  Batch wrap, middle;
  for (int i = 0; i < 6; ++i) {
    const double offset = 0.01 * (i + 1);
    const double az = i % 2 == 0 ? kPi - offset : -kPi + offset;
    wrap.add(polar(80e3 + 500.0 * i, az, -0.05 - 0.001 * i));
    middle.add(polar(80e3 + 500.0 * i, i % 2 == 0 ? -offset : offset, -0.05 - 0.001 * i));
  }
  const std::vector<double> a = wrap.densities(), b = middle.densities();
  for (std::size_t j = 0; j < a.size(); ++j) {
    EXPECT_GT(a[j], 0.0);
    EXPECT_NEAR(a[j], b[j], 1e-9 * b[j]) << "plot " << j;
  }
}

TEST(ClutterMap, PlotsSharingOneFlightLevelSpreadAtLeastTheirOwnHeightNoise) {
  // GIVEN three aircraft on the ground 2 km from an airport radar whose replies all report
  // the same flight level (whole steps), none yet explained by a track
  Batch b;
  for (int i = 0; i < 3; ++i) {
    PlotMeasurement p;
    p.model = MeasurementModel::polar_height(PlatformState{}, false, vec({15.0, 0.0012, 30.0}));
    p.z = vec({2000.0 + 10.0 * i, 0.3 + 0.03 * i, 7.62});
    b.add(p);
  }
  // WHEN their clutter density is mapped (too few for a spread of their own)
  const std::vector<double> d = b.densities();
  // THEN the height width is the plots' own noise width (sqrt 12 x 30 m), not the nil extent
  // of identical values: the two other plots over the 3 x 3 block of 5 km x 0.05 rad cells
  // (clipped at zero range) times 104 m
  const double area = (2.0 * 5000.0) * 3.0 * (2.0 * kPi / 126.0);
  EXPECT_NEAR(d[0], 2.0 / (area * std::sqrt(12.0) * 30.0), 1e-9 * d[0]);
}

TEST(ClutterMap, PositionsAndCellsFarBeyondAnyRadarDoNotOverflowTheCells) {
  // GIVEN finite but absurd plots (1e23 m: a corrupted range or x) beside ordinary ones, and
  // cells far finer than any radar's
  Batch b;
  b.add(polar(4.6e23, 0.1, 0.0));
  b.add(polar(-1e300, -0.1, 0.0));
  b.add(cartesian(1e30, -1e30));
  for (int i = 0; i < 20; ++i) b.add(polar(50e3 + 100.0 * i, 0.01 * i, 0.0));
  // WHEN the map counts them (under UBSan a float-to-integer overflow would abort)
  const std::vector<double> d = b.densities({.range = 1e-20, .azimuth = 1e-20, .cartesian = 1e-20});
  const std::vector<double> ordinary = b.densities();
  // THEN every density is finite and not negative
  for (const double v : d) EXPECT_TRUE(std::isfinite(v) && v >= 0.0);
  for (const double v : ordinary) EXPECT_TRUE(std::isfinite(v) && v >= 0.0);
}

TEST(ClutterMap, CartesianPlotsAreCountedOverTheirBlockArea) {
  // 90 plots spread over one 3 x 3 block of 1 km cells, plus one plot far away.
  Batch b;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 3000.0);
  for (int i = 0; i < 90; ++i) {
    const double y = u(rng), x = u(rng);
    b.add(cartesian(x, y));
  }
  b.add(cartesian(50e3, 50e3));
  const std::vector<double> d =
      b.densities({.range = 5000.0, .azimuth = 0.05, .cartesian = 1000.0});
  // The plot in the middle cell sees the other 89 plots over (3 km)^2.
  for (std::size_t j = 0; j < 90; ++j) {
    const PlotMeasurement& p = b.plots[j];
    if (p.z[0] >= 1000.0 && p.z[0] < 2000.0 && p.z[1] >= 1000.0 && p.z[1] < 2000.0) {
      EXPECT_NEAR(d[j], 89.0 / 9e6, 1e-15);
    }
  }
  EXPECT_EQ(d[90], 0.0);
}

}  // namespace
}  // namespace skytrack::clutter
