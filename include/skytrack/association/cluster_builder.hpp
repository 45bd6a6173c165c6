#pragma once
// Track clusters for JPDA (Fortmann, Bar-Shalom & Scheffe 1983, "Sonar tracking of multiple
// targets using joint probabilistic data association", IEEE JOE 8(3), sec. III: the
// validation matrix splits into independent blocks). Two tracks are in one cluster when a
// chain of shared gated plots links them; found with union-find over tracks and plots
// (path halving, union by size; Tarjan 1975), O((T + P + pairs) * alpha).
//
// Determinism: clusters come in order of their lowest track index; tracks and plots inside
// a cluster are ascending. A track with no gated plot is a singleton cluster with no plots;
// a plot gated by no track belongs to no cluster (it is listed in free_plots()).
#include <span>
#include <vector>

namespace skytrack {

/// One (track, plot) pair that passed the gate.
struct GatedPair {
  int track = 0;
  int plot = 0;
};

struct Cluster {
  std::vector<int> tracks;  // ascending scan track indices
  std::vector<int> plots;   // ascending scan plot indices gated by at least one of them
};

/// Keeps its buffers (and the clusters' vectors) between scans: after warm-up, build()
/// does not allocate.
class ClusterBuilder {
 public:
  /// Clusters of the scan's num_tracks tracks given the gated pairs. Pairs with an index
  /// out of range are ignored; duplicates are harmless. The span stays valid until the
  /// next call.
  std::span<const Cluster> build(int num_tracks, int num_plots,
                                 std::span<const GatedPair> pairs) noexcept;

  std::span<const Cluster> clusters() const noexcept;
  /// Plots of the last build gated by no track (ascending).
  std::span<const int> free_plots() const noexcept { return free_plots_; }

 private:
  int find(int node) noexcept;
  void unite(int a, int b) noexcept;

  std::vector<int> parent_;  // union-find over tracks [0, T) and plots [T, T + P)
  std::vector<int> size_;
  std::vector<int> cluster_of_root_;
  std::vector<char> plot_gated_;
  std::vector<Cluster> clusters_;  // first count_ are live; the rest keep their capacity
  std::vector<int> free_plots_;
  int count_ = 0;
};

}  // namespace skytrack
