// Union-find clustering of gated track-plot pairs (Fortmann, Bar-Shalom & Scheffe 1983,
// sec. III; Tarjan 1975 for the disjoint-set forest).
#include "skytrack/association/cluster_builder.hpp"

#include <cstddef>
#include <utility>

namespace skytrack {
namespace {

std::size_t at(int i) {
  return static_cast<std::size_t>(i);
}

}  // namespace

int ClusterBuilder::find(int node) noexcept {
  while (parent_[at(node)] != node) {
    parent_[at(node)] = parent_[at(parent_[at(node)])];  // path halving
    node = parent_[at(node)];
  }
  return node;
}

void ClusterBuilder::unite(int a, int b) noexcept {
  a = find(a);
  b = find(b);
  if (a == b) return;
  if (size_[at(a)] < size_[at(b)] || (size_[at(a)] == size_[at(b)] && b < a)) std::swap(a, b);
  parent_[at(b)] = a;
  size_[at(a)] += size_[at(b)];
}

std::span<const Cluster> ClusterBuilder::build(int num_tracks, int num_plots,
                                               std::span<const GatedPair> pairs) noexcept {
  const int tracks = num_tracks > 0 ? num_tracks : 0;
  const int plots = num_plots > 0 ? num_plots : 0;
  const int nodes = tracks + plots;
  parent_.resize(at(nodes));
  size_.assign(at(nodes), 1);
  for (int i = 0; i < nodes; ++i) parent_[at(i)] = i;
  plot_gated_.assign(at(plots), 0);
  for (const GatedPair& pair : pairs) {
    if (pair.track < 0 || pair.track >= tracks || pair.plot < 0 || pair.plot >= plots) continue;
    plot_gated_[at(pair.plot)] = 1;
    unite(pair.track, tracks + pair.plot);
  }

  // Number clusters by their lowest track: scanning tracks in order meets each root first
  // at that track, and appends tracks and then plots in ascending order.
  cluster_of_root_.assign(at(nodes), -1);
  count_ = 0;
  for (int t = 0; t < tracks; ++t) {
    const int root = find(t);
    int& id = cluster_of_root_[at(root)];
    if (id < 0) {
      id = count_++;
      if (clusters_.size() < at(count_)) clusters_.emplace_back();
      clusters_[at(id)].tracks.clear();
      clusters_[at(id)].plots.clear();
    }
    clusters_[at(id)].tracks.push_back(t);
  }
  free_plots_.clear();
  for (int j = 0; j < plots; ++j) {
    if (plot_gated_[at(j)] == 0) {
      free_plots_.push_back(j);
      continue;
    }
    clusters_[at(cluster_of_root_[at(find(tracks + j))])].plots.push_back(j);
  }
  return clusters();
}

std::span<const Cluster> ClusterBuilder::clusters() const noexcept {
  return {clusters_.data(), at(count_)};
}

}  // namespace skytrack
