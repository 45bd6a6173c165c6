// ExtendedTracker: a hull longer than the partition distance's reach, whose first scans' plots
// left a gap wider than it (two partitions), starts one track, not one per piece
// (crossing seed 186's object D: 340 m, plots split 2 + 5 in two scans, then whole).
#include <cstdint>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "skytrack/extended/extended_tracker.hpp"

namespace skytrack::extended {
namespace {

// A 340 m x 40 m hull (semi-axes 170 m, 20 m) east at 10 m/s. Plots at fixed offsets along and
// across it: in the first two scans four at each end, 130 m apart; then ten over its length,
// at most 40 m apart.
std::vector<Eigen::Vector2d> hull_plots(int scan) {
  const Eigen::Vector2d centre(100.0 * scan, 0.0);
  static const double pieces[8][2] = {{-165, 8}, {-140, -10}, {-120, 4}, {-100, -6},
                                      {30, 5},   {75, -12},   {120, 10}, {160, -4}};
  static const double whole[10][2] = {{-160, 6}, {-125, -9}, {-90, 12}, {-55, -4}, {-20, 9},
                                      {15, -11}, {50, 3},    {85, -7},  {120, 10}, {155, -2}};
  std::vector<Eigen::Vector2d> plots;
  if (scan < 2) {
    for (const auto& p : pieces) plots.push_back(centre + Eigen::Vector2d(p[0], p[1]));
  } else {
    for (const auto& p : whole) plots.push_back(centre + Eigen::Vector2d(p[0], p[1]));
  }
  return plots;
}

TEST(LongHull, ItsPiecesStartOneTrack) {
  for (EstimatorKind kind :
       {EstimatorKind::kSmf, EstimatorKind::kRandomMatrix, EstimatorKind::kMemEkf}) {
    SCOPED_TRACE(static_cast<int>(kind));
    ExtendedSpec spec;
    spec.kind = kind;
    ExtendedTracker tracker(spec);
    std::set<std::uint64_t> confirmed;
    for (int scan = 0; scan < 8; ++scan) {
      const std::vector<Eigen::Vector2d> plots = hull_plots(scan);
      const std::vector<Eigen::Matrix2d> noises(plots.size(), 25.0 * Eigen::Matrix2d::Identity());
      const ExtendedScanReport report = tracker.process(10.0 * scan, plots, noises);
      ASSERT_FALSE(report.skipped);
      if (scan == 0) {
        EXPECT_EQ(report.partitions, 2);  // the gap splits it (the premise)
      }
      for (const ExtendedTrack& track : tracker.tracks()) {
        if (track.status == ExtendedTrackStatus::kConfirmed) confirmed.insert(track.id);
      }
    }
    // THEN one number over the run, and its track ends within 30 m of the hull's centre
    ASSERT_EQ(confirmed.size(), 1u);
    ASSERT_EQ(tracker.tracks().size(), 1u);
    EXPECT_LT((tracker.tracks().front().position() - Eigen::Vector2d(700.0, 0.0)).norm(), 30.0);
  }
}

}  // namespace
}  // namespace skytrack::extended
