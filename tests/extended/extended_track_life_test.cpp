// ExtendedTracker's deletion of a confirmed track by its existence probability
// (ExtendedSpec::existence): a well-seen object coasts through a fade, a track of plot pairs
// (clutter) goes sooner.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "skytrack/extended/extended_tracker.hpp"

namespace skytrack::extended {
namespace {

// A 50 m x 20 m object from the origin east at 10 m/s, 8 plots a scan uniform over it plus
// N(0, 25 m^2), except in scans [unseen_from, unseen_to): none. Returns the numbers of the
// confirmed tracks within 100 m of it, scan by scan after the first three.
std::vector<std::uint64_t> run_unseen(const ExtendedSpec& spec, int scans, int unseen_from,
                                      int unseen_to) {
  ExtendedTracker tracker(spec);
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 5.0);
  std::vector<std::uint64_t> numbers;
  std::vector<Eigen::Vector2d> plots;
  for (int k = 0; k < scans; ++k) {
    const double t = 10.0 * k;
    const Eigen::Vector2d centre(10.0 * t, 0.0);
    plots.clear();
    for (int i = 0; i < 8 && (k < unseen_from || k >= unseen_to); ++i) {
      const double r = std::sqrt(u(rng)), phi = 2.0 * std::numbers::pi * u(rng);
      // Each draw is its own step, last argument first: the order GCC used when the scenes were
      // measured (C++ leaves the evaluation order of arguments unspecified).
      const double noise_y = noise(rng), noise_x = noise(rng);
      plots.push_back(centre + Eigen::Vector2d(50.0 * r * std::cos(phi) + noise_x,
                                               20.0 * r * std::sin(phi) + noise_y));
    }
    const std::vector<Eigen::Matrix2d> noises(plots.size(), Eigen::Matrix2d::Identity() * 25.0);
    EXPECT_FALSE(tracker.process(t, plots, noises).skipped);
    if (k < 3 || (k >= unseen_from && k < unseen_to)) continue;
    for (const ExtendedTrack& track : tracker.tracks()) {
      if (track.status == ExtendedTrackStatus::kConfirmed &&
          (track.position() - centre).norm() < 100.0) {
        numbers.push_back(track.id);
      }
    }
  }
  return numbers;
}

TEST(ExtendedTrackLife, WellSeenTrackCoastsThroughThreeScansUnseen) {
  // GIVEN the default existence and an object seen 12 scans, 8 plots each
  const ExtendedSpec spec;
  // WHEN it is unseen for 3 scans, then seen again on its path
  const std::vector<std::uint64_t> numbers = run_unseen(spec, 20, 12, 15);
  // THEN one track within 100 m of it, one number, before and after
  ASSERT_EQ(numbers.size(), 9u + 5u);
  for (std::uint64_t id : numbers) EXPECT_EQ(id, numbers.front());
}

TEST(ExtendedTrackLife, ObjectUnseenFourScansIsRenumbered) {
  // GIVEN the same object WHEN it is unseen for 4 scans THEN its track is deleted and the
  // object is confirmed again under a new number
  const std::vector<std::uint64_t> numbers = run_unseen(ExtendedSpec{}, 20, 12, 16);
  ASSERT_FALSE(numbers.empty());
  EXPECT_NE(numbers.front(), numbers.back());
}

TEST(ExtendedTrackLife, WithoutExistenceDeletesAfterDeleteMisses) {
  // GIVEN existence off (delete_misses 3) WHEN the object is unseen for 3 scans THEN the
  // track is deleted and the object renumbered
  ExtendedSpec spec;
  spec.existence.enabled = false;
  const std::vector<std::uint64_t> numbers = run_unseen(spec, 20, 12, 15);
  ASSERT_FALSE(numbers.empty());
  EXPECT_NE(numbers.front(), numbers.back());
}

TEST(ExtendedTrackLife, PlotPairsAreNotConfirmedAsAnObject) {
  // GIVEN a pair of plots 20 m apart at the same place in six scans (clutter), in a young
  // track's gate of some 10^6 m^2 where clutter of 1e-6 / m^2 gives about as many
  auto confirmed_after = [](const ExtendedSpec& spec) {
    ExtendedTracker tracker(spec);
    const std::vector<Eigen::Vector2d> pair = {{0.0, 0.0}, {20.0, 0.0}};
    const std::vector<Eigen::Matrix2d> noises(2, Eigen::Matrix2d::Identity() * 25.0);
    for (int k = 0; k < 6; ++k) {
      tracker.process(10.0 * k, pair, noises);
      for (const ExtendedTrack& track : tracker.tracks()) {
        if (track.status == ExtendedTrackStatus::kConfirmed) return k + 1;
      }
    }
    return 0;
  };
  // WHEN tracked with existence THEN never confirmed; without it, at the third scan
  EXPECT_EQ(confirmed_after(ExtendedSpec{}), 0);
  ExtendedSpec counts;
  counts.existence.enabled = false;
  EXPECT_EQ(confirmed_after(counts), 3);
}

TEST(ExtendedTrackLife, AConfirmedTrackSurvivesItsNextMissedScan) {
  // GIVEN objects seen with few plots (2 to 4 a scan over 50 m x 20 m), whose existence
  // climbs slowly, in 40 runs
  int confirmed_runs = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    ExtendedTracker tracker{ExtendedSpec{}};
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::uniform_int_distribution<int> count(2, 4);
    std::normal_distribution<double> noise(0.0, 5.0);
    std::vector<Eigen::Vector2d> plots;
    std::uint64_t confirmed = 0;
    double t = 0.0;
    for (int k = 0; k < 12 && confirmed == 0; ++k, t += 10.0) {
      plots.clear();
      for (int i = count(rng); i > 0; --i) {
        const double r = std::sqrt(u(rng)), phi = 2.0 * std::numbers::pi * u(rng);
        const double noise_y = noise(rng), noise_x = noise(rng);
        plots.push_back(Eigen::Vector2d(10.0 * t + 50.0 * r * std::cos(phi) + noise_x,
                                        20.0 * r * std::sin(phi) + noise_y));
      }
      const std::vector<Eigen::Matrix2d> noises(plots.size(), Eigen::Matrix2d::Identity() * 25.0);
      tracker.process(t, plots, noises);
      for (const ExtendedTrack& track : tracker.tracks()) {
        if (track.status == ExtendedTrackStatus::kConfirmed) confirmed = track.id;
      }
    }
    if (confirmed == 0) continue;
    ++confirmed_runs;
    // WHEN the scan after its confirmation misses the object
    tracker.process(t, std::vector<Eigen::Vector2d>{}, std::vector<Eigen::Matrix2d>{});
    // THEN its track is still there: a track is numbered only once a miss would not delete it
    const auto tracks = tracker.tracks();
    EXPECT_TRUE(std::any_of(tracks.begin(), tracks.end(),
                            [&](const ExtendedTrack& x) { return x.id == confirmed; }))
        << "seed " << seed;
  }
  EXPECT_GE(confirmed_runs, 30);
}

}  // namespace
}  // namespace skytrack::extended
