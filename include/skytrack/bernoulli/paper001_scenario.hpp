#pragma once
// The simulated experiment of paper 001 (§4): a fast target manoeuvring CV - CT - CV - CT -
// CV for 100 s, seen by a fixed range/bearing sensor at the origin with P_D = 0.98 and a
// Poisson number (mean 20) of clutter plots uniform over a half disc of 25 km per 1 s scan.
// For tests, the benchmark and tools/experiments/bernoulli-mc. The paper's bearing is
// arctan(y/x) in [0, pi], the half-plane north of the sensor; in skytrack's azimuth
// (clockwise from north, DESIGN.md) that is [-pi/2, pi/2], which the clutter covers.
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "skytrack/bernoulli/bernoulli_estimate.hpp"

namespace skytrack::bernoulli {

struct Paper001Options {
  int scans = 100;
  int first_scan_with_target = 0;  // the target exists in scans [first, last]
  int last_scan_with_target = 99;
  double detection_probability = 0.98;
  double clutter_rate = 20.0;   // mean clutter plots per scan
  double max_range = 25000.0;   // [m] clutter range interval [0, max_range]
  double sigma_range = 5.0;     // [m]
  double sigma_azimuth = 3e-3;  // [rad]
  std::uint64_t seed = 1;
};

struct Paper001Scan {
  double time = 0.0;  // [s] scan k at k T, T = 1 s
  bool target_present = false;
  Eigen::Vector4d truth = Eigen::Vector4d::Zero();  // [x, vx, y, vy]
  std::vector<PolarPlot2d> plots;                   // target plot (if detected) and clutter
};

/// The noise-free truth of scan k: starts at (11689, 20840) m with (-8.3, -399.9) m/s; the
/// step from scan k to k+1 is CV for k in [0, 20), a clockwise turn of 0.1 rad/s in
/// [20, 40), CV in [40, 60), an anticlockwise turn of 0.07 rad/s in [60, 80), CV after.
std::vector<Eigen::Vector4d> paper001_truth(int scans);

/// One Monte Carlo run's scans, deterministic for options.seed (plots in random order).
std::vector<Paper001Scan> simulate_paper001(const Paper001Options& options);

}  // namespace skytrack::bernoulli
