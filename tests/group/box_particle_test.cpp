// Box-particle steps of paper 000 §3.2, checked against hand-computed values: interval
// prediction (eq. 14), box likelihood (eq. 19), PHD update (eq. 18, 20, 24), contraction
// (eq. 25-26 with constraint propagation) and systematic resampling.
#include "skytrack/group/box_particle.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

namespace skytrack::group {
namespace {

constexpr double kTol = 1e-12;

BoxParticle box(double x_lo, double x_hi, double vx_lo, double vx_hi, double y_lo, double y_hi,
                double vy_lo, double vy_hi) {
  BoxParticle b;
  b.centre << 0.5 * (x_lo + x_hi), 0.5 * (vx_lo + vx_hi), 0.5 * (y_lo + y_hi),
      0.5 * (vy_lo + vy_hi);
  b.half << 0.5 * (x_hi - x_lo), 0.5 * (vx_hi - vx_lo), 0.5 * (y_hi - y_lo), 0.5 * (vy_hi - vy_lo);
  return b;
}

PlaneBox plane(double x_lo, double x_hi, double y_lo, double y_hi) {
  return PlaneBox{Eigen::Vector2d(x_lo, y_lo), Eigen::Vector2d(x_hi, y_hi)};
}

TEST(GroupTransition, ConstantVelocityAndTurn) {
  const BoxMat cv = group_transition(GroupMotion::kConstantVelocity, 0.3, 2.0);
  EXPECT_DOUBLE_EQ(cv(0, 1), 2.0);
  EXPECT_DOUBLE_EQ(cv(2, 3), 2.0);
  EXPECT_DOUBLE_EQ(cv(1, 3), 0.0);
  // CT, w = 3 deg/s, T = 1 s: x' = x + sin(w)/w vx - (1 - cos w)/w vy.
  const double w = 3.0 * std::numbers::pi / 180.0;
  const BoxMat ct = group_transition(GroupMotion::kCoordinatedTurn, w, 1.0);
  EXPECT_NEAR(ct(0, 1), std::sin(w) / w, kTol);
  EXPECT_NEAR(ct(0, 3), -(1.0 - std::cos(w)) / w, kTol);
  EXPECT_NEAR(ct(3, 1), std::sin(w), kTol);
  EXPECT_NEAR(ct(1, 1), std::cos(w), kTol);
  // Speed is kept by a turn.
  const BoxVec x(0.0, 40.0, 0.0, -40.0);
  EXPECT_NEAR((ct * x)(1) * (ct * x)(1) + (ct * x)(3) * (ct * x)(3), 3200.0, 1e-9);
}

TEST(PredictBox, IntervalHullOfLinearMap) {
  // Eq. 14, CV, T = 2: x in [0, 2], vx in [1, 3] -> x' = x + 2 vx in [2, 8].
  BoxParticle b = box(0, 2, 1, 3, 10, 10, -1, 1);
  predict_box(group_transition(GroupMotion::kConstantVelocity, 0.0, 2.0), b);
  EXPECT_NEAR(b.centre(0) - b.half(0), 2.0, kTol);
  EXPECT_NEAR(b.centre(0) + b.half(0), 8.0, kTol);
  EXPECT_NEAR(b.centre(1) - b.half(1), 1.0, kTol);  // velocity unchanged
  EXPECT_NEAR(b.centre(2) - b.half(2), 8.0, kTol);  // y = 10 + 2 [-1, 1]
  EXPECT_NEAR(b.centre(2) + b.half(2), 12.0, kTol);
}

TEST(BoxLikelihood, OverlapAreaRatio) {
  // Eq. 19: [x] = [0, 4] x [0, 2] (area 8), [z] = [2, 6] x [1, 5]: overlap 2 x 1 = 2.
  const BoxParticle b = box(0, 4, -1, 1, 0, 2, -1, 1);
  EXPECT_NEAR(box_likelihood(b, plane(2, 6, 1, 5)), 0.25, kTol);
  EXPECT_NEAR(box_likelihood(b, plane(-1, 5, -1, 3)), 1.0, kTol);                  // inside [z]
  EXPECT_EQ(box_likelihood(b, plane(5, 6, 0, 2)), 0.0);                            // apart
  EXPECT_EQ(box_likelihood(box(1, 1, 0, 0, 0, 2, 0, 0), plane(0, 4, 0, 4)), 0.0);  // no area
  EXPECT_EQ(plane(0, 2, 0, 3).area(), 6.0);
  EXPECT_EQ(plane(2, 0, 0, 3).area(), 0.0);
}

TEST(PhdUpdate, HandComputedWeights) {
  // A overlaps [z] by half (g = 0.5), w = 0.4; B misses it, w = 0.6. Pd = 0.9,
  // lambda c = 0.1. Eq. 20: D = 0.1 + 0.5 0.9 0.4 = 0.28.
  // Eq. 18: w_A = (0.1 + 0.5 0.9 / 0.28) 0.4, w_B = 0.1 0.6.
  std::vector<BoxParticle> p = {box(0, 2, -1, 1, 0, 2, -1, 1), box(10, 12, -1, 1, 0, 2, -1, 1)};
  p[0].weight = 0.4;
  p[0].slot = 0;
  p[1].weight = 0.6;
  p[1].slot = 1;
  const std::vector<PlaneBox> z = {plane(1, 3, 0, 2)};
  const std::vector<double> clutter = {0.1};
  PhdUpdateResult r;
  phd_update(p, z, clutter, 0.9, 2, r);
  EXPECT_NEAR(r.denominators[0], 0.28, kTol);
  EXPECT_NEAR(p[0].weight, (0.1 + 0.45 / 0.28) * 0.4, kTol);
  EXPECT_NEAR(p[1].weight, 0.06, kTol);
  EXPECT_EQ(r.best_cell[0], 0);
  EXPECT_EQ(r.best_cell[1], -1);
  EXPECT_NEAR(r.shares[0], 0.45 * 0.4 / 0.28, kTol);  // slot 0's share of cell 0 (eq. 24)
  EXPECT_EQ(r.shares[1], 0.0);
}

TEST(PhdUpdate, NonFiniteWeightsAndEmptyCells) {
  std::vector<BoxParticle> p = {box(0, 2, -1, 1, 0, 2, -1, 1)};
  p[0].weight = std::nan("");
  PhdUpdateResult r;
  phd_update(p, {}, {}, 0.9, 0, r);
  EXPECT_EQ(p[0].weight, 0.0);
  EXPECT_EQ(r.best_cell[0], -1);
}

TEST(ContractBox, PositionIntersectedVelocityByConstraintPropagation) {
  // Prior x in [0, 2], vx in [-10, 10]; CV, T = 1: predicted x in [-10, 12]. With [z]_x =
  // [4, 6]: x' = [4, 6] (eq. 26); the constraint x + vx in [4, 6] with x in [0, 2] gives
  // vx in [2, 6]. Same in y with [z]_y = [-3, -1] and prior y in [0, 0]: vy in [-3, -1].
  const BoxParticle prior = box(0, 2, -10, 10, 0, 0, -10, 10);
  BoxParticle b = prior;
  const BoxMat F = group_transition(GroupMotion::kConstantVelocity, 0.0, 1.0);
  predict_box(F, b);
  ASSERT_TRUE(contract_box(F, prior.centre, prior.half, plane(4, 6, -3, -1), b));
  EXPECT_NEAR(b.centre(0) - b.half(0), 4.0, kTol);
  EXPECT_NEAR(b.centre(0) + b.half(0), 6.0, kTol);
  EXPECT_NEAR(b.centre(1) - b.half(1), 2.0, kTol);
  EXPECT_NEAR(b.centre(1) + b.half(1), 6.0, kTol);
  EXPECT_NEAR(b.centre(3) - b.half(3), -3.0, kTol);
  EXPECT_NEAR(b.centre(3) + b.half(3), -1.0, kTol);
  // No overlap: unchanged.
  BoxParticle c = prior;
  predict_box(F, c);
  const BoxParticle before = c;
  EXPECT_FALSE(contract_box(F, prior.centre, prior.half, plane(100, 101, 0, 1), c));
  EXPECT_EQ(c.centre, before.centre);
  EXPECT_EQ(c.half, before.half);
}

TEST(SystematicResample, HandComputed) {
  // Total 4, u0 = 0.5: targets 0.5, 1.5, 2.5, 3.5; index 1 covers [0, 1), index 3 [1, 4).
  std::vector<int> out;
  systematic_resample(std::vector<double>{0.0, 1.0, 0.0, 3.0}, 4, 0.5, out);
  EXPECT_EQ(out, (std::vector<int>{1, 3, 3, 3}));
  // All zero: uniform over the boxes (a missed group keeps its boxes).
  systematic_resample(std::vector<double>{0.0, 0.0}, 4, 0.0, out);
  EXPECT_EQ(out, (std::vector<int>{0, 0, 1, 1}));
  systematic_resample(std::vector<double>{}, 4, 0.0, out);
  EXPECT_TRUE(out.empty());
}

}  // namespace
}  // namespace skytrack::group
