// Block resampling: each block follows its own factor of the plot's likelihood.
#include "skytrack/bernoulli/block_resampling.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

namespace skytrack::bernoulli {
namespace {

constexpr double kKappa = 20.0 / (std::numbers::pi * 25000.0);

/// A product cloud in the plot's frame: every along offset (with its velocity) with every
/// across offset (with its velocity), so the blocks are independent in the sample itself.
std::vector<Particle> product_cloud(const ScanPlot& plot, const std::vector<double>& along,
                                    const std::vector<double>& across) {
  std::vector<Particle> cloud;
  for (const double a : along) {
    for (const double c : across) {
      const Eigen::Vector2d p = plot.position + a * plot.along + c * plot.across;
      const Eigen::Vector2d v = (-350.0 + 0.5 * a) * plot.along + (190.0 - 0.1 * c) * plot.across;
      cloud.push_back({p.x(), v.x(), p.y(), v.y()});
    }
  }
  return cloud;
}

double along_of(const ScanPlot& plot, const Particle& p) {
  return (Eigen::Vector2d(p.x, p.y) - plot.position).dot(plot.along);
}

double across_of(const ScanPlot& plot, const Particle& p) {
  return (Eigen::Vector2d(p.x, p.y) - plot.position).dot(plot.across);
}

TEST(BlockResampling, OnAProductCloudTheEstimateIsTheJointWeightedMean) {
  // GIVEN a polar plot at 21 km (sigma 5 m in range, 63 m across) and a product cloud
  ScanPlot plot;
  ASSERT_TRUE(make_polar_plot({0, 0}, 21000.0, 0.5, 5.0, 3e-3, kKappa, 50.0, plot));
  const std::vector<Particle> cloud =
      product_cloud(plot, {-14.0, -6.0, -1.0, 3.0, 9.0, 20.0}, {-90.0, -40.0, 0.0, 25.0, 70.0});
  // WHEN it is block-resampled
  std::vector<double> scratch(2 * cloud.size());
  std::vector<Particle> out(cloud.size());
  Eigen::Vector4d estimate;
  ASSERT_TRUE(block_resample(cloud, plot, 0.3, 0.6, scratch, out, estimate));
  // THEN the estimate is the mean under the factorised (linearised) likelihood, which on a
  // product cloud is the joint weighted mean
  Eigen::Vector4d joint = Eigen::Vector4d::Zero();
  double total = 0.0;
  for (const Particle& p : cloud) {
    const double ea = along_of(plot, p) / 5.0, ec = across_of(plot, p) / (21000.0 * 3e-3);
    const double w = std::exp(-0.5 * (ea * ea + ec * ec));
    joint += w * Eigen::Vector4d(p.x, p.vx, p.y, p.vy);
    total += w;
  }
  joint /= total;
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(estimate[i], joint[i], 1e-8 * (1.0 + std::abs(joint[i])));
}

TEST(BlockResampling, EachBlockIsDrawnFromItsOwnFactor) {
  // GIVEN a Cartesian plot (blocks x and y) with sigma 10 m in x, 1000 m in y, and a cloud
  // whose x offsets are -40, 0, 40 m: only the middle one has weight in x
  ScanPlot plot;
  ASSERT_TRUE(make_cartesian_plot({5000.0, 8000.0}, 10.0, 1000.0, 1e-6, 50.0, plot));
  const std::vector<Particle> cloud = product_cloud(plot, {-40.0, 0.0, 40.0}, {-30.0, 0.0, 30.0});
  std::vector<double> scratch(2 * cloud.size());
  std::vector<Particle> out(9);
  Eigen::Vector4d estimate;
  // WHEN resampled into 9
  ASSERT_TRUE(block_resample(cloud, plot, 0.5, 0.5, scratch, out, estimate));
  // THEN every x is the middle one (the x factor picks it) while the y values, nearly flat
  // under their factor, keep all three offsets three times each (each particle once), each
  // velocity with its own block's position
  std::vector<double> ys;
  for (const Particle& p : out) {
    EXPECT_NEAR(p.x, 5000.0, 1e-9);
    EXPECT_NEAR(p.vx, -350.0, 1e-9);
    const double c = p.y - 8000.0;
    EXPECT_NEAR(p.vy, 190.0 - 0.1 * c, 1e-9);
    ys.push_back(std::round(c));
  }
  std::sort(ys.begin(), ys.end());
  EXPECT_EQ(ys, (std::vector<double>{-30, -30, -30, 0, 0, 0, 30, 30, 30}));
}

TEST(BlockResampling, NothingDoneWhenAFactorVanishes) {
  // GIVEN a cloud 10 km from the plot: the range factor underflows on every particle
  ScanPlot plot;
  ASSERT_TRUE(make_polar_plot({0, 0}, 21000.0, 0.5, 5.0, 3e-3, kKappa, 50.0, plot));
  std::vector<Particle> cloud(4, Particle{0.0, 0.0, 1000.0, 0.0});
  std::vector<double> scratch(8);
  std::vector<Particle> out(4, Particle{1.0, 2.0, 3.0, 4.0});
  Eigen::Vector4d estimate = Eigen::Vector4d::Constant(7.0);
  // WHEN block-resampled THEN it refuses and leaves the output alone
  EXPECT_FALSE(block_resample(cloud, plot, 0.5, 0.5, scratch, out, estimate));
  EXPECT_EQ(out[0].x, 1.0);
  EXPECT_EQ(estimate[0], 7.0);
}

TEST(BlockResampling, DependenceIsTheMutualInformationBetweenTheBlocks) {
  // GIVEN a polar plot at azimuth 0.5 rad and covariances built in its frame [a, va, c, vc]
  ScanPlot plot;
  ASSERT_TRUE(make_polar_plot({0, 0}, 21000.0, 0.5, 5.0, 3e-3, kKappa, 50.0, plot));
  Eigen::Matrix4d r = Eigen::Matrix4d::Zero();  // frame -> [x, vx, y, vy]
  r(0, 0) = r(1, 1) = plot.along.x();
  r(2, 0) = r(3, 1) = plot.along.y();
  r(0, 2) = r(1, 3) = plot.across.x();
  r(2, 2) = r(3, 3) = plot.across.y();
  Eigen::Matrix4d frame;  // each block correlated within itself, none across
  frame << 100.0, 40.0, 0.0, 0.0, 40.0, 64.0, 0.0, 0.0, 0.0, 0.0, 1600.0, 300.0, 0.0, 0.0, 300.0,
      100.0;
  // THEN blocks independent in the plot's frame: 0
  EXPECT_NEAR(block_dependence(plot, r * frame * r.transpose()), 0.0, 1e-9);
  // and a correlation rho = 0.6 between a and c: -1/2 log(1 - rho^2) (the within-block
  // correlations are zero here so that it is the only canonical correlation)
  frame.setZero();
  frame.diagonal() << 100.0, 64.0, 1600.0, 100.0;
  frame(0, 2) = frame(2, 0) = 0.6 * 10.0 * 40.0;
  EXPECT_NEAR(block_dependence(plot, r * frame * r.transpose()), -0.5 * std::log(1.0 - 0.36), 1e-9);
  // and a singular covariance: infinite
  EXPECT_TRUE(std::isinf(block_dependence(plot, Eigen::Matrix4d::Zero())));
}

}  // namespace
}  // namespace skytrack::bernoulli
