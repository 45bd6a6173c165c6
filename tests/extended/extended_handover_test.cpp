// A turn's first scan splitting a ship's plots between its track and a new one: the next
// scan's plots all fall to the new track, and the ship keeps its number (the handover). Not
// SMF-EOT: its inner-bound extent collapses on the split's two plots and tells no length.
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "skytrack/extended/extended_tracker.hpp"

namespace skytrack::extended {
namespace {

constexpr double kScan = 10.0;   // [s]
constexpr double kSpeed = 14.0;  // [m/s]

// Five plots along a 340 m x 80 m hull centred at `centre`, its major axis along `axis`.
void hull_plots(const Eigen::Vector2d& centre, const Eigen::Vector2d& axis,
                std::vector<Eigen::Vector2d>& out) {
  const Eigen::Vector2d across(-axis.y(), axis.x());
  const double along[] = {-120.0, -60.0, 0.0, 60.0, 120.0};
  const double side[] = {15.0, -20.0, 10.0, -15.0, 20.0};
  for (int i = 0; i < 5; ++i) out.push_back(centre + along[i] * axis + side[i] * across);
}

// The confirmed track numbers near the ship (within 150 m) in each scan.
std::vector<std::vector<std::uint64_t>> run_split(EstimatorKind kind) {
  ExtendedSpec spec;
  spec.kind = kind;
  ExtendedTracker tracker(spec);
  const Eigen::Vector2d east(1.0, 0.0), north(0.0, 1.0);
  std::vector<std::vector<std::uint64_t>> near;
  Eigen::Vector2d centre(0.0, 0.0);
  for (int k = 0; k < 10; ++k) {
    std::vector<Eigen::Vector2d> plots;
    if (k < 6) {  // east, straight
      centre = Eigen::Vector2d(kSpeed * kScan * k, 0.0);
      hull_plots(centre, east, plots);
    } else if (k == 6) {  // turned north: two plots where the track expects the hull, three
                          // 220 m north of them, beyond its gate
      const Eigen::Vector2d stern(kSpeed * kScan * 6 - 20.0, 0.0);
      plots = {stern + Eigen::Vector2d(0.0, 10.0), stern + Eigen::Vector2d(15.0, -10.0)};
      for (double y : {190.0, 220.0, 250.0}) plots.push_back(stern + Eigen::Vector2d(5.0, y));
      centre = stern + Eigen::Vector2d(5.0, 220.0);
    } else {  // north
      centre += kSpeed * kScan * north;
      hull_plots(centre, north, plots);
    }
    const std::vector<Eigen::Matrix2d> noises(plots.size(), 25.0 * Eigen::Matrix2d::Identity());
    tracker.process(kScan * k, plots, noises);
    near.emplace_back();
    for (const ExtendedTrack& track : tracker.tracks()) {
      if (track.status == ExtendedTrackStatus::kConfirmed &&
          (track.position() - centre).norm() < 150.0) {
        near.back().push_back(track.id);
      }
    }
  }
  return near;
}

class ExtendedHandover : public ::testing::TestWithParam<EstimatorKind> {};

TEST_P(ExtendedHandover, ASplitTurnKeepsTheShipsNumber) {
  const std::vector<std::vector<std::uint64_t>> near = run_split(GetParam());
  // GIVEN the ship's track confirmed before the turn
  ASSERT_EQ(near[5].size(), 1u);
  const std::uint64_t number = near[5].front();
  // THEN after the split scan the ship is tracked under that number alone
  for (int k = 8; k < 10; ++k) {
    ASSERT_EQ(near[k].size(), 1u) << "scan " << k;
    EXPECT_EQ(near[k].front(), number) << "scan " << k;
  }
}

INSTANTIATE_TEST_SUITE_P(AllEstimators, ExtendedHandover,
                         ::testing::Values(EstimatorKind::kRandomMatrix, EstimatorKind::kMemEkf));

}  // namespace
}  // namespace skytrack::extended
