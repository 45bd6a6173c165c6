// A shared partition's split against one object being all of it (split_log_ratio,
// ExtendedSpec::one_object_split_test): by hand, kept for two objects' plots, refused for one
// object's plots that a coasting neighbour's prediction reached. And the split against its
// exchange (exchange_log_ratio): by hand, and a coasting track's labelling put right.
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "skytrack/extended/ellipse_geometry.hpp"
#include "skytrack/extended/extended_existence.hpp"

namespace skytrack::extended {
namespace {

// Eight plots over a 100 m x 25 m object along x at `centre` (a fixed pattern).
std::vector<Eigen::Vector2d> object_plots(const Eigen::Vector2d& centre) {
  const double pattern[8][2] = {{-70, 5}, {-40, -12}, {-15, 15}, {0, -3},
                                {20, 10}, {45, -15},  {60, 4},   {80, -2}};
  std::vector<Eigen::Vector2d> plots;
  for (const auto& p : pattern) plots.push_back(centre + Eigen::Vector2d(p[0], p[1]));
  return plots;
}

PlotsModel model_at(const Eigen::Vector2d& centre, double centre_sigma) {
  const Eigen::Matrix2d extent = shape_from_axes(100.0, 50.0, 0.0);  // minor floored at 50 m
  return {centre, centre_sigma * centre_sigma * Eigen::Matrix2d::Identity(),
          extent / 4.0 + 25.0 * Eigen::Matrix2d::Identity()};
}

TEST(SplitLogRatio, ByHand) {
  // GIVEN shares of one and two plots and two models, the default P_D 0.95 and gamma 8
  const ExistenceSpec spec;
  const std::vector<Eigen::Vector2d> own{{0.0, 40.0}}, other{{10.0, 0.0}, {-10.0, 5.0}};
  const PlotsModel a = model_at({0.0, 50.0}, 20.0), b = model_at({0.0, 0.0}, 15.0);
  const std::vector<Eigen::Vector2d> all{{0.0, 40.0}, {10.0, 0.0}, {-10.0, 5.0}};
  auto f = [](const std::vector<Eigen::Vector2d>& z, const PlotsModel& m) {
    return object_plots_log_density(z, m.centre, m.centre_cov, m.spread);
  };
  // THEN ln 19 - 8 + f_a(own) + f_b(other) - f_b(all), to 1e-9
  EXPECT_NEAR(split_log_ratio(own, other, a, b, spec),
              std::log(19.0) - 8.0 + f(own, a) + f(other, b) - f(all, b), 1e-9);
  // AND an empty share is no split
  EXPECT_EQ(split_log_ratio({}, other, a, b, spec), -std::numeric_limits<double>::infinity());
}

TEST(SplitLogRatio, TwoObjectsSideBySideKeepTheSplit) {
  // GIVEN two objects 60 m apart across their length, each track predicted on its own with
  // 20 m centre sigma, each object's eight plots its track's share
  const std::vector<Eigen::Vector2d> a = object_plots({0.0, 0.0}), b = object_plots({0.0, 60.0});
  const PlotsModel ma = model_at({0.0, 0.0}, 20.0), mb = model_at({0.0, 60.0}, 20.0);
  // THEN neither track's object is likelier missed: both ratios above +3
  EXPECT_GT(split_log_ratio(a, b, ma, mb, ExistenceSpec{}), 3.0);
  EXPECT_GT(split_log_ratio(b, a, mb, ma, ExistenceSpec{}), 3.0);
}

TEST(SplitLogRatio, OneObjectsPlotsAreNotSplitWithACoastingNeighbour) {
  // GIVEN one object's eight plots at the origin, its track there (20 m sigma), and a
  // neighbour that coasted (100 m sigma) predicted 120 m off across the object, given by the
  // split the three plots on its side
  const std::vector<Eigen::Vector2d> plots = object_plots({0.0, 0.0});
  std::vector<Eigen::Vector2d> near, rest;
  for (const Eigen::Vector2d& z : plots) (z.y() > 4.5 ? near : rest).push_back(z);
  ASSERT_EQ(near.size(), 3u);
  const PlotsModel own = model_at({0.0, 0.0}, 20.0), coasting = model_at({0.0, 120.0}, 100.0);
  // THEN the split is refused with the neighbour's object the missed one: its ratio below -2
  // and below the object's own track's by more than 2 (the tracker drops the lower)
  const double neighbour_missed = split_log_ratio(near, rest, coasting, own, ExistenceSpec{});
  const double own_missed = split_log_ratio(rest, near, own, coasting, ExistenceSpec{});
  EXPECT_LT(neighbour_missed, -2.0);
  EXPECT_LT(neighbour_missed, own_missed - 2.0);
}

TEST(ExchangeLogRatio, ByHand) {
  // GIVEN two shares and two models
  const std::vector<Eigen::Vector2d> own{{0.0, 40.0}}, other{{10.0, 0.0}, {-10.0, 5.0}};
  const PlotsModel a = model_at({0.0, 50.0}, 20.0), b = model_at({0.0, 0.0}, 15.0);
  auto f = [](const std::vector<Eigen::Vector2d>& z, const PlotsModel& m) {
    return object_plots_log_density(z, m.centre, m.centre_cov, m.spread);
  };
  // THEN f_a(other) + f_b(own) - f_a(own) - f_b(other), to 1e-9, and its negative exchanged
  const double r = exchange_log_ratio(own, other, a, b);
  EXPECT_NEAR(r, f(other, a) + f(own, b) - f(own, a) - f(other, b), 1e-9);
  EXPECT_NEAR(exchange_log_ratio(other, own, b, a), r, 1e-9);
  EXPECT_LT(r, 0.0);  // each share lies at its own model
  EXPECT_EQ(exchange_log_ratio({}, other, a, b), -std::numeric_limits<double>::infinity());
}

TEST(ExchangeLogRatio, ATrackThatCoastedBehindItsObjectGetsItsObjectsPlots) {
  // GIVEN two objects crossing at right angles, A along x at (100, 0) and B along y at
  // (0, 100) (crossing seed 256 at 140 s), B's track predicted beside B (30 m sigma) and A's,
  // which coasted through a missed scan at too low a speed, 160 m behind A (150 m sigma)
  const double pattern[8][2] = {{-70, 5}, {-40, -12}, {-15, 15}, {0, -3},
                                {20, 10}, {45, -15},  {60, 4},   {80, -2}};
  std::vector<Eigen::Vector2d> a_plots, b_plots;
  for (const auto& p : pattern) {
    a_plots.emplace_back(100.0 + p[0], p[1]);
    b_plots.emplace_back(p[1], 100.0 + p[0]);
  }
  const Eigen::Matrix2d noise = 25.0 * Eigen::Matrix2d::Identity();
  const PlotsModel b_track{{27.0, 93.0},
                           900.0 * Eigen::Matrix2d::Identity(),
                           shape_from_axes(100.0, 50.0, std::numbers::pi / 2.0) / 4.0 + noise};
  const PlotsModel a_track{{-59.0, 20.0},
                           22500.0 * Eigen::Matrix2d::Identity(),
                           shape_from_axes(100.0, 50.0, 0.0) / 4.0 + noise};
  // WHEN the split from the shapes alone gave B's track A's plots and A's track B's
  const double r = exchange_log_ratio(a_plots, b_plots, b_track, a_track);
  // THEN the exchange, each track with its own object, is the likelier by more than 10
  EXPECT_GT(r, 10.0);
}

}  // namespace
}  // namespace skytrack::extended
