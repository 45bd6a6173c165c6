// ExtendedTracker's deletion of a confirmed track whose object goes unseen for a while
// (ExtendedSpec::established_hits, established_delete_misses).
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
      plots.push_back(centre + Eigen::Vector2d(50.0 * r * std::cos(phi) + noise(rng),
                                               20.0 * r * std::sin(phi) + noise(rng)));
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

TEST(ExtendedTrackLife, EstablishedTrackCoastsThroughItsObjectUnseen) {
  // GIVEN a track established over 12 scans, its object then unseen for 4 scans
  ExtendedSpec spec;
  spec.established_hits = 10;
  spec.established_delete_misses = 5;
  // WHEN the object is seen again on its path
  const std::vector<std::uint64_t> numbers = run_unseen(spec, 20, 12, 16);
  // THEN one track, one number, before and after
  ASSERT_EQ(numbers.size(), 9u + 4u);
  for (std::uint64_t id : numbers) EXPECT_EQ(id, numbers.front());
}

TEST(ExtendedTrackLife, DefaultDeletesAfterThreeMissesAndRenumbers) {
  // GIVEN the default (no exception: established_delete_misses = delete_misses = 3)
  const ExtendedSpec spec;
  // WHEN the same object is unseen for 4 scans
  const std::vector<std::uint64_t> numbers = run_unseen(spec, 20, 12, 16);
  // THEN the track is deleted; the object is confirmed again under a new number after
  // confirm_hits scans
  ASSERT_FALSE(numbers.empty());
  EXPECT_NE(numbers.front(), numbers.back());
}

TEST(ExtendedTrackLife, YoungTrackIsDeletedOnTheUsualCount) {
  // GIVEN a track confirmed 5 scans (fewer than established_hits) WHEN its object is unseen
  // for 4 scans THEN it is deleted after 3 and the object comes back under a new number
  ExtendedSpec spec;
  spec.established_hits = 10;
  spec.established_delete_misses = 5;
  const std::vector<std::uint64_t> numbers = run_unseen(spec, 14, 5, 9);
  ASSERT_FALSE(numbers.empty());
  EXPECT_NE(numbers.front(), numbers.back());
}

}  // namespace
}  // namespace skytrack::extended
