#pragma once
// The closed set of motion models an IMM mode can use, and the prediction step.
// All modes of one tracker share one StateLayout (filter/state.hpp), so the IMM can mix them
// (Blom & Bar-Shalom 1988; paper 003 eq. 1-2): a model leaves the states it does not use in a
// defined condition (acceleration -> 0 with zero covariance, w carried unchanged).
//
// Prediction (Bar-Shalom, Li & Kirubarajan 2001, §5.2 Kalman filter, §10.3 EKF):
//   dt > 0:  x' = f(x) (= F x for linear models),  P' = F P F' + Q(dt)
//   dt = 0:  identity (the Gaussian is returned unchanged)
//   dt < 0:  retrodiction, x' = f(x, dt) (F(dt) = F(-dt)^-1 for the linear models),
//            P' = F(dt) (P + Q(|dt|)) F(dt)': the state at the earlier time is
//            F^-1 (x - w) with w the noise accumulated over the interval (Bar-Shalom 2002,
//            "Update with out-of-sequence measurements", retrodiction without the
//            cross-covariance terms).
#include <variant>
#include <vector>

#include "skytrack/config/profile.hpp"
#include "skytrack/filter/state.hpp"
#include "skytrack/motion/constant_acceleration.hpp"
#include "skytrack/motion/constant_velocity.hpp"
#include "skytrack/motion/coordinated_turn.hpp"
#include "skytrack/motion/coordinated_turn_estimated.hpp"
#include "skytrack/motion/singer.hpp"

namespace skytrack {

using AnyMotionModel = std::variant<ConstantVelocity, ConstantAcceleration, CoordinatedTurn,
                                    CoordinatedTurnEstimated, Singer>;

/// The model a profile entry describes (only the parameters of its type are read).
AnyMotionModel make_motion_model(const config::MotionModelSpec& spec);

/// The smallest layout every model of the set can act on: acceleration states if any model
/// is constant acceleration or Singer, the turn rate if any is coordinated_turn_estimated.
StateLayout layout_for(const std::vector<config::MotionModelSpec>& specs, int dims);

/// True when the layout carries every state the model needs.
bool supports(const AnyMotionModel& model, const StateLayout& layout) noexcept;

/// Predicts `prior` over dt [s] (see the top of this file for dt <= 0). The layout must
/// support the model and match the Gaussian's size.
Gaussian predict(const AnyMotionModel& model, const StateLayout& layout, const Gaussian& prior,
                 double dt) noexcept;

}  // namespace skytrack
