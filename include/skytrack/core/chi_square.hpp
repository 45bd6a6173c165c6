#pragma once
// Chi-square distribution helpers for validation gates: a plot is in a track's gate when its
// normalised innovation squared is below the quantile of the gate probability.

namespace skytrack {

/// P(X <= x) for X ~ chi-square with `dof` degrees of freedom.
double chi_square_cdf(double x, int dof) noexcept;

/// The x with chi_square_cdf(x, dof) = p, for p in (0, 1).
double chi_square_quantile(double p, int dof) noexcept;

}  // namespace skytrack
