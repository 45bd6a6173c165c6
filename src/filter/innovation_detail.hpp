#pragma once
// Internal: pieces shared by the EKF and unscented innovations (filter/innovation.hpp).
#include "skytrack/config/profile.hpp"
#include "skytrack/filter/innovation.hpp"

namespace skytrack::filter_detail {

/// Factorises shape.shared.S and forms the gain K = cross S^-1 (cross = P H' or Pxz) and
/// log det S. Sets shape.shared.ok.
void factorise(const GainMat& cross, InnovationShape& shape) noexcept;

/// NIS and log N(nu; 0, S) of out.residual against the shape's factor of S. Sets out.ok; on
/// failure the likelihood is -inf and the NIS +inf.
void whiten(const InnovationShape& shape, Innovation& out) noexcept;

/// Both, for an innovation whose S and residual are set (the unscented one).
void finish_innovation(const GainMat& cross, Innovation& out) noexcept;

/// Marks `out` as failed.
void fail_innovation(Innovation& out) noexcept;

/// Fills residual, S, R (H left empty) by the unscented transform, then finishes.
void innovate_unscented(const Gaussian& predicted, const StateLayout& layout,
                        const PlotMeasurement& measurement, const config::UnscentedSpec& spec,
                        Innovation& out) noexcept;

}  // namespace skytrack::filter_detail
