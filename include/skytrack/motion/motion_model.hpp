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
#include <array>
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

/// A linear model's transition and process noise for the last two intervals it was
/// discretised over. A snapshot radar's tracks and chains are predicted over the same few
/// intervals every scan, and a turn's discretisation costs its sines and cosines each time.
/// One memo per model and layout; not shared between threads.
class DiscretisationMemo {
 public:
  struct Entry {
    double dt = 0.0;
    bool valid = false;
    StateMat F, Q;
  };
  /// The entry for dt, discretised by `discretise(dt, F, Q)` when it is not kept.
  template <class Discretise>
  const Entry& at(double dt, const Discretise& discretise) {
    for (const Entry& e : entries_) {
      if (e.valid && e.dt == dt) return e;
    }
    Entry& e = entries_[next_];
    next_ = 1 - next_;
    discretise(dt, e.F, e.Q);
    e.dt = dt;
    e.valid = true;
    return e;
  }

 private:
  std::array<Entry, 2> entries_;
  int next_ = 0;
};

/// The same prediction written into `out` (not `prior`), a linear model's discretisation
/// taken from `memo` when it holds dt: the same numbers as predict().
void predict(const AnyMotionModel& model, const StateLayout& layout, const Gaussian& prior,
             double dt, DiscretisationMemo& memo, Gaussian& out) noexcept;

}  // namespace skytrack
