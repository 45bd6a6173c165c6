#pragma once
// One fusion cycle's track-to-track association (paper 004 eq. 13 with a one-to-one
// constraint): which system track each local track joins. Not installed.
//
// Pairs of local tracks of different sensors are scored with the MOSPA of eq. 12 (only pairs
// the spatial gate lets through: farther ones can never pass gamma). Sensors are taken in
// increasing id: the cost of a local track for a system track is the mean MOSPA to that
// system track's members on other sensors (those decided this cycle, and for sensors not yet
// decided, last cycle's members; a member outside the spatial gate counts c), forbidden at or
// above gamma; a gated minimum-cost assignment per sensor (by connected components) decides,
// so a system track takes at most one track per sensor. A local track that joins none stays
// in last cycle's system track unless a lower sensor's track has taken it; else it starts one.
#include <cstdint>
#include <span>
#include <vector>

#include "fusion_types.hpp"
#include "skytrack/association/assignment.hpp"
#include "skytrack/fusion/fusion_spec.hpp"

namespace skytrack::fusion::detail {

class CycleAssociator {
 public:
  explicit CycleAssociator(const FusionSpec& spec);

  /// `tracks` sorted by (sensor, id). Writes into `system_of` the system track of each
  /// (existing numbers, or new ones taken from `next_id`).
  void associate(std::span<const PresentTrack> tracks, std::uint64_t cycle,
                 std::uint64_t window_cycles, std::int64_t& next_id,
                 std::vector<std::int64_t>& system_of);

  /// Pairs scored by MOSPA in the last call (after the spatial gate).
  std::size_t pairs_scored() const { return pairs_scored_; }

 private:
  struct Neighbour {
    int other;
    double mospa;
  };
  struct Edge {
    int row;     // track index
    int column;  // dense system index
    double cost;
  };

  void find_neighbours(std::span<const PresentTrack> tracks, std::uint64_t cycle,
                       std::uint64_t window_cycles);
  double mospa_of(int a, int b) const;
  void decide_sensor(std::span<const PresentTrack> tracks, int begin, int end,
                     std::int64_t& next_id);
  void solve_components(int begin, int end);
  int dense_index(std::int64_t system_id, std::int64_t& next_id, bool create);

  FusionSpec spec_;
  double gate_radius_ = 0.0;  // in sigmas (normalised) or metres; infinite: no spatial gate
  std::size_t pairs_scored_ = 0;

  // Workspaces, reused every cycle.
  std::vector<std::vector<Neighbour>> neighbours_;
  std::vector<int> by_x_;
  std::vector<std::int64_t> system_ids_;     // dense index -> system id
  std::vector<std::vector<int>> members_;    // dense index -> track indices
  std::vector<int> current_;                 // track -> dense system index (-1: none)
  std::vector<int> previous_;                // track -> last cycle's dense index
  std::vector<bool> decided_sensor_member_;  // dense index -> taken by a decided sensor
  std::vector<Edge> edges_;
  std::vector<int> parent_;    // union-find over rows and columns
  std::vector<int> assigned_;  // row -> dense system index
  std::vector<int> component_rows_, component_columns_;
  AssignmentSolver solver_;
  Eigen::MatrixXd cost_;
};

}  // namespace skytrack::fusion::detail
