#pragma once
// Paper 002's experiment (Liu et al. 2023, section 3.1) as a simulation and a Monte Carlo
// runner for the three extent estimators. Our reading of what the paper leaves open is in
// docs/extended.md ("Reading of the paper"); the defaults below are that reading.
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "skytrack/extended/extended_spec.hpp"

namespace skytrack::extended::experiment {

enum class NoiseKind { kBounded, kGaussian };

struct PaperScenario {
  double period = 10.0;                           // [s] T
  double duration = 160.0;                        // [s]
  Eigen::Vector2d start_position{800.0, -200.0};  // [m] x0 (first two of the printed six)
  Eigen::Vector2d start_velocity{9.82, -9.82};    // [m/s] 50 km/h
  double turn_rate = 4.5;     // [deg/s] "4.5" in [30, 70] s, "-4.5" in [90, 130] s
  double major_axis = 170.0;  // [m] the object's semi-axes (not printed: our 340 m x 80 m
  double minor_axis = 40.0;   //      ship), major axis along the heading
  Eigen::Matrix2d sensor_bound = Eigen::Vector2d(400.0, 100.0).asDiagonal();  // U [m^2]
  double mean_plots = 10.0;  // Poisson mean of the plots per scan (not printed)
  NoiseKind noise = NoiseKind::kBounded;
};

struct ObjectTruth {
  double time = 0.0;
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();
  Eigen::Matrix2d extent = Eigen::Matrix2d::Zero();
};

/// The object at every scan time 0, T, ..., duration.
std::vector<ObjectTruth> paper_truth(const PaperScenario& scenario);

/// Plots of one object: scatterers uniform over its ellipse plus noise, uniform in E(0, U)
/// (bounded) or N(0, U / 4) (Gaussian, the same covariance); `count` plots appended.
void sample_object_plots(const ObjectTruth& truth, int count, const Eigen::Matrix2d& bound,
                         NoiseKind noise, std::mt19937_64& rng, std::vector<Eigen::Vector2d>& out);

/// One filter as the comparison runs it: its spec and the noise matrix it is given (for
/// SMF-EOT the bound is smf.bound_sigmas^2 times this).
struct FilterSetup {
  std::string name;
  ExtendedSpec spec;
  Eigen::Matrix2d noise = Eigen::Matrix2d::Identity();
};

struct McResult {
  double armse_position = 0.0;    // [m]   mean over scans of the RMSE over runs
  double armse_velocity = 0.0;    // [m/s]
  double mean_gwd_squared = 0.0;  // [m^2] eq. 50 as printed, mean over scans and runs
  double mean_gwd = 0.0;          // [m]   its root, mean over scans and runs
};

/// `runs` runs with seeds derived from `seed`; run i draws the same plots for every filter.
McResult run_paper_monte_carlo(const PaperScenario& scenario, const FilterSetup& filter, int runs,
                               std::uint64_t seed);

/// The comparison's three filters with the paper's parameters (lambda = 0.25, Q = 0.5^2,
/// theta = 40 s). `bayes_noise` is what the random-matrix and MEM-EKF filters take as R.
/// `literal_smf` adds SMF-EOT with the extent step as printed, after SMF-EOT.
std::vector<FilterSetup> paper_filters(const PaperScenario& scenario,
                                       const Eigen::Matrix2d& bayes_noise,
                                       bool literal_smf = false);

}  // namespace skytrack::extended::experiment
