// Likelihood ratios, gating, dynamics, resampling and moments of the particle kernel.
#include "skytrack/bernoulli/particle_kernel.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "skytrack/motion/coordinated_turn.hpp"

namespace skytrack::bernoulli {
namespace {

constexpr double kKappa = 20.0 / (std::numbers::pi * 25000.0);  // the paper's 2.5465e-4

TEST(BernoulliParticleKernel, LikelihoodRatioAtThePlotIsThePeakDensityOverClutter) {
  ScanPlot plot;
  ASSERT_TRUE(make_polar_plot({0, 0}, 20000.0, 0.5, 5.0, 3e-3, kKappa, 50.0, plot));
  // g peak 1 / (2 pi 5 m 3 mrad) = 10.61 per m rad, over kappa 2.5465e-4: 41667
  const double expected = 1.0 / (2.0 * std::numbers::pi * 5.0 * 3e-3 * kKappa);
  EXPECT_NEAR(expected, 41666.7, 0.1);
  EXPECT_NEAR(plot_likelihood_ratio(plot, plot.position.x(), plot.position.y(), 50.0), expected,
              1e-9 * expected);
}

TEST(BernoulliParticleKernel, DistanceMatchesExactRangeAndAzimuthFromAMovingPlatform) {
  // GIVEN a platform away from the origin and a plot at azimuth 2.8 rad (south-east)
  const Eigen::Vector2d origin(-3000.0, 1500.0);
  const double range = 18000.0, azimuth = 2.8, sr = 5.0, sa = 3e-3;
  ScanPlot plot;
  ASSERT_TRUE(make_polar_plot(origin, range, azimuth, sr, sa, kKappa, 50.0, plot));
  // WHEN particles lie a few sigma off in range and azimuth THEN the distance is the exact one
  for (const double dr : {-20.0, 0.0, 13.0}) {
    for (const double da : {-0.2, -0.015, -0.004, 0.0, 0.009, 0.06}) {
      const double r = range + dr, a = azimuth + da;
      const double x = origin.x() + r * std::sin(a), y = origin.y() + r * std::cos(a);
      const double exact_r = std::hypot(x - origin.x(), y - origin.y());
      const double exact_a = std::atan2(x - origin.x(), y - origin.y());
      const double expected =
          std::pow((exact_r - range) / sr, 2) + std::pow((exact_a - azimuth) / sa, 2);
      EXPECT_NEAR(plot_distance_squared(plot, x, y), expected, 1e-6 * (1.0 + expected));
    }
  }
  // A particle behind the sensor is never in the gate.
  EXPECT_EQ(plot_likelihood_ratio(plot, origin.x() - 100 * std::sin(azimuth),
                                  origin.y() - 100 * std::cos(azimuth), 50.0),
            0.0);
}

TEST(BernoulliParticleKernel, CartesianPlotRatio) {
  ScanPlot plot;
  ASSERT_TRUE(make_cartesian_plot({100.0, 200.0}, 10.0, 20.0, 1e-8, 50.0, plot));
  // d^2 = (10/10)^2 + (20/20)^2 = 2 -> peak e^-1, peak 1 / (2 pi 200 1e-8)
  const double peak = 1.0 / (2.0 * std::numbers::pi * 200.0 * 1e-8);
  EXPECT_NEAR(plot_likelihood_ratio(plot, 110.0, 220.0, 50.0), peak * std::exp(-1.0), 1e-6 * peak);
  EXPECT_FALSE(make_cartesian_plot({NAN, 0.0}, 10.0, 10.0, 1e-8, 50.0, plot));
  EXPECT_FALSE(make_polar_plot({0, 0}, 100.0, 0.1, 0.0, 1e-3, kKappa, 50.0, plot));
}

TEST(BernoulliParticleKernel, GatedAccumulationEqualsTheSumOverEveryPlot) {
  NormalSampler rng(5);
  std::vector<ScanPlot> plots;
  for (int i = 0; i < 30; ++i) {
    ScanPlot plot;
    const double r = i < 3 ? 15000.0 + 10.0 * i : 25000.0 * rng.uniform();
    const double a = i < 3 ? 1.0 + 0.002 * i : std::numbers::pi * rng.uniform();
    ASSERT_TRUE(make_polar_plot({0, 0}, r, a, 5.0, 3e-3, kKappa, 50.0, plot));
    plots.push_back(plot);
  }
  std::vector<Particle> cloud(500);
  for (Particle& p : cloud) {
    p.x = 15000.0 * std::sin(1.0) + 40.0 * rng.normal();
    p.y = 15000.0 * std::cos(1.0) + 40.0 * rng.normal();
  }
  std::vector<double> gated(cloud.size(), 0.0);
  const DominantPlot dominant = accumulate_likelihood_ratios(cloud, plots, 50.0, gated);
  double total = 0.0;
  std::vector<double> per_plot(plots.size(), 0.0);
  for (std::size_t n = 0; n < cloud.size(); ++n) {
    double brute = 0.0;
    for (std::size_t z = 0; z < plots.size(); ++z) {
      const double ratio = plot_likelihood_ratio(plots[z], cloud[n].x, cloud[n].y, 50.0);
      brute += ratio;
      per_plot[z] += ratio;
    }
    EXPECT_NEAR(gated[n], brute, 1e-9 * (1.0 + brute));
    total += brute;
  }
  EXPECT_GT(total, 0.0);  // the test saw particles in a gate
  // and the plot that contributes most, with its share of the block's sum
  const auto largest = static_cast<std::size_t>(std::max_element(per_plot.begin(), per_plot.end()) -
                                                per_plot.begin());
  EXPECT_EQ(dominant.index, largest);
  EXPECT_NEAR(dominant.sum, per_plot[largest], 1e-9 * per_plot[largest]);
  EXPECT_NEAR(dominant.total, total, 1e-9 * total);
}

TEST(BernoulliParticleKernel, NoiseFreeDynamicsMatchTheCoordinatedTurnModel) {
  const StateLayout layout{};
  for (const double w : {0.0, -0.1, 0.07}) {
    const ModelDynamics m = make_dynamics({w, 0.0, 1}, 2.0);
    const StateMat F = CoordinatedTurn{w, 1.0, 1.0}.transition(layout, 2.0);
    Particle p{100.0, -8.3, 200.0, -399.9};
    NormalSampler rng(1);
    propagate(m, p, rng);  // accel_sigma 0: the draws have no effect
    StateVec x(4);
    x << 100.0, -8.3, 200.0, -399.9;
    const StateVec expected = F * x;
    EXPECT_NEAR(p.x, expected[0], 1e-9);
    EXPECT_NEAR(p.vx, expected[1], 1e-9);
    EXPECT_NEAR(p.y, expected[2], 1e-9);
    EXPECT_NEAR(p.vy, expected[3], 1e-9);
  }
}

TEST(BernoulliParticleKernel, ProcessNoiseIsDiscreteWhiteAcceleration) {
  // Var(x) = (T^2/2 sigma)^2, Var(vx) = (T sigma)^2, Cov = T^3/2 sigma^2 with T 1, sigma 5
  const ModelDynamics m = make_dynamics({0.0, 5.0, 1}, 1.0);
  NormalSampler rng(9);
  double sxx = 0, svv = 0, sxv = 0;
  constexpr int kDraws = 200000;
  for (int i = 0; i < kDraws; ++i) {
    Particle p;
    propagate(m, p, rng);
    sxx += p.x * p.x;
    svv += p.vx * p.vx;
    sxv += p.x * p.vx;
  }
  EXPECT_NEAR(sxx / kDraws, 6.25, 0.1);
  EXPECT_NEAR(svv / kDraws, 25.0, 0.4);
  EXPECT_NEAR(sxv / kDraws, 12.5, 0.2);
}

TEST(BernoulliParticleKernel, SystematicResamplingCopiesByWeight) {
  const std::vector<Particle> in{{1, 0, 0, 0}, {2, 0, 0, 0}, {3, 0, 0, 0}};
  std::vector<Particle> out(4);
  systematic_resample(in, std::vector<double>{0.0, 1.0, 0.0}, 0.3, out);
  for (const Particle& p : out) EXPECT_EQ(p.x, 2.0);
  systematic_resample(in, std::vector<double>{0.5, 0.0, 0.5}, 0.7, out);
  EXPECT_EQ(out[0].x, 1.0);
  EXPECT_EQ(out[1].x, 1.0);
  EXPECT_EQ(out[2].x, 3.0);
  EXPECT_EQ(out[3].x, 3.0);
}

TEST(BernoulliParticleKernel, WeightedMomentsByHand) {
  // x in {10000, 10004} with weights 0.25, 0.75: mean 10003, variance 3
  const std::vector<Particle> in{{10000, 1, 0, 0}, {10004, 1, 2, 0}};
  Eigen::Vector4d mean;
  Eigen::Matrix4d cov;
  weighted_moments(in, std::vector<double>{0.25, 0.75}, mean, cov);
  EXPECT_NEAR(mean[0], 10003.0, 1e-9);
  EXPECT_NEAR(mean[1], 1.0, 1e-12);
  EXPECT_NEAR(mean[2], 1.5, 1e-12);
  EXPECT_NEAR(cov(0, 0), 3.0, 1e-9);
  EXPECT_NEAR(cov(0, 2), 1.5, 1e-9);  // 0.25 (-3)(-1.5) + 0.75 (1)(0.5)
  EXPECT_NEAR(cov(2, 0), 1.5, 1e-9);
  EXPECT_NEAR(cov(1, 1), 0.0, 1e-12);
}

TEST(BernoulliParticleKernel, RegularisationSpreadsCopiesAndKeepsTheMoments) {
  // GIVEN 2000 parents of a posterior with a position-velocity correlation, each copied 10
  // times as resampling copies the few newborns near a target
  NormalSampler rng(7);
  std::vector<Particle> cloud;
  for (int k = 0; k < 2000; ++k) {
    const double px = 40.0 * rng.normal(), py = 5.0 * rng.normal();
    const Particle parent{20000.0 + px, -8.0 + 0.8 * px + 30.0 * rng.normal(), 10000.0 + py,
                          -400.0 + 2.0 * py + 10.0 * rng.normal()};
    for (int c = 0; c < 10; ++c) cloud.push_back(parent);
  }
  const std::vector<double> weights(cloud.size(), 1.0 / static_cast<double>(cloud.size()));
  Eigen::Vector4d mean, after_mean;
  Eigen::Matrix4d cov, after_cov;
  weighted_moments(cloud, weights, mean, cov);
  const std::vector<Particle> before = cloud;
  // WHEN the kernel for 2000 draws (h = 0.36, h^2 var(vx | x) = 117 (m/s)^2) is wider than a
  // 5 m/s^2 prediction noise
  const double h = optimal_kernel_bandwidth(2000.0);
  EXPECT_NEAR(h, std::pow(4.0 / 12000.0, 0.125), 1e-12);
  ASSERT_TRUE(regularise_velocity(cloud, mean, cov, h, 25.0, rng));
  // THEN every copy has its own velocity, positions stay, mean and covariance are kept
  int moved = 0;
  for (std::size_t k = 0; k < cloud.size(); ++k) {
    EXPECT_EQ(cloud[k].x, before[k].x);
    EXPECT_EQ(cloud[k].y, before[k].y);
    moved += cloud[k].vx != before[k].vx && cloud[k].vy != before[k].vy;
  }
  EXPECT_EQ(moved, static_cast<int>(cloud.size()));
  weighted_moments(cloud, weights, after_mean, after_cov);
  EXPECT_NEAR(after_mean[1], mean[1], 0.5);
  EXPECT_NEAR(after_mean[3], mean[3], 0.2);
  EXPECT_NEAR(after_cov(1, 1) / cov(1, 1), 1.0, 0.05);
  EXPECT_NEAR(after_cov(3, 3) / cov(3, 3), 1.0, 0.05);
  EXPECT_NEAR(after_cov(0, 1) / cov(0, 1), 1.0, 0.05);
  EXPECT_NEAR(after_cov(2, 3) / cov(2, 3), 1.0, 0.05);
}

TEST(BernoulliParticleKernel, NoRegularisationWhenThePredictionNoiseIsWider) {
  // GIVEN a cloud whose velocity given the position spreads 3 m/s per axis
  NormalSampler rng(3);
  std::vector<Particle> cloud;
  for (int k = 0; k < 300; ++k) {
    cloud.push_back(
        {40.0 * rng.normal(), 3.0 * rng.normal(), 40.0 * rng.normal(), 3.0 * rng.normal()});
  }
  const std::vector<double> weights(cloud.size(), 1.0 / 300.0);
  Eigen::Vector4d mean;
  Eigen::Matrix4d cov;
  weighted_moments(cloud, weights, mean, cov);
  const std::vector<Particle> before = cloud;
  // WHEN the next prediction adds 5 m/s per axis, more than the kernel would (h^2 9 < 25)
  EXPECT_FALSE(regularise_velocity(cloud, mean, cov, optimal_kernel_bandwidth(300.0), 25.0, rng));
  // THEN the cloud is unchanged
  for (std::size_t k = 0; k < cloud.size(); ++k) EXPECT_EQ(cloud[k].vx, before[k].vx);
}

TEST(BernoulliParticleKernel, PredictedMomentsAreThoseOfThePropagatedCloud) {
  // GIVEN 20000 parents with correlated position and velocity, accumulated one at a time
  NormalSampler rng(11);
  std::vector<Particle> parents;
  MomentAccumulator accumulator;
  for (int k = 0; k < 20000; ++k) {
    const double px = 30.0 * rng.normal();
    parents.push_back({15000.0 + px, -8.0 + 0.5 * px + 10.0 * rng.normal(),
                       20000.0 + 20.0 * rng.normal(), -400.0 + 6.0 * rng.normal()});
    accumulator.add(parents.back());
  }
  const std::vector<double> equal(parents.size(), 1.0 / static_cast<double>(parents.size()));
  Eigen::Vector4d mean, direct_mean;
  Eigen::Matrix4d cov, direct_cov;
  accumulator.moments(mean, cov);
  weighted_moments(parents, equal, direct_mean, direct_cov);
  EXPECT_LT((mean - direct_mean).norm(), 1e-6);
  EXPECT_LT((cov - direct_cov).norm(), 1e-6);
  // WHEN they are predicted 1 s by the anticlockwise CT model (0.07 rad/s, 40 m/s^2)
  const ModelDynamics d = make_dynamics({0.07, 40.0, 700}, 1.0);
  predict_moments(d, mean, cov);
  for (Particle& p : parents) propagate(d, p, rng);
  weighted_moments(parents, equal, direct_mean, direct_cov);
  // THEN the predicted moments are the propagated cloud's, up to its sampling error
  for (int a = 0; a < 4; ++a) {
    EXPECT_NEAR(mean[a], direct_mean[a], 4.0 * std::sqrt(cov(a, a) / 20000.0)) << a;
    for (int b = 0; b < 4; ++b) {
      EXPECT_NEAR(cov(a, b), direct_cov(a, b), 0.04 * std::sqrt(cov(a, a) * cov(b, b))) << a << b;
    }
  }
}

TEST(BernoulliParticleKernel, WeightedMomentsGiveTheLeadingBlocksMean) {
  // GIVEN a weighted cloud whose first 70 particles are survivors, the rest newborns
  NormalSampler rng(8);
  std::vector<Particle> cloud;
  std::vector<double> weights;
  double total = 0.0;
  for (int k = 0; k < 100; ++k) {
    cloud.push_back({15000.0 + 30.0 * rng.normal(), -8.0 + 10.0 * rng.normal(),
                     20000.0 + 20.0 * rng.normal(),
                     -400.0 + 6.0 * rng.normal() + (k < 70 ? 0 : 40)});
    weights.push_back(0.5 + rng.uniform());
    total += weights.back();
  }
  for (double& w : weights) w /= total;
  // WHEN the moments are taken with the block's mean
  Eigen::Vector4d mean, plain_mean;
  Eigen::Matrix4d cov, plain_cov;
  BlockMean head;
  weighted_moments(cloud, weights, 70, mean, cov, head);
  weighted_moments(cloud, weights, plain_mean, plain_cov);
  // THEN the cloud's moments are the plain ones, bit for bit
  EXPECT_EQ(mean, plain_mean);
  EXPECT_EQ(cov, plain_cov);
  // AND the block's mass and mean are its own
  double mass = 0.0;
  Eigen::Vector4d sum = Eigen::Vector4d::Zero();
  for (int k = 0; k < 70; ++k) {
    mass += weights[k];
    sum += weights[k] * Eigen::Vector4d(cloud[k].x, cloud[k].vx, cloud[k].y, cloud[k].vy);
  }
  EXPECT_NEAR(head.mass, mass, 1e-12);
  EXPECT_LT((head.mean - sum / mass).norm(), 1e-8);
}

TEST(BernoulliParticleKernel, VelocityGivenPositionIsThePosteriorMeanVelocity) {
  // GIVEN a Gaussian predicted cloud whose velocity depends on its position, weighted by a
  // likelihood of the position only (a plot 40 m east of the predicted mean, sigma 5 m)
  NormalSampler rng(5);
  std::vector<Particle> cloud;
  std::vector<double> weights;
  double total = 0.0;
  for (int k = 0; k < 200000; ++k) {
    const double px = 50.0 * rng.normal(), py = 50.0 * rng.normal();
    cloud.push_back({px, 100.0 + 0.6 * px + 30.0 * rng.normal(), py,
                     -400.0 - 0.3 * py + 0.2 * px + 30.0 * rng.normal()});
    const double dx = px - 40.0, dy = py;
    weights.push_back(std::exp(-0.5 * (dx * dx + dy * dy) / 25.0));
    total += weights.back();
  }
  for (double& w : weights) w /= total;
  const std::vector<double> equal(cloud.size(), 1.0 / static_cast<double>(cloud.size()));
  Eigen::Vector4d prior_mean, posterior_mean;
  Eigen::Matrix4d prior_cov, posterior_cov;
  weighted_moments(cloud, equal, prior_mean, prior_cov);
  weighted_moments(cloud, weights, posterior_mean, posterior_cov);
  // WHEN the velocity is conditioned on the posterior mean position
  double vx = 0.0, vy = 0.0;
  ASSERT_TRUE(
      velocity_given_position(prior_mean, prior_cov, posterior_mean[0], posterior_mean[2], vx, vy));
  // THEN it is the weighted mean velocity (100 + 0.6 * 40 = 124, -400 + 0.2 * 40 = -392),
  // which carries the residual's noise (ESS ~ 2000 here, 30 m/s: 0.7 m/s)
  EXPECT_NEAR(posterior_mean[0], 40.0 * 2500.0 / 2525.0, 0.5);
  EXPECT_NEAR(vx, 100.0 + 0.6 * posterior_mean[0], 0.3);
  EXPECT_NEAR(vy, -400.0 + 0.2 * posterior_mean[0] - 0.3 * posterior_mean[2], 0.3);
  EXPECT_NEAR(posterior_mean[1], vx, 2.5);
  EXPECT_NEAR(posterior_mean[3], vy, 2.5);
  // AND a degenerate position covariance leaves the velocity alone
  Eigen::Matrix4d flat = prior_cov;
  flat(0, 0) = flat(2, 2) = flat(0, 2) = flat(2, 0) = 0.0;
  double ux = 1.0, uy = 2.0;
  EXPECT_FALSE(velocity_given_position(prior_mean, flat, 0.0, 0.0, ux, uy));
  EXPECT_EQ(ux, 1.0);
  EXPECT_EQ(uy, 2.0);
}

TEST(BernoulliParticleKernel, EffectiveSampleSize) {
  EXPECT_NEAR(effective_sample_size(std::vector<double>{0.25, 0.25, 0.25, 0.25}), 4.0, 1e-12);
  EXPECT_NEAR(effective_sample_size(std::vector<double>{1.0, 0.0, 0.0}), 1.0, 1e-12);
}

}  // namespace
}  // namespace skytrack::bernoulli
