// The contract every estimator mode behind the Pipeline keeps, whatever it estimates: an empty
// batch gives a frame, bad plots are dropped and counted, an out-of-order batch changes
// nothing, the same input gives the same output, and no input throws. A new mode joins by
// adding its profile to kModes.
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "../tracking/tracker_test_support.hpp"

namespace skytrack {
namespace {

struct PointBranching {
  static config::TrackingProfile profile() { return testing::test_profile(); }
};
struct PointPlainJpda {
  static config::TrackingProfile profile() {
    config::TrackingProfile p = testing::test_profile();
    p.point.branching.enabled = false;
    return p;
  }
};
struct PointGnn {
  static config::TrackingProfile profile() {
    config::TrackingProfile p = testing::test_profile();
    p.association.method = config::AssociationMethod::kGnn;
    return p;
  }
};
/// One straight-flight model, births from plot pairs (the stream's targets fly any way).
struct Bernoulli {
  static config::TrackingProfile profile() {
    config::TrackingProfile p = testing::test_profile();
    p.mode = config::TrackingMode::kBernoulli;
    p.dimension = 2;
    p.motion_models = {{.name = "cv", .accel_sigma = 2.0}};
    p.mode_transition = {{1.0}};
    p.initial_mode_probabilities = {1.0};
    p.bernoulli.model_count = 1;
    p.bernoulli.models[0] = {.turn_rate = 0.0, .accel_sigma = 2.0, .particles = 500};
    p.bernoulli.transition[0][0] = 1.0;
    p.bernoulli.birth_model_probabilities[0] = 1.0;
    p.bernoulli.birth_proposal = bernoulli::BirthProposal::kPlotPairs;
    return p;
  }
};
/// Groups on straight courses. The stream's targets are single plots kilometres apart: a
/// kernel bandwidth of kilometres keeps each as a cell of its own.
struct Group {
  static config::TrackingProfile profile() {
    config::TrackingProfile p = testing::test_profile();
    p.mode = config::TrackingMode::kGroup;
    p.dimension = 2;
    p.clutter_rejection.enabled = true;
    p.clutter_rejection.kernel_bandwidth = 2000.0;
    p.clutter_rejection.mean_shift.bandwidth = 500.0;
    p.group.motion = group::GroupMotion::kConstantVelocity;
    p.group.surveillance_area = 6.4e9;
    p.group.position_width = 100.0;
    p.group.birth_speed = 300.0;
    p.group.velocity_width = 50.0;
    return p;
  }
};
/// Extended objects: the stream's targets are one plot each, so one plot makes a partition.
struct Extended {
  static config::TrackingProfile profile() {
    config::TrackingProfile p = testing::test_profile();
    p.mode = config::TrackingMode::kExtended;
    p.dimension = 2;
    p.extended.min_partition_plots = 1;
    return p;
  }
};
using kModes =
    ::testing::Types<PointBranching, PointPlainJpda, PointGnn, Bernoulli, Group, Extended>;

using testing::cartesian;

/// Three targets and a little clutter, seen every 4 s.
std::vector<PlotScan> stream(int batches, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, 10.0);
  std::uniform_real_distribution<double> anywhere(-40e3, 40e3);
  std::vector<PlotScan> out;
  for (int k = 0; k < batches; ++k) {
    PlotScan scan;
    scan.sensor = 1;
    scan.scan = static_cast<std::uint64_t>(k);
    scan.time = 4.0 * k;
    scan.sigma.x = 10.0;
    scan.sigma.y = 10.0;
    const double t = scan.time;
    std::int64_t id = 0;
    // Each draw is its own step, last argument first: the order GCC used when the scenes were
    // measured (C++ leaves the evaluation order of arguments unspecified).
    const double noise_y0 = noise(rng), noise_x0 = noise(rng);
    scan.plots.push_back(cartesian(id++, 10e3 + 200.0 * t + noise_x0, 5e3 + noise_y0));
    const double noise_y1 = noise(rng), noise_x1 = noise(rng);
    scan.plots.push_back(cartesian(id++, -8e3 + noise_x1, 20e3 - 150.0 * t + noise_y1));
    scan.plots.push_back(cartesian(id++, 3e3 + 100.0 * t + noise(rng), -15e3 + 100.0 * t));
    for (int c = 0; c < 3; ++c) {
      const double y = anywhere(rng), x = anywhere(rng);
      scan.plots.push_back(cartesian(id++, x, y));
    }
    out.push_back(std::move(scan));
  }
  return out;
}

template <typename Mode>
class EstimatorContract : public ::testing::Test {
 protected:
  Pipeline make() {
    auto pipeline = Pipeline::create(Mode::profile());
    EXPECT_TRUE(pipeline) << (pipeline ? "" : pipeline.error().message);
    return std::move(*pipeline);
  }
};
TYPED_TEST_SUITE(EstimatorContract, kModes);

TYPED_TEST(EstimatorContract, AnEmptyBatchGivesAFrameAtItsTime) {
  Pipeline pipeline = this->make();
  PlotScan empty;
  empty.sensor = 3;
  empty.scan = 9;
  empty.time = 36.0;
  const ScanResult& r = pipeline.process(empty);
  EXPECT_TRUE(r.accepted);
  EXPECT_EQ(r.frame.sensor, 3u);
  EXPECT_EQ(r.frame.scan, 9u);
  EXPECT_EQ(r.frame.time, 36.0);
  EXPECT_TRUE(r.frame.tracks.empty());
}

TYPED_TEST(EstimatorContract, BadPlotsAreDroppedAndCountedAndChangeNothing) {
  Pipeline clean = this->make(), dirty = this->make();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (PlotScan scan : stream(15, 7)) {
    const TrackFrame expected = clean.process(scan).frame;
    scan.plots.push_back(cartesian(100, nan, 0.0));
    scan.plots.push_back(cartesian(101, 0.0, std::numeric_limits<double>::infinity()));
    const ScanResult& r = dirty.process(scan);
    ASSERT_TRUE(r.accepted);
    EXPECT_EQ(r.frame.tracks, expected.tracks);
    EXPECT_EQ(r.report.plots_invalid, 2);
  }
  EXPECT_EQ(dirty.counters().plots_invalid, 30u);
}

TYPED_TEST(EstimatorContract, AnOutOfOrderBatchIsRefusedAndChangesNothing) {
  Pipeline clean = this->make(), tested = this->make();
  const auto batches = stream(15, 8);
  for (std::size_t k = 0; k < batches.size(); ++k) {
    const TrackFrame expected = clean.process(batches[k]).frame;
    EXPECT_EQ(tested.process(batches[k]).frame.tracks, expected.tracks);
    if (k >= 2) {
      EXPECT_FALSE(tested.process(batches[k - 2]).accepted);
    }
  }
  EXPECT_FALSE(clean.process(batches.back()).frame.tracks.empty());
}

TYPED_TEST(EstimatorContract, TheSameInputGivesTheSameOutput) {
  Pipeline a = this->make(), b = this->make();
  for (const PlotScan& scan : stream(20, 9)) {
    const TrackFrame first = a.process(scan).frame;
    EXPECT_EQ(b.process(scan).frame, first);
  }
}

TYPED_TEST(EstimatorContract, NoInputThrows) {
  // Seeded garbage: extreme and non-finite values in every field, duplicate ids, empty and
  // crowded batches, both plot forms, times that jump about.
  Pipeline pipeline = this->make();
  std::mt19937_64 rng(11);
  const double specials[] = {0.0,
                             -0.0,
                             1e-300,
                             -1e-300,
                             1e300,
                             -1e300,
                             std::numeric_limits<double>::quiet_NaN(),
                             std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::infinity()};
  std::uniform_int_distribution<int> pick(0, 11);
  std::uniform_real_distribution<double> ordinary(-5e4, 5e4);
  const auto value = [&] {
    const int i = pick(rng);
    return i < 9 ? specials[i] : ordinary(rng);
  };
  for (int k = 0; k < 300; ++k) {
    PlotScan scan;
    scan.sensor = static_cast<std::uint32_t>(pick(rng) % 3);
    scan.scan = static_cast<std::uint64_t>(k - pick(rng));
    scan.time = pick(rng) < 10 ? 4.0 * k : value();
    if (pick(rng) == 0) scan.platform.position.x() = value();
    const int n = pick(rng) * pick(rng);
    for (int i = 0; i < n; ++i) {
      const double y = value(), x = value();
      Plot p = cartesian(i % 5, x, y);
      if (pick(rng) < 6) {
        p.form = PlotForm::kPolar;
        p.range = value();
        p.azimuth = value();
        if (pick(rng) < 3) p.elevation = value();
        if (pick(rng) < 3) p.range_rate = value();
      }
      if (pick(rng) == 0) p.time = value();
      if (pick(rng) == 0) p.sigma.x = value();
      if (pick(rng) == 0) p.sigma.range = value();
      scan.plots.push_back(p);
    }
    EXPECT_NO_THROW(pipeline.process(scan));
  }
}

}  // namespace
}  // namespace skytrack
