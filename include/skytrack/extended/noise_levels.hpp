#pragma once
// The two noise levels of an extended object's motion (MotionSpec: accel_noise going
// straight, manoeuvre_accel in a manoeuvre) mixed per scan, an interacting multiple model
// over the levels: each level keeps its own estimate, both are predicted and updated with
// every scan's plots, and the plots' likelihood under each prediction moves the levels'
// probabilities. The object reported, gated and associated is their mixture (moment
// matched). For the Bayesian estimators (random matrix, MEM-EKF*), whose kinematics are
// Gaussian; SMF-EOT's state set has no mixture and chooses one level per scan instead.
//
// The levels switch as Markov chains in continuous time: an object keeps a level for a mean
// duration (MotionSpec::straight_duration, manoeuvre_duration), so over dt it stays with
// probability e^{-dt / duration}. The extent is the object's, not the motion's: after each
// update both levels take the likelier level's.
#include <array>
#include <span>

#include <Eigen/Core>

#include "skytrack/extended/extended_estimator.hpp"

namespace skytrack::extended {

struct NoiseLevels {
  std::array<ExtendedObject, 2> object;         // [0] quiet, [1] manoeuvre
  std::array<double, 2> probability{1.0, 0.0};  // after the last scan
};

/// Both levels started at `object`, with the levels' long-run probabilities.
NoiseLevels start_levels(const ExtendedObject& object, const MotionSpec& motion) noexcept;

/// Mix the levels for a step of dt [s], predict each with its noise, and write their
/// mixture to `mixture`.
void predict_levels(NoiseLevels& levels, const ExtendedEstimator& estimator,
                    const MotionSpec& motion, double dt, ExtendedObject& mixture) noexcept;

/// Weigh the levels by one scan's plots' likelihood under their predictions (spread: each
/// plot's scatter about the centre, X / 4 + R), update each with the plots (noise: their
/// mean covariance) and write the mixture to `mixture`. A numeric failure of either
/// level's update is returned (that level stays as predicted).
UpdateStatus update_levels(NoiseLevels& levels, ExtendedEstimator& estimator,
                           std::span<const Eigen::Vector2d> plots, const Eigen::Matrix2d& noise,
                           const Eigen::Matrix2d& spread, ExtendedObject& mixture) noexcept;

/// The levels' mixture: kinematics moment matched, the extent of the likelier level.
ExtendedObject mix(const NoiseLevels& levels) noexcept;

}  // namespace skytrack::extended
