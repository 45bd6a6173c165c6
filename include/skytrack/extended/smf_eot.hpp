#pragma once
// SMF-EOT: extended object tracking with a set-membership filter under unknown-but-bounded
// noise (paper 002: Liu, Ma, Zhang & Li 2023, J. Air Force Eng. Univ. 24(6), section 2.2).
//   predict  x = Phi x, P = Phi P Phi' + Q, S = (1 + 1/p) Phi S Phi' + (1 + p) Q (eq. 23, 27-29),
//            X unchanged (eq. 30);
//   update   with the plots' mean zbar and the noise bound C = lambda X (+) U (eq. 2):
//            K = P H'(H P H' + C)^-1, x = (I - KH) x + K zbar, P = P - K H P,
//            S = (1 + 1/p)(I - KH) S (I - KH)' + (1 + p) K C K' (eq. 32-37);
//   extent   each plot's bounding ellipse E(z_r, Omega), Omega = H S H' (+) C (eq. 38-39), the
//            Graham-scan hull of their boundary points, its enclosing ellipse B (eq. 40-41),
//            then Minkowski differences (eq. 42-48).
// Our reading of the extent step (the paper prints its steps, not a consistent model): B is
// the plots' enclosing ellipse grown by Omega, so B (-) Omega is the plots' own enclosing
// ellipse; each plot is a scatterer on the object plus noise in E(0, U), so the object's
// ellipse is that (-) U. The paper subtracts only Omega's (1 + 1/p) H S H' term, then U,
// and divides by lambda, which leaves lambda X_pred and U inside the result. Every plot
// bound is a Minkowski-sum bound of least trace (Theorems 3-4). Where a difference is empty
// across one axis only (a long object's plots no wider than their noise across it), the
// axis the plots resolve keeps its length (smf_eot.cpp), instead of the whole extent falling
// to SmfSpec::min_axis.
// Not in the paper: before the update, plots farther from most of the scan's plots than the
// object's predicted diameter (times a margin) plus the noise leave the update, centre and
// hull (SmfSpec::outlier_margin, smf_eot.cpp), so a stray plot does not grow the hull.
#include <span>
#include <vector>

#include "skytrack/extended/extended_object.hpp"

namespace skytrack::extended {

/// Buffers reused across updates (the heap stops growing after the largest scan).
struct SmfWorkspace {
  std::vector<Eigen::Vector2d> boundary;
  std::vector<Eigen::Vector2d> hull;
  std::vector<Eigen::Vector2d> kept;  // the plots consistent with one object
  std::vector<Eigen::Vector2d> inliers;
};

void smf_predict(const MotionSpec& motion, ExtendedObject& object, double dt) noexcept;

/// `bound` is the sensor's noise bound U (shape matrix [m^2]): each plot's noise lies in
/// E(0, U). Non-finite plots must have been dropped by the caller. Plots inconsistent with
/// one object (SmfSpec::outlier_margin) are left out.
UpdateStatus smf_update(const SmfSpec& spec, ExtendedObject& object,
                        std::span<const Eigen::Vector2d> plots, const Eigen::Matrix2d& bound,
                        SmfWorkspace& workspace) noexcept;

/// The extent step alone (eq. 38-48): the object's ellipse from the plots, the updated
/// centre bound H S H' and the noise bound C, U. Exposed for tests.
Eigen::Matrix2d smf_extent_measurement(const SmfSpec& spec, std::span<const Eigen::Vector2d> plots,
                                       const Eigen::Matrix2d& centre_bound,
                                       const Eigen::Matrix2d& noise_bound,
                                       const Eigen::Matrix2d& sensor_bound,
                                       SmfWorkspace& workspace) noexcept;

}  // namespace skytrack::extended
