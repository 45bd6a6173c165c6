// ExtendedTracker: several objects in clutter, crossing objects, partitions from the caller,
// track numbers, deletion and bad input.
#include "skytrack/extended/extended_tracker.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "skytrack/extended/distance_partitioner.hpp"
#include "skytrack/extended/ellipse_geometry.hpp"

namespace skytrack::extended {
namespace {

struct Object {
  Eigen::Vector2d start, velocity;
  double major, minor;
};

// n plots uniform over the object's ellipse (major axis along its velocity) plus N(0, 25).
void object_plots(const Object& o, double t, int n, std::mt19937_64& rng,
                  std::vector<Eigen::Vector2d>& out) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 5.0);
  const double heading = std::atan2(o.velocity.y(), o.velocity.x());
  const double c = std::cos(heading), s = std::sin(heading);
  for (int i = 0; i < n; ++i) {
    const double r = std::sqrt(u(rng)), phi = 2.0 * std::numbers::pi * u(rng);
    const double a = o.major * r * std::cos(phi), b = o.minor * r * std::sin(phi);
    // Each draw is its own step, last argument first: the order GCC used when the scenes were
    // measured (C++ leaves the evaluation order of arguments unspecified).
    const double noise_y = noise(rng), noise_x = noise(rng);
    out.emplace_back(o.start + t * o.velocity + Eigen::Vector2d(c * a - s * b, s * a + c * b) +
                     Eigen::Vector2d(noise_x, noise_y));
  }
}

// Two objects crossing at the origin at t = 100 s, a third apart, 10 clutter plots a scan.
std::vector<std::vector<std::uint64_t>> run_crossing(EstimatorKind kind,
                                                     std::vector<ExtendedTrack>* last = nullptr) {
  const Object objects[] = {{{-1500.0, 0.0}, {15.0, 0.0}, 80.0, 20.0},
                            {{0.0, -1500.0}, {0.0, 15.0}, 80.0, 20.0},
                            {{1500.0, 1500.0}, {-5.0, 0.0}, 40.0, 15.0}};
  ExtendedSpec spec;
  spec.kind = kind;
  ExtendedTracker tracker(spec);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-2500.0, 2500.0);
  std::vector<Eigen::Vector2d> plots;
  std::vector<std::vector<std::uint64_t>> numbers(3);  // per object, the confirmed track on it
  for (int k = 0; k <= 20; ++k) {
    const double t = 10.0 * k;
    plots.clear();
    for (const Object& o : objects) object_plots(o, t, 10, rng, plots);
    for (int c = 0; c < 10; ++c) {
      const double y = u(rng), x = u(rng);
      plots.emplace_back(x, y);
    }
    const std::vector<Eigen::Matrix2d> noises(plots.size(), Eigen::Matrix2d::Identity() * 25.0);
    const ExtendedScanReport report = tracker.process(t, plots, noises);
    EXPECT_FALSE(report.skipped);
    // While they overlap (70 to 130 s) either track is near either object: not scored; after
    // the crossing each object must carry the number it had before.
    if (t > 70.0 && t < 130.0) continue;
    for (int o = 0; o < 3; ++o) {
      const Eigen::Vector2d truth = objects[o].start + t * objects[o].velocity;
      for (const ExtendedTrack& track : tracker.tracks()) {
        if (track.status == ExtendedTrackStatus::kConfirmed &&
            (track.position() - truth).norm() < 60.0 &&
            (numbers[o].empty() || numbers[o].back() != track.id)) {
          numbers[o].push_back(track.id);
        }
      }
    }
  }
  if (last) last->assign(tracker.tracks().begin(), tracker.tracks().end());
  return numbers;
}

TEST(ExtendedTracker, CrossingObjectsInClutterKeepOneNumberEach) {
  for (EstimatorKind kind :
       {EstimatorKind::kSmf, EstimatorKind::kRandomMatrix, EstimatorKind::kMemEkf}) {
    SCOPED_TRACE(static_cast<int>(kind));
    std::vector<ExtendedTrack> tracks;
    const auto numbers = run_crossing(kind, &tracks);
    std::set<std::uint64_t> distinct;
    for (const auto& on_object : numbers) {
      ASSERT_EQ(on_object.size(), 1u);  // tracked, and never under another number
      distinct.insert(on_object.front());
    }
    EXPECT_EQ(distinct.size(), 3u);
    int confirmed = 0;
    for (const ExtendedTrack& track : tracks) {
      confirmed += track.status == ExtendedTrackStatus::kConfirmed;
    }
    EXPECT_EQ(confirmed, 3);  // no confirmed clutter track at the end
  }
}

TEST(ExtendedTracker, SameInputSameTracks) {
  std::vector<ExtendedTrack> a, b;
  run_crossing(EstimatorKind::kSmf, &a);
  run_crossing(EstimatorKind::kSmf, &b);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].id, b[i].id);
    EXPECT_EQ(a[i].object.x, b[i].object.x);
    EXPECT_EQ(a[i].object.extent, b[i].object.extent);
  }
}

