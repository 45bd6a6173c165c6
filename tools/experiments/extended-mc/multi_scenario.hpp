#pragma once
// Several extended objects in clutter, two of them crossing, for the ExtendedTracker with
// each estimator (issue 27, deliverable 5). Generated here (table C of docs/extended.md);
// the same scenario ships as config/scenarios/extended_crossing.yaml for `skytrack simulate`
// / `track` / `eval` and skytrackd (same objects, noise, detection and clutter, the
// simulator's own random draws; tools/experiments/extended-crossing.sh).
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "paper_scenario.hpp"
#include "skytrack/extended/extended_spec.hpp"

namespace skytrack::extended::experiment {

struct MultiResult {
  double mean_gwd = 0.0;            // [m]   root of eq. 50, over matched object-scans
  double mean_gwd_squared = 0.0;    // [m^2] eq. 50 as printed
  double centre_rmse = 0.0;         // [m]
  double missed = 0.0;              // fraction of object-scans with no confirmed track on it
  double number_changes = 0.0;      // per object per run: the number on it changed
  long number_change_count = 0;     // the same, summed over the runs' objects
  double objects_one_number = 0.0;  // fraction of objects tracked with one number all run
  double false_tracks = 0.0;        // confirmed tracks on no object, mean per scan
  double scan_cost_us = 0.0;        // [us] mean ExtendedTracker::process per scan
};

/// One scan of the scenario: every object's plots (N(0, U / 4) noise, U of PaperScenario)
/// then the clutter; `truth` the four objects at `time`.
struct MultiScan {
  double time = 0.0;
  std::vector<Eigen::Vector2d> plots;
  std::vector<ObjectTruth> truth;
};
std::vector<MultiScan> multi_object_scans(std::uint64_t seed);

/// `runs` runs of the scenario (plots N(0, U/4) per object, Poisson clutter) with the
/// tracker under `spec`; every plot is given `noise` as its covariance.
MultiResult run_multi_object(const ExtendedSpec& spec, const Eigen::Matrix2d& noise, int runs,
                             std::uint64_t seed);

/// The table for the three estimators.
void print_multi_table(const Eigen::Matrix2d& bayes_noise, int runs, std::uint64_t seed);

}  // namespace skytrack::extended::experiment
