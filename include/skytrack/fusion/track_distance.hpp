#pragma once
// Paper 004 (Li & Zhang 2016, "Track fusion based on the mean OSPA distance with an adaptive
// sliding window"), eq. 9-12, for one pair of tracks (a local track of one sensor against one
// of another): with one track on each side the OSPA of eq. 9 is the cut-off base distance.
//   base distance (eq. 10)   d~ = (d(x, y)^p + (alpha delta)^p)^(1/p), cut at c (eq. 9)
//   history (sliding window) Dw = mean of the past scans' cut-off distances in the window
//   adaptive blend (eq. 11)  Daw = beta Dw + (1 - beta) D, beta = eps max(Dw, D) / (Dw + D)
//   MOSPA (eq. 12)           expectation over the track posteriors: with Gaussian errors
//                            E|x - y|^2 = |mx - my|^2 + tr(Px + Py) (Euclidean), and
//                            E[(x-y)' S^-1 (x-y)] = (mx-my)' S^-1 (mx-my) + n, S = Px + Py
// Readings (docs/fusion.md): E[d^p] is taken as E[d^2]^(p/2), exact for p = 2; the cutoff
// applies after the expectation; delta = 1 when the two tracks were not last fused into the
// same system track (label hysteresis), else 0.
#include <cstdint>
#include <span>

#include <Eigen/Core>

#include "skytrack/fusion/fusion_spec.hpp"

namespace skytrack::fusion {

/// A track's position estimate at one time: mean and covariance over dims (2: x, y; 3: +z).
struct PositionEstimate {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  Eigen::Matrix3d cov = Eigen::Matrix3d::Identity();
  int dims = 2;
};

/// One past scan of a track, for the history distance.
struct HistoryPoint {
  std::uint64_t cycle = 0;
  PositionEstimate position;
};

/// E[d(x, y)^2] over the two Gaussian position posteriors (eq. 12 with p = 2), over the
/// dimensions both tracks have. Normalised: in the pair's summed covariance.
double expected_squared_distance(const PositionEstimate& a, const PositionEstimate& b,
                                 Metric metric) noexcept;

/// Cut-off base distance of eq. 9-10 from the expected squared distance and the label term.
double base_distance(double expected_squared, bool labels_differ, const FusionSpec& spec) noexcept;

/// beta of eq. 11: eps max(Dw, D) / (Dw + D); eps / 2 when both are zero.
double adaptive_beta(double history, double current, double epsilon) noexcept;

/// Daw of eq. 11 under the spec's blend (adaptive, or the fixed history weight).
double blend(double history, double current, const FusionSpec& spec) noexcept;

/// Dw: mean base distance over the scans both histories hold in the window before `cycle`
/// (cycles in (cycle - window_cycles, cycle)); nullopt-like: returns `fallback` when none.
/// Histories are in increasing cycle order.
double history_distance(std::span<const HistoryPoint> a, std::span<const HistoryPoint> b,
                        std::uint64_t cycle, std::uint64_t window_cycles, bool labels_differ,
                        const FusionSpec& spec, double fallback) noexcept;

/// The pair's MOSPA (eq. 12): the blend of its current and history distances.
double pair_mospa(const PositionEstimate& a, const PositionEstimate& b,
                  std::span<const HistoryPoint> history_a, std::span<const HistoryPoint> history_b,
                  std::uint64_t cycle, std::uint64_t window_cycles, bool labels_differ,
                  const FusionSpec& spec) noexcept;

}  // namespace skytrack::fusion