TEST(ExtendedTracker, ConfirmsAfterThreeScansAndDeletesAfterThreeMissesWithoutExistence) {
  ExtendedSpec spec;               // confirm_hits 3, delete_misses 3
  spec.existence.enabled = false;  // (with it: extended_track_life_test.cpp)
  ExtendedTracker tracker(spec);
  std::mt19937_64 rng(3);
  const Object o{{0.0, 0.0}, {10.0, 0.0}, 50.0, 20.0};
  std::vector<Eigen::Vector2d> plots;
  for (int k = 0; k < 3; ++k) {
    plots.clear();
    object_plots(o, 10.0 * k, 8, rng, plots);
    const std::vector<Eigen::Matrix2d> noises(plots.size(), Eigen::Matrix2d::Identity() * 25.0);
    tracker.process(10.0 * k, plots, noises);
    ASSERT_EQ(tracker.tracks().size(), 1u);
    EXPECT_EQ(tracker.tracks()[0].status,
              k < 2 ? ExtendedTrackStatus::kTentative : ExtendedTrackStatus::kConfirmed);
  }
  const std::uint64_t id = tracker.tracks()[0].id;
  for (int k = 3; k < 6; ++k) {
    const ExtendedScanReport report = tracker.process(10.0 * k, std::span<const Eigen::Vector2d>{},
                                                      std::span<const Eigen::Matrix2d>{});
    EXPECT_EQ(report.deleted, k == 5 ? 1 : 0);
  }
  EXPECT_TRUE(tracker.tracks().empty());
  ASSERT_EQ(tracker.deleted().size(), 1u);
  EXPECT_EQ(tracker.deleted()[0], id);
}

TEST(ExtendedTracker, UsesTheCallersPartitions) {
  // GIVEN two plots 500 m apart that the caller says are one partition
  ExtendedTracker tracker(ExtendedSpec{});
  const std::vector<Eigen::Vector2d> plots = {{0.0, 0.0}, {500.0, 0.0}};
  const std::vector<Eigen::Matrix2d> noises(2, Eigen::Matrix2d::Identity() * 25.0);
  const std::vector<std::vector<int>> partitions = {{0, 1, 7}};  // 7: out of range, ignored
  const ExtendedScanReport report = tracker.process(0.0, plots, noises, partitions);
  EXPECT_EQ(report.partitions, 1);
  ASSERT_EQ(tracker.tracks().size(), 1u);
  EXPECT_NEAR(tracker.tracks()[0].position().x(), 250.0, 1e-9);
  // WHEN the distance partitioning decides instead: two singletons, too small to start tracks
  ExtendedTracker other(ExtendedSpec{});
  EXPECT_EQ(other.process(0.0, plots, noises).partitions, 2);
  EXPECT_TRUE(other.tracks().empty());
}

TEST(ExtendedTracker, BadInputIsCountedNotFatal) {
  ExtendedTracker tracker(ExtendedSpec{});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Eigen::Vector2d> plots = {{0.0, 0.0}, {nan, 1.0}, {10.0, 5.0}, {20.0, 0.0}};
  std::vector<Eigen::Matrix2d> noises(4, Eigen::Matrix2d::Identity() * 25.0);
  noises[3](0, 0) = -1.0;
  const ExtendedScanReport report = tracker.process(5.0, plots, noises);
  EXPECT_EQ(report.rejected_plots, 2);
  EXPECT_EQ(report.plots, 2);
  ASSERT_EQ(tracker.tracks().size(), 1u);  // from the two good plots
  EXPECT_TRUE(tracker.tracks()[0].object.x.allFinite());
  // An earlier scan, a non-finite time and mismatched sizes are skipped.
  EXPECT_TRUE(tracker.process(4.0, plots, noises).skipped);
  EXPECT_TRUE(tracker.process(nan, plots, noises).skipped);
  EXPECT_TRUE(tracker.process(6.0, plots, std::span(noises).first(2)).skipped);
}

TEST(ExtendedTracker, TakesPlotMeasurementsInTheTrackingFrame) {
  // GIVEN polar plots from a sensor at the origin heading north: range 1000 m, azimuth 90
  // degrees (clockwise from north) is x = 1000, y = 0.
  std::vector<PlotMeasurement> plots(3);
  MeasVec sigma(2);
  sigma << 5.0, 0.001;
  PlatformState platform;
  for (int i = 0; i < 3; ++i) {
    plots[i].model = MeasurementModel::polar(platform, false, false, 2, sigma);
    plots[i].z = MeasVec(2);
    plots[i].z << 1000.0 + 10.0 * i, std::numbers::pi / 2.0 + 0.01 * (i - 1);
  }
  ExtendedTracker tracker(ExtendedSpec{});
  tracker.process(0.0, plots);
  ASSERT_EQ(tracker.tracks().size(), 1u);
  EXPECT_NEAR(tracker.tracks()[0].position().x(), 1010.0, 0.1);
  EXPECT_NEAR(tracker.tracks()[0].position().y(), 0.0, 0.1);
}

TEST(DistancePartitioner, ChainsNeighboursAndOrdersGroupsByFirstPlot) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Eigen::Vector2d> plots = {{1000.0, 0.0}, {0.0, 0.0}, {90.0, 0.0},
                                              {180.0, 0.0},  {nan, 0.0}, {1050.0, 0.0}};
  DistancePartitioner partitioner;
  std::vector<std::vector<int>> groups;
  partitioner.partition(plots, 100.0, groups);
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_EQ(groups[0], (std::vector<int>{0, 5}));
  EXPECT_EQ(groups[1], (std::vector<int>{1, 2, 3}));  // 0-90-180: one chain
}

}  // namespace
}  // namespace skytrack::extended
