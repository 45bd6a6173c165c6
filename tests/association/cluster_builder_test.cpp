#include "skytrack/association/cluster_builder.hpp"

#include <algorithm>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace skytrack {
namespace {

TEST(ClusterBuilder, TracksSharingPlotsFormOneCluster) {
  // GIVEN tracks 0 and 1 share plot 0, tracks 1 and 3 share plot 2, track 2 alone has
  // plot 4, track 4 has none; plots 1 and 3 are gated by nobody.
  const std::vector<GatedPair> pairs = {{3, 2}, {0, 0}, {1, 0}, {2, 4}, {1, 2}, {3, 5}};
  ClusterBuilder builder;
  const auto clusters = builder.build(5, 6, pairs);  // WHEN clustered
  ASSERT_EQ(clusters.size(), 3U);                    // THEN in order of their lowest track
  EXPECT_EQ(clusters[0].tracks, (std::vector<int>{0, 1, 3}));
  EXPECT_EQ(clusters[0].plots, (std::vector<int>{0, 2, 5}));
  EXPECT_EQ(clusters[1].tracks, (std::vector<int>{2}));
  EXPECT_EQ(clusters[1].plots, (std::vector<int>{4}));
  EXPECT_EQ(clusters[2].tracks, (std::vector<int>{4}));  // singleton without plots
  EXPECT_TRUE(clusters[2].plots.empty());
  EXPECT_EQ(std::vector<int>(builder.free_plots().begin(), builder.free_plots().end()),
            (std::vector<int>{1, 3}));
}

// Connected components by repeated relaxation: label = lowest track reachable.
std::vector<int> component_labels(int tracks, int plots, const std::vector<GatedPair>& pairs) {
  std::vector<int> label(static_cast<std::size_t>(tracks + plots));
  for (int i = 0; i < tracks + plots; ++i) label[static_cast<std::size_t>(i)] = i;
  for (bool changed = true; changed;) {
    changed = false;
    for (const GatedPair& p : pairs) {
      int& a = label[static_cast<std::size_t>(p.track)];
      int& b = label[static_cast<std::size_t>(tracks + p.plot)];
      if (a != b) {
        a = b = std::min(a, b);
        changed = true;
      }
    }
  }
  return label;
}

TEST(ClusterBuilder, ClustersAreTheConnectedComponentsInDeterministicOrder) {
  std::mt19937_64 rng(3);
  ClusterBuilder builder;  // reused across "scans"
  for (int scan = 0; scan < 100; ++scan) {
    std::uniform_int_distribution<int> size_of(0, 40);
    const int tracks = size_of(rng), plots = size_of(rng);
    std::vector<GatedPair> pairs;
    if (tracks > 0 && plots > 0) {
      std::uniform_int_distribution<int> track_of(0, tracks - 1), plot_of(0, plots - 1);
      for (int n = size_of(rng); n > 0; --n) pairs.push_back({track_of(rng), plot_of(rng)});
    }
    const auto clusters = builder.build(tracks, plots, pairs);
    const std::vector<int> label = component_labels(tracks, plots, pairs);
    std::vector<int> seen_tracks(static_cast<std::size_t>(tracks), 0);
    int previous_first = -1;
    for (const Cluster& cluster : clusters) {
      ASSERT_FALSE(cluster.tracks.empty());
      EXPECT_TRUE(std::is_sorted(cluster.tracks.begin(), cluster.tracks.end()));
      EXPECT_TRUE(std::is_sorted(cluster.plots.begin(), cluster.plots.end()));
      EXPECT_GT(cluster.tracks.front(), previous_first);
      previous_first = cluster.tracks.front();
      const int id = label[static_cast<std::size_t>(cluster.tracks.front())];
      for (int t : cluster.tracks) {
        EXPECT_EQ(label[static_cast<std::size_t>(t)], id);
        ++seen_tracks[static_cast<std::size_t>(t)];
      }
      for (int j : cluster.plots) EXPECT_EQ(label[static_cast<std::size_t>(tracks + j)], id);
      // The whole component is here: count its members.
      const auto members = std::count(label.begin(), label.end(), id);
      EXPECT_EQ(static_cast<std::size_t>(members), cluster.tracks.size() + cluster.plots.size());
    }
    EXPECT_TRUE(std::all_of(seen_tracks.begin(), seen_tracks.end(), [](int n) { return n == 1; }));
  }
}

TEST(ClusterBuilder, OutOfRangePairsAreIgnored) {
  const std::vector<GatedPair> pairs = {{0, 0}, {-1, 0}, {0, 7}, {5, 0}};
  ClusterBuilder builder;
  const auto clusters = builder.build(2, 1, pairs);
  ASSERT_EQ(clusters.size(), 2U);
  EXPECT_EQ(clusters[0].plots, (std::vector<int>{0}));
  EXPECT_TRUE(clusters[1].plots.empty());
}

}  // namespace
}  // namespace skytrack
