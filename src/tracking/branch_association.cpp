#include "skytrack/tracking/branch_association.hpp"

#include <algorithm>
#include <tuple>

namespace skytrack {

std::vector<BranchPair> confirm_pairs(std::span<const BranchPair> pairs, int num_tracks,
                                      int num_plots) {
  std::vector<BranchPair> order(pairs.begin(), pairs.end());
  std::sort(order.begin(), order.end(), [](const BranchPair& a, const BranchPair& b) {
    return std::make_tuple(static_cast<int>(a.kind), -a.probability, a.track, a.plot) <
           std::make_tuple(static_cast<int>(b.kind), -b.probability, b.track, b.plot);
  });
  std::vector<std::uint8_t> plot_used(static_cast<std::size_t>(std::max(num_plots, 0)), 0);
  // 1: updated by a confirmed pair; 2: created a branch (may create more, never be updated).
  std::vector<std::uint8_t> track_used(static_cast<std::size_t>(std::max(num_tracks, 0)), 0);
  std::vector<BranchPair> confirmed;
  for (const BranchPair& pair : order) {
    if (pair.track < 0 || pair.track >= num_tracks || pair.plot < 0 || pair.plot >= num_plots) {
      continue;
    }
    std::uint8_t& track = track_used[static_cast<std::size_t>(pair.track)];
    std::uint8_t& plot = plot_used[static_cast<std::size_t>(pair.plot)];
    if (plot != 0) continue;
    const bool updating = updates_track(pair.kind);
    if (track == 1 || (updating && track != 0)) continue;
    plot = 1;
    track = updating ? 1 : 2;
    confirmed.push_back(pair);
  }
  return confirmed;
}

}  // namespace skytrack
