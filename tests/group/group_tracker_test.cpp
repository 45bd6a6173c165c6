// Labeled box-particle PHD group tracking (paper 000 §3.2) through GroupTracker: births with
// a one-scan delay, stable labels, state / extent / member estimates, the double and single
// label rules through missed detections (§3.2.7), death after chi missed scans, merging,
// determinism and bad input.
#include "skytrack/group/group_tracker.hpp"

#include <cmath>
#include <random>
#include <set>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

namespace skytrack::group {
namespace {

struct Truth {
  Eigen::Vector2d position;
  Eigen::Vector2d velocity;
};

// Plots of one scan: 15 per group, uniform within +-10 m of the centroid (variance 100/3 m^2
// per axis), no sensor noise; groups listed in `hidden` return nothing.
std::vector<Eigen::Vector3d> scan_plots(const std::vector<Truth>& groups, double t,
                                        std::mt19937_64& rng, const std::set<int>& hidden = {}) {
  std::uniform_real_distribution<double> spread(-10.0, 10.0);
  std::vector<Eigen::Vector3d> plots;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    if (hidden.count(static_cast<int>(g)) != 0) {
      continue;
    }
    const Eigen::Vector2d c = groups[g].position + t * groups[g].velocity;
    for (int i = 0; i < 15; ++i) {
      // Each draw is its own step, last argument first: the order GCC used when the scenes were
      // measured (C++ leaves the evaluation order of arguments unspecified).
      const double dy = spread(rng), dx = spread(rng);
      plots.emplace_back(c.x() + dx, c.y() + dy, 0.0);
    }
  }
  return plots;
}

GroupSpec cv_spec() {
  GroupSpec spec;
  spec.motion = GroupMotion::kConstantVelocity;
  spec.measurement_sigma = 0.0;  // the test plots have no sensor noise
  return spec;
}

std::vector<GroupEstimate> detected(const std::vector<GroupEstimate>& all) {
  std::vector<GroupEstimate> out;
  for (const auto& e : all) {
    if (e.missed_scans == 0) {
      out.push_back(e);
    }
  }
  return out;
}

TEST(GroupTracker, OneGroupBornAfterOneScanThenStable) {
  const std::vector<Truth> truth = {{{-500, 200}, {30, -20}}};
  GroupTracker tracker(cv_spec());
  std::mt19937_64 rng(3);
  std::uint32_t label = 0;
  for (int k = 0; k < 25; ++k) {
    const double t = k;
    const auto est = detected(tracker.process(t, scan_plots(truth, t, rng)));
    if (k == 0) {
      EXPECT_TRUE(est.empty());  // births come from the previous scan's boxes (§3.2.2)
      continue;
    }
    ASSERT_EQ(est.size(), 1U) << "scan " << k;
    if (label == 0) {
      label = est[0].label;
    }
    EXPECT_EQ(est[0].label, label) << "scan " << k;
    if (k >= 8) {
      const Eigen::Vector2d c = truth[0].position + t * truth[0].velocity;
      EXPECT_LT((est[0].position - c).norm(), 6.0) << "scan " << k;
      EXPECT_LT((est[0].velocity - truth[0].velocity).norm(), 4.0) << "scan " << k;
      // Uniform +-10 m: variance 33.3 m^2 per axis; 15 members, all detected.
      EXPECT_NEAR(est[0].extent(0, 0), 100.0 / 3.0, 12.0);
      EXPECT_NEAR(est[0].extent(1, 1), 100.0 / 3.0, 12.0);
      EXPECT_NEAR(est[0].extent(0, 1), 0.0, 8.0);
      EXPECT_NEAR(est[0].members, 15.0, 3.0);
    }
  }
  EXPECT_NEAR(tracker.filter().group_count(), 1.0, 0.3);  // eq. 28
}

// Two missed scans: the double label keeps the number (l2 counts to 2 <= chi = 3); the
// single label re-initiates the group under a new number.
TEST(GroupTracker, MissedDetectionsDoubleKeepsSingleRestarts) {
  const std::vector<Truth> truth = {{{0, 0}, {35, -35}}, {{600, 0}, {-30, -35}}};
  for (const LabelModel model : {LabelModel::kDouble, LabelModel::kSingle}) {
    GroupSpec spec = cv_spec();
    spec.labels = model;
    GroupTracker tracker(spec);
    std::mt19937_64 rng(11);
    std::set<std::uint32_t> numbers;
    for (int k = 0; k < 20; ++k) {
      const std::set<int> hidden = (k == 8 || k == 9) ? std::set<int>{0} : std::set<int>{};
      const auto& all = tracker.process(k, scan_plots(truth, k, rng, hidden));
      for (const auto& e : detected(all)) {
        numbers.insert(e.label);
      }
      if (k == 9 && model == LabelModel::kDouble) {
        ASSERT_EQ(all.size(), 2U);  // the missed group coasts, reported with l2 = 2
        EXPECT_EQ(all.back().missed_scans, 2);
      }
      if (k == 19) {
        EXPECT_EQ(detected(all).size(), 2U);
      }
    }
    EXPECT_EQ(numbers.size(), model == LabelModel::kDouble ? 2U : 3U);
  }
}

TEST(GroupTracker, DiesAfterMoreThanChiMissedScans) {
  const std::vector<Truth> truth = {{{0, 0}, {20, 0}}};
  GroupTracker tracker(cv_spec());
  std::mt19937_64 rng(5);
  for (int k = 0; k < 6; ++k) {
    tracker.process(k, scan_plots(truth, k, rng));
  }
  ASSERT_EQ(detected(tracker.estimates()).size(), 1U);
  for (int k = 6; k < 9; ++k) {  // l2 = 1, 2, 3: still alive
    tracker.process(k, std::vector<Eigen::Vector3d>{});
    ASSERT_EQ(tracker.estimates().size(), 1U) << "scan " << k;
    EXPECT_EQ(tracker.estimates()[0].missed_scans, k - 5);
  }
  tracker.process(9, std::vector<Eigen::Vector3d>{});  // l2 = 4 > chi = 3: dead
  EXPECT_TRUE(tracker.estimates().empty());
}

// Two groups fly into one: within a few scans one number is reported on the merged group.
TEST(GroupTracker, MergedGroupsReportOneNumber) {
  std::vector<Truth> truth = {{{0, 0}, {20, 0}}, {{0, 200}, {20, 0}}};
  GroupTracker tracker(cv_spec());
  std::mt19937_64 rng(9);
  for (int k = 0; k < 8; ++k) {
    tracker.process(k, scan_plots(truth, k, rng));
  }
  ASSERT_EQ(detected(tracker.estimates()).size(), 2U);
  truth[1] = truth[0];  // group 2 joins group 1
  for (int k = 8; k < 14; ++k) {
    tracker.process(k, scan_plots(truth, k, rng));
    if (k >= 9) {
      EXPECT_EQ(detected(tracker.estimates()).size(), 1U) << "scan " << k;
    }
  }
}

TEST(GroupTracker, DeterministicPerSeed) {
  const std::vector<Truth> truth = {{{0, 0}, {20, 5}}, {{400, 100}, {-10, 20}}};
  std::vector<std::vector<Eigen::Vector3d>> scans;
  std::mt19937_64 rng(21);
  for (int k = 0; k < 15; ++k) {
    scans.push_back(scan_plots(truth, k, rng));
  }
  GroupTracker a(cv_spec()), b(cv_spec());
  for (int k = 0; k < 15; ++k) {
    const auto ea = a.process(k, scans[static_cast<std::size_t>(k)]);
    const auto eb = b.process(k, scans[static_cast<std::size_t>(k)]);
    ASSERT_EQ(ea.size(), eb.size());
    for (std::size_t i = 0; i < ea.size(); ++i) {
      EXPECT_EQ(ea[i].label, eb[i].label);
      EXPECT_EQ(ea[i].position, eb[i].position);  // bit-identical
      EXPECT_EQ(ea[i].velocity, eb[i].velocity);
    }
  }
}

TEST(GroupTracker, BadInputNeitherThrowsNorLeaksNan) {
  GroupTracker tracker(cv_spec());
  std::mt19937_64 rng(1);
  const std::vector<Truth> truth = {{{0, 0}, {10, 0}}};
  for (int k = 0; k < 5; ++k) {
    auto plots = scan_plots(truth, k, rng);
    plots.emplace_back(std::nan(""), 0.0, 0.0);
    plots.emplace_back(INFINITY, 1.0, 0.0);
    tracker.process(k, plots);
  }
  tracker.process(std::nan(""), std::vector<Eigen::Vector3d>{});  // skipped
  tracker.process(2.0, scan_plots(truth, 5, rng));                // time going back: dt = 0
  std::vector<GroupCell> cells(1);
  cells[0].box.lower = Eigen::Vector2d(std::nan(""), 0);
  tracker.process_cells(7.0, cells);
  for (const auto& e : tracker.estimates()) {
    EXPECT_TRUE(e.position.allFinite());
    EXPECT_TRUE(e.velocity.allFinite());
    EXPECT_TRUE(e.extent.allFinite());
  }
  GroupSpec bad = cv_spec();
  bad.boxes_per_group = 0;
  EXPECT_THROW(GroupTracker{bad}, std::invalid_argument);
}

TEST(GroupTracker, TakesPlotMeasurements) {
  GroupTracker tracker(cv_spec());
  std::mt19937_64 rng(4);
  const std::vector<Truth> truth = {{{100, -100}, {10, 10}}};
  MeasVec sigma(2);
  sigma << 2.5, 2.5;
  for (int k = 0; k < 6; ++k) {
    std::vector<PlotMeasurement> plots;
    for (const auto& p : scan_plots(truth, k, rng)) {
      PlotMeasurement m;
      m.model = MeasurementModel::cartesian(2, 2, sigma);
      m.z = p.head<2>();
      m.time = k;
      plots.push_back(m);
    }
    tracker.process(static_cast<double>(k), plots);
  }
  const auto est = detected(tracker.estimates());
  ASSERT_EQ(est.size(), 1U);
  EXPECT_LT((est[0].position - Eigen::Vector2d(150, -50)).norm(), 10.0);
}

}  // namespace
}  // namespace skytrack::group
