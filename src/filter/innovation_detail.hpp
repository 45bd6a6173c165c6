#pragma once
// Internal: pieces shared by the EKF and unscented innovations (filter/innovation.hpp).
#include "skytrack/config/profile.hpp"
#include "skytrack/filter/innovation.hpp"

namespace skytrack::filter_detail {

/// Factorises S, forms K = cross S^-1 (cross = P H' or Pxz), NIS and log N(nu; 0, S).
/// Sets out.ok; on failure the likelihood is -inf and the NIS +inf.
void finish_innovation(const GainMat& cross, Innovation& out) noexcept;

/// Marks `out` as failed.
void fail_innovation(Innovation& out) noexcept;

/// Fills residual, S, R (H left empty) by the unscented transform, then finishes.
void innovate_unscented(const Gaussian& predicted, const StateLayout& layout,
                        const PlotMeasurement& measurement, const config::UnscentedSpec& spec,
                        Innovation& out) noexcept;

}  // namespace skytrack::filter_detail
