// Construction-time checks of an IMM filter (startup code: may allocate, returns Expected).
#include <cmath>
#include <string>
#include <utility>
#include <variant>

#include "skytrack/filter/imm_filter.hpp"

namespace skytrack {
namespace {

bool non_negative(double value) {
  return std::isfinite(value) && value >= 0.0;
}

/// Empty when the model's parameters are usable.
std::string model_problem(const AnyMotionModel& model) {
  struct Visitor {
    std::string operator()(const ConstantVelocity& m) const {
      return non_negative(m.accel_sigma) && non_negative(m.vertical_accel_sigma)
                 ? ""
                 : "constant velocity sigmas must be finite and >= 0";
    }
    std::string operator()(const ConstantAcceleration& m) const {
      return non_negative(m.jerk_sigma) && non_negative(m.vertical_accel_sigma)
                 ? ""
                 : "constant acceleration sigmas must be finite and >= 0";
    }
    std::string operator()(const CoordinatedTurn& m) const {
      return std::isfinite(m.turn_rate) && non_negative(m.accel_sigma) &&
                     non_negative(m.vertical_accel_sigma)
                 ? ""
                 : "coordinated turn parameters must be finite (sigmas >= 0)";
    }
    std::string operator()(const CoordinatedTurnEstimated& m) const {
      return non_negative(m.accel_sigma) && non_negative(m.turn_rate_sigma) &&
                     non_negative(m.vertical_accel_sigma)
                 ? ""
                 : "coordinated turn (estimated) sigmas must be finite and >= 0";
    }
    std::string operator()(const Singer& m) const {
      return non_negative(m.accel_sigma) && non_negative(m.vertical_accel_sigma) &&
                     m.time_constant > 0.0 && !std::isnan(m.time_constant)
                 ? ""
                 : "Singer needs sigmas >= 0 and a time constant > 0";
    }
  };
  return std::visit(Visitor{}, model);
}

}  // namespace

Expected<ImmFilter> ImmFilter::create(std::vector<AnyMotionModel> models,
                                      std::vector<std::string> names, Eigen::MatrixXd transition,
                                      StateLayout layout, config::MeasurementSpec measurement,
                                      double transition_interval) {
  const auto n = static_cast<Eigen::Index>(models.size());
  if (n == 0 || n > kMaxImmModes) {
    return make_error("an IMM needs 1 to " + std::to_string(kMaxImmModes) + " modes");
  }
  if (names.size() != models.size()) return make_error("one name per IMM mode is needed");
  if (transition.rows() != n || transition.cols() != n) {
    return make_error("the mode transition matrix must be " + std::to_string(n) + " x " +
                      std::to_string(n));
  }
  if (!transition.allFinite() || (transition.array() < 0.0).any()) {
    return make_error("mode transition probabilities must be finite and >= 0");
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    const double row = transition.row(i).sum();
    if (std::abs(row - 1.0) > 1e-6) {
      return make_error("row " + std::to_string(i) + " of the mode transition matrix sums to " +
                        std::to_string(row) + ", not 1");
    }
    transition.row(i) /= row;
  }
  if (layout.dims != 2 && layout.dims != 3) return make_error("state dims must be 2 or 3");
  if (layout.size() > kMaxStateDim) return make_error("state layout too large");
  for (std::size_t j = 0; j < models.size(); ++j) {
    if (!supports(models[j], layout)) {
      return make_error("mode '" + names[j] + "' needs states the layout does not have");
    }
    if (std::string problem = model_problem(models[j]); !problem.empty()) {
      return make_error("mode '" + names[j] + "': " + problem);
    }
  }
  const config::UnscentedSpec& ut = measurement.unscented;
  if (measurement.update == config::MeasurementUpdate::kUnscented &&
      !(ut.alpha > 0.0 && ut.alpha <= 1.0 && std::isfinite(ut.beta) && ut.kappa >= 0.0)) {
    return make_error("unscented parameters need alpha in (0, 1] and kappa >= 0");
  }
  if (!(transition_interval >= 0.0 && std::isfinite(transition_interval))) {
    return make_error("mode_transition_interval must be a finite number >= 0");
  }
  return ImmFilter(std::move(models), std::move(names), std::move(transition), layout,
                   std::move(measurement), transition_interval);
}

Expected<ImmFilter> ImmFilter::from_profile(const config::TrackingProfile& profile, int auto_dims) {
  std::vector<AnyMotionModel> models;
  std::vector<std::string> names;
  for (const config::MotionModelSpec& spec : profile.motion_models) {
    models.push_back(make_motion_model(spec));
    names.push_back(spec.name);
  }
  const auto n = static_cast<Eigen::Index>(models.size());
  Eigen::MatrixXd transition = Eigen::MatrixXd::Constant(n, n, -1.0);  // -1: missing entry
  for (Eigen::Index i = 0; i < n && i < static_cast<Eigen::Index>(profile.mode_transition.size());
       ++i) {
    const std::vector<double>& row = profile.mode_transition[i];
    for (Eigen::Index j = 0; j < n && j < static_cast<Eigen::Index>(row.size()); ++j) {
      transition(i, j) = row[j];
    }
  }
  if (static_cast<Eigen::Index>(profile.mode_transition.size()) != n) {
    return make_error("mode_transition needs one row per motion model");
  }
  const int dims = profile.dimension == 0 ? auto_dims : profile.dimension;
  return create(std::move(models), std::move(names), std::move(transition),
                layout_for(profile.motion_models, dims), profile.measurement,
                profile.mode_transition_interval);
}

}  // namespace skytrack
