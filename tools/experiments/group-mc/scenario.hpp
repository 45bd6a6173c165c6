#pragma once
// Paper 000's two simulated scenarios (§4.1, §4.2): group centroid truth and each scan's
// plots (group plots uniform round the centroid plus sensor noise, Poisson clutter).
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "skytrack/group/box_particle.hpp"

namespace group_mc {

using skytrack::group::BoxVec;

struct TruthGroup {
  int id = 0;
  int first = 1;  // first and last scan alive (1-based, inclusive)
  int last = 50;
  double plot_rate = 15.0;    // Poisson mean of the group's plots per scan
  std::vector<BoxVec> state;  // per scan 1..scans (index k - 1); valid in [first, last]
  bool alive(int k) const { return k >= first && k <= last; }
};

struct ScenarioSpec {
  int scans = 50;
  double dt = 1.0;                 // [s]
  double turn_rate = 0.0;          // [rad/s] truth CT rate; 0 = CV
  double process_sigma = 0.1;      // [m/s^2] acceleration noise of the centroids
  double measurement_sigma = 2.5;  // [m]
  double half_spread = 10.0;       // [m] plots uniform in +- this round the centroid
  double clutter_rate = 10.0;      // Poisson mean per scan over the area
  double area_half = 1000.0;       // area [-a, a]^2 [m]
  double group_detection = 1.0;    // P_d of a whole group per scan
};

struct Scan {
  double time = 0.0;
  std::vector<Eigen::Vector3d> plots;
  std::vector<int> source;  // truth group id per plot, 0 for clutter
  std::vector<int> missed;  // ids of live groups not detected in this scan
};

struct Scenario {
  ScenarioSpec spec;
  std::vector<TruthGroup> groups;
  std::vector<Scan> scans;
  /// Positions of the live groups at scan k (1-based) and their ids.
  std::vector<Eigen::VectorXd> truth_positions(int k, std::vector<int>* ids = nullptr) const;
};

/// Experiment 1 (six groups, CT 3 deg/s, merge at 10, split at 25), seeded.
Scenario make_experiment1(std::uint64_t seed);
/// Experiment 2 (two groups, CV, P_d 0.98), seeded.
Scenario make_experiment2(std::uint64_t seed);

}  // namespace group_mc
