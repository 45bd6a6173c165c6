#pragma once
// The two baselines of paper 000 §4.1, for the reproduction only: the box-particle PHD
// group filter without labels (BP-PHD, the paper's ref. 15) and the same after the §3.1
// preprocessing (MS-BP-PHD). Both extract states by k-means over the resampled boxes with
// k = round(N-hat). They share the core's box steps (group/box_particle.hpp).
#include <cstdint>
#include <random>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "skytrack/clutter/clutter_rejector.hpp"
#include "skytrack/clutter/mean_shift_partition.hpp"
#include "skytrack/group/box_particle.hpp"
#include "skytrack/group/group_spec.hpp"
#include "skytrack/group/labeled_box_phd.hpp"

namespace group_mc {

using skytrack::group::BoxParticle;
using skytrack::group::BoxVec;
using skytrack::group::GroupSpec;

/// k-means seeding: random boxes as the initial centres (Forgy, the classic k-means whose
/// local optima the paper blames), or k-means++ (Arthur & Vassilvitskii 2007).
enum class KmeansInit { kRandom, kPlusPlus };

class BpPhdKmeans {
 public:
  /// mean_shift: true = MS-BP-PHD (clutter rejection + mean-shift cells, spec.preprocessing);
  /// false = BP-PHD: no clutter rejection, distance partitioning (plots closer than
  /// partition_distance [m], transitively, share a cell).
  BpPhdKmeans(const GroupSpec& spec, bool mean_shift, double partition_distance, KmeansInit init);

  /// One scan; returns the k-means state estimates [x vx y vy].
  const std::vector<BoxVec>& step(double time, std::span<const Eigen::Vector3d> plots);
  double group_count() const { return group_count_; }

 private:
  void kmeans(int k);
  double uniform(double lo, double hi);

  GroupSpec spec_;
  KmeansInit init_;
  skytrack::clutter::MeanShiftPartitioner partitioner_;
  std::mt19937_64 rng_;
  std::vector<BoxParticle> particles_;
  std::vector<skytrack::group::GroupCell> cells_;
  std::vector<skytrack::group::PlaneBox> previous_cells_;
  std::vector<BoxVec> estimates_;
  std::vector<BoxVec> prior_centre_, prior_half_;
  skytrack::group::PhdUpdateResult update_;
  std::vector<int> assignment_;
  bool has_time_ = false;
  double last_time_ = 0.0;
  double group_count_ = 0.0;
};

}  // namespace group_mc
