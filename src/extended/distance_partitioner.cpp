// Single-linkage distance partitioning over a k-d tree (see distance_partitioner.hpp).
#include "skytrack/extended/distance_partitioner.hpp"

namespace skytrack::extended {

int DistancePartitioner::find(int i) noexcept {
  while (parent_[i] != i) {
    parent_[i] = parent_[parent_[i]];  // path halving
    i = parent_[i];
  }
  return i;
}

void DistancePartitioner::partition(std::span<const Eigen::Vector2d> positions, double distance,
                                    std::vector<std::vector<int>>& groups) {
  groups.clear();
  const int n = static_cast<int>(positions.size());
  points_.clear();
  parent_.resize(n);
  for (int i = 0; i < n; ++i) {
    parent_[i] = i;
    const bool ok = positions[i].allFinite();
    // Non-finite plots are put far away and dropped below.
    points_.emplace_back(ok ? positions[i].x() : 0.0, ok ? positions[i].y() : 0.0, 0.0);
  }
  index_.build(points_, 2);
  for (int i = 0; i < n; ++i) {
    if (!positions[i].allFinite()) continue;
    index_.within(points_[i], distance, neighbours_);
    for (int j : neighbours_) {
      if (j <= i || !positions[j].allFinite()) continue;
      const int a = find(i), b = find(j);
      if (a != b) parent_[std::max(a, b)] = std::min(a, b);  // root = smallest index
    }
  }
  group_of_root_.assign(n, -1);
  for (int i = 0; i < n; ++i) {
    if (!positions[i].allFinite()) continue;
    const int root = find(i);
    if (group_of_root_[root] < 0) {
      group_of_root_[root] = static_cast<int>(groups.size());
      groups.emplace_back();
    }
    groups[group_of_root_[root]].push_back(i);
  }
}

}  // namespace skytrack::extended
