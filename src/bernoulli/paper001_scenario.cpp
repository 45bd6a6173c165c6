// Paper 001 §4 scenario: truth, detections and Poisson clutter.
#include "skytrack/bernoulli/paper001_scenario.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "skytrack/bernoulli/particle_kernel.hpp"

namespace skytrack::bernoulli {

std::vector<Eigen::Vector4d> paper001_truth(int scans) {
  std::vector<Eigen::Vector4d> truth;
  truth.reserve(static_cast<std::size_t>(std::max(scans, 0)));
  Particle p{11689.0, -8.3, 20840.0, -399.9};
  for (int k = 0; k < scans; ++k) {
    truth.emplace_back(p.x, p.vx, p.y, p.vy);
    double turn_rate = 0.0;
    if (k >= 20 && k < 40) turn_rate = -0.1;  // clockwise
    if (k >= 60 && k < 80) turn_rate = 0.07;  // anticlockwise
    const ModelDynamics m = make_dynamics({turn_rate, 0.0, 1}, 1.0);
    const Particle q = p;
    p.x = q.x + m.s_over_w * q.vx - m.one_minus_c_over_w * q.vy;
    p.vx = m.c * q.vx - m.s * q.vy;
    p.y = q.y + m.one_minus_c_over_w * q.vx + m.s_over_w * q.vy;
    p.vy = m.s * q.vx + m.c * q.vy;
  }
  return truth;
}

std::vector<Paper001Scan> simulate_paper001(const Paper001Options& options) {
  std::mt19937_64 engine(options.seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::poisson_distribution<int> clutter_count(options.clutter_rate);
  const std::vector<Eigen::Vector4d> truth = paper001_truth(options.scans);
  std::vector<Paper001Scan> scans(truth.size());
  for (std::size_t k = 0; k < truth.size(); ++k) {
    Paper001Scan& scan = scans[k];
    scan.time = static_cast<double>(k);
    scan.truth = truth[k];
    const int kk = static_cast<int>(k);
    scan.target_present =
        kk >= options.first_scan_with_target && kk <= options.last_scan_with_target;
    const PolarPlot2d noise_model{0.0, 0.0, options.sigma_range, options.sigma_azimuth};
    if (scan.target_present && uniform(engine) < options.detection_probability) {
      PolarPlot2d plot = noise_model;
      plot.range = std::hypot(truth[k][0], truth[k][2]) + options.sigma_range * normal(engine);
      plot.azimuth = std::atan2(truth[k][0], truth[k][2]) + options.sigma_azimuth * normal(engine);
      scan.plots.push_back(plot);
    }
    const int clutter = clutter_count(engine);
    for (int c = 0; c < clutter; ++c) {
      PolarPlot2d plot = noise_model;
      // The paper's bearing arctan(y/x) in [0, pi] is the half-plane y >= 0, azimuths
      // [-pi/2, pi/2] clockwise from north: the target stays inside it (y >= 4.8 km).
      plot.azimuth = std::numbers::pi * (uniform(engine) - 0.5);
      plot.range = options.max_range * uniform(engine);
      scan.plots.push_back(plot);
    }
    std::shuffle(scan.plots.begin(), scan.plots.end(), engine);
  }
  return scans;
}

}  // namespace skytrack::bernoulli
