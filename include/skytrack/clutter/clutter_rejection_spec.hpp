#pragma once
// The preprocessing stage's kernel-density clutter rejection and mean-shift partitioning
// (paper 000 §3.1) as a profile gives them: the `clutter_rejection` section, which every
// estimator mode shares (config/README.md).
namespace skytrack::config {

/// Mean-shift partitioning of the kept plots (paper 000 eq. 9-10).
struct MeanShiftSpec {
  double bandwidth = 500.0;       // [m] Gaussian kernel bandwidth
  double merge_distance = 100.0;  // [m] converged points closer than this form one cell
  int max_iterations = 50;        // per plot
  double tolerance = 1.0;         // [m] a point has converged when it moves less than this
  bool operator==(const MeanShiftSpec&) const = default;
};

/// Kernel-density clutter rejection, paper 000 §3.1: a plot whose density (eq. 6-7) is below
/// tau = f_min + (beta / n_f) (f_max - f_min) (eq. 8) is clutter.
struct ClutterRejectionSpec {
  bool enabled = false;             // default.yaml says why it is off for point targets
  double kernel_bandwidth = 500.0;  // h [m]
  int beta = 1;                     // in [1, n_f); raise it in heavier clutter
  int n_f = 10;                     // number of equal bins of [f_min, f_max]
  MeanShiftSpec mean_shift;
  bool operator==(const ClutterRejectionSpec&) const = default;
};

}  // namespace skytrack::config
