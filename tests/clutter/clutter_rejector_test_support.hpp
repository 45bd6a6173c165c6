#pragma once
// Plot scenes for the ClutterRejector tests: uniform clutter, Gaussian blobs, and both.
#include <cstdint>
#include <random>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "skytrack/clutter/clutter_rejection_spec.hpp"

namespace skytrack::test {

using Points = std::vector<Eigen::Vector3d>;
inline constexpr std::span<const std::uint8_t> kNoProtection{};

inline config::ClutterRejectionSpec enabled_spec(double h = 500.0) {
  config::ClutterRejectionSpec spec;
  spec.enabled = true;
  spec.kernel_bandwidth = h;
  spec.beta = 1;
  spec.n_f = 10;
  spec.mean_shift.bandwidth = h;
  return spec;
}

// Uniform plots over [0, side]^2 (z = 0).
inline void add_uniform(Points& points, int count, double side, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, side);
  for (int i = 0; i < count; ++i) {
    const double x = u(rng);
    points.emplace_back(x, u(rng), 0.0);
  }
}

// Gaussian blob of `count` plots with standard deviation sigma per axis (z = 0).
inline void add_blob(Points& points, const Eigen::Vector2d& centre, int count, double sigma,
                     std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, sigma);
  for (int i = 0; i < count; ++i) {
    const double x = centre.x() + n(rng);
    points.emplace_back(x, centre.y() + n(rng), 0.0);
  }
}

// 100 km x 100 km, 2000 uniform clutter plots (2e-7 per m^2, about 0.3 neighbours within
// h = 500 m of a plot), plus 10 clusters of 20 plots with sigma = 100 m, 25 km apart.
struct ClutterScene {
  Points points;
  int clutter = 0;
};

inline ClutterScene clutter_and_clusters(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  ClutterScene scene;
  add_uniform(scene.points, 2000, 100e3, rng);
  scene.clutter = static_cast<int>(scene.points.size());
  for (int c = 0; c < 10; ++c) {
    const Eigen::Vector2d centre(12.5e3 + 25e3 * (c % 4), 12.5e3 + 25e3 * (c / 4));
    add_blob(scene.points, centre, 20, 100.0, rng);
  }
  return scene;
}

}  // namespace skytrack::test
