#pragma once
// Kernel-density clutter rejection and mean-shift partitioning of one scan's plots.
// Paper 000 §3.1 (LBP-PHD group tracking): Gaussian kernel density at each plot (eq. 6-7),
// clutter threshold tau (eq. 8), mean-shift vector and iteration (eq. 9-10), and the interval
// hull of each partition cell as its measurement box (eq. 11). docs/clutter_rejection.md
// gives the equations, the kernel truncation and its error bound, and benchmark figures.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "skytrack/clutter/clutter_rejection_spec.hpp"

namespace skytrack::clutter {

/// Interval hull [lower, upper] of the plots of one mean-shift cell (eq. 11), in the
/// tracking frame [m]. With dims = 2 the z interval is [0, 0].
struct MeasurementBox {
  Eigen::Vector3d lower = Eigen::Vector3d::Zero();
  Eigen::Vector3d upper = Eigen::Vector3d::Zero();
};

/// Outcome of ClutterRejector::apply for one scan; every per-plot vector has one entry per
/// input plot, in input order.
struct ClutterRejectionResult {
  std::vector<std::uint8_t> keep;     // 1: kept, 0: rejected as clutter (or non-finite)
  std::vector<int> cell;              // mean-shift cell 0..cells-1; -1 for a rejected plot
  int cells = 0;                      // number of cells; labels follow first plot index
  int rejected = 0;                   // plots with keep == 0, non-finite ones included
  int protected_kept = 0;             // protected plots below tau, kept by the protection rule
  int invalid = 0;                    // plots with a non-finite coordinate (always rejected)
  int mean_shift_steps = 0;           // eq. 10 steps summed over the kept plots
  std::vector<double> density;        // f(z) (eq. 6-7), truncated kernel [1/m^dims]; 0 if invalid
  double threshold = 0.0;             // tau (eq. 8); 0 when disabled or no valid plot
  std::vector<MeasurementBox> boxes;  // one per cell (eq. 11)
};

/// Gaussian kernel G(z, z_i) of eq. 7 for a squared distance |z - z_i|^2 [m^2],
/// bandwidth h [m] and dimension d: (2 pi h^2)^(-d/2) exp(-|z - z_i|^2 / (2 h^2)).
double gaussian_kernel(double squared_distance, double bandwidth, int dims) noexcept;

/// Threshold of eq. 8: tau = f_min + (beta / n_f) (f_max - f_min). n_f < 1 is taken as 1.
double clutter_threshold(double f_min, double f_max, int beta, int n_f) noexcept;

/// Upper bound on the density error of truncating the kernel at c = truncation_sigmas
/// bandwidths: every plot farther than c h contributes less than G(0) exp(-c^2 / 2) / N to
/// eq. 6, so the truncated density is low by at most (N - n_in) / N * G(0) exp(-c^2 / 2)
/// < G(0) exp(-c^2 / 2), with n_in the plots inside the radius. Returns G(0) exp(-c^2 / 2).
double truncation_error_bound(double bandwidth, int dims, double truncation_sigmas) noexcept;

namespace detail {
struct ClutterWorkspace;  // k-d trees and buffers, defined in clutter_rejector.cpp
}  // namespace detail

/// Per-scan clutter rejection of paper 000 §3.1, configured from the profile.
///  1. Density f(z) at each plot (eq. 6-7) over all N valid plots of the scan, the plot
///     itself included (the paper's sum runs over i = 1..N), the kernel truncated at
///     truncation_sigmas * h and evaluated through a k-d tree radius search: cost
///     ~ N x (neighbours within the radius), not N^2.
///  2. tau (eq. 8) over the scan's densities; a plot with f(z) < tau is clutter unless
///     protected_plots[i] != 0 (inside the gate of a confirmed track): a protected plot is
///     never rejected. If all densities are equal (to 1e-9 relative) every plot is kept.
///  3. Mean-shift (eq. 9-10) of each kept plot over the kept plots with the Gaussian kernel
///     of mean_shift.bandwidth (same truncation) until a step is shorter than
///     mean_shift.tolerance or after mean_shift.max_iterations steps. Converged points within
///     mean_shift.merge_distance of each other (inclusive, transitively) form one cell.
///  4. The interval hull of each cell is its measurement box (eq. 11).
/// When spec.enabled is false nothing is rejected and no density is computed (all 0), but
/// steps 3-4 still run: group tracking needs the cells.
/// Deterministic: the same input gives bit-identical output. Buffers live in the object and
/// are reused; after warm-up only the k-d tree node pools are re-allocated per scan.
class ClutterRejector {
 public:
  static constexpr double kDefaultTruncationSigmas = 3.0;

  explicit ClutterRejector(const config::ClutterRejectionSpec& spec,
                           double truncation_sigmas = kDefaultTruncationSigmas);
  ~ClutterRejector();
  ClutterRejector(ClutterRejector&&) noexcept;
  ClutterRejector& operator=(ClutterRejector&&) noexcept;
  ClutterRejector(const ClutterRejector&) = delete;
  ClutterRejector& operator=(const ClutterRejector&) = delete;

  /// positions: the scan's plot positions in the tracking frame [m]; only the first `dims`
  /// coordinates are used (dims 2 or 3; anything below 3 is taken as 2).
  /// protected_plots: empty (nothing protected) or one flag per plot; entries past its end
  /// count as unprotected. The returned reference stays valid until the next apply().
  const ClutterRejectionResult& apply(std::span<const Eigen::Vector3d> positions, int dims,
                                      std::span<const std::uint8_t> protected_plots) noexcept;

  const ClutterRejectionResult& result() const noexcept { return result_; }
  const config::ClutterRejectionSpec& spec() const noexcept { return spec_; }
  double truncation_sigmas() const noexcept { return truncation_sigmas_; }

 private:
  config::ClutterRejectionSpec spec_;
  double truncation_sigmas_;
  ClutterRejectionResult result_;
  std::unique_ptr<detail::ClutterWorkspace> workspace_;
};

}  // namespace skytrack::clutter
