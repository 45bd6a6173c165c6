#pragma once
// Box particles and the interval steps of the box-particle PHD filter, paper 000 §3.2
// (after Schikora et al. 2014, the paper's ref. 19): interval prediction (eq. 14), the box
// likelihood |[x] ∩ [z]| / |[x]| (eq. 19), the PHD weight update with Poisson clutter
// (eq. 18, 20), the choice of the contracting measurement box (eq. 23-24) and contraction
// (eq. 25-26) by constraint propagation through the motion model, and per-label
// systematic resampling. Shared by the labeled filter and the k-means baselines.
// State of a box: intervals over [x vx y vy] (2-D, tracking frame, SI units).
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "skytrack/group/group_spec.hpp"

namespace skytrack::group {

using BoxVec = Eigen::Vector4d;  // [x vx y vy]
using BoxMat = Eigen::Matrix4d;

/// An axis-aligned box in the measurement plane (x, y) [m]: a cell's interval hull (eq. 11).
struct PlaneBox {
  Eigen::Vector2d lower = Eigen::Vector2d::Zero();
  Eigen::Vector2d upper = Eigen::Vector2d::Zero();
  double area() const noexcept;  // 0 for an empty or inverted box
};

/// A labeled box particle: the interval [centre - half, centre + half] over [x vx y vy], its
/// PHD weight and the two-part label of §3.2 (l1 = group, 0 undecided; l2 = missed scans).
struct BoxParticle {
  BoxVec centre = BoxVec::Zero();
  BoxVec half = BoxVec::Zero();  // half-widths, >= 0
  double weight = 0.0;
  std::uint32_t label = 0;  // l1
  int missed = 0;           // l2
  int slot = -1;            // this scan's label or newborn set (index into the caller's table)
};

/// F(dt) of the group motion: CV, or CT with the known turn rate (w -> 0 gives CV).
BoxMat group_transition(GroupMotion motion, double turn_rate, double dt) noexcept;

/// Eq. 14: the interval hull of F [x], exact for a linear map: centre F c, half |F| h.
void predict_box(const BoxMat& F, BoxParticle& box) noexcept;

/// Eq. 19: |[h]([x]) ∩ [z]| / |[h]([x])| with [h]([x]) the box's (x, y) projection; 0 when
/// the projection has no area or they do not meet.
double box_likelihood(const BoxParticle& box, const PlaneBox& z) noexcept;

/// Eq. 25-26 with the constraint propagation of ref. 19: the predicted box's position is
/// intersected with [z]; the prior box (before eq. 14) is contracted by the constraint
/// "F's position rows of the prior lie in that intersection" (one forward-backward pass of
/// each linear row), and the velocity of the result is F's velocity rows of the contracted
/// prior. This is how a measurement, which sees position only, narrows the velocity.
/// Returns false (box unchanged) when the position does not meet [z].
bool contract_box(const BoxMat& F, const BoxVec& prior_centre, const BoxVec& prior_half,
                  const PlaneBox& z, BoxParticle& box) noexcept;

/// Output of phd_update, reused between scans.
struct PhdUpdateResult {
  std::vector<int> best_cell;        // eq. 23 per particle; -1 when no cell weighs on it
  std::vector<double> denominators;  // eq. 20 per cell
  std::vector<double> shares;        // slots x cells (row-major): sum over the slot's
                                     // particles of g Pd w / denominator (eq. 24)
  int slots = 0;
  // Workspace: the non-zero likelihoods (eq. 19) of particle i are pairs
  // [offsets[i], offsets[i + 1]) of (cell, g); cells sorted by their lower x bound let each
  // box visit only the cells its x interval can meet, so the cost grows with the boxes
  // times the cells near each, not boxes times cells.
  std::vector<std::pair<int, double>> pairs;
  std::vector<std::size_t> offsets;
  std::vector<int> cells_by_x;
  std::vector<double> lower_x;  // sorted
};

/// Eq. 18 and 20 in place on the particles' weights: w <- [(1 - Pd) + sum_j g_ij Pd /
/// (lambda c_j + sum_i g_ij Pd w_i)] w, with clutter_intensity[j] = lambda c([z_j]).
/// Also fills best_cell (eq. 23-24) and the per-slot shares of each cell (particles with
/// slot in [0, slots)). Non-finite weights are taken as 0.
void phd_update(std::span<BoxParticle> particles, std::span<const PlaneBox> cells,
                std::span<const double> clutter_intensity, double detection_probability, int slots,
                PhdUpdateResult& out) noexcept;

/// Systematic resampling: `count` indices into `weights` (ascending), offset u0 in [0, 1).
/// All-zero or non-finite weights resample uniformly (a missed group keeps its boxes).
void systematic_resample(std::span<const double> weights, int count, double u0,
                         std::vector<int>& out) noexcept;

}  // namespace skytrack::group
