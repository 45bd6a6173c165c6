// Two noise levels mixed per scan (see noise_levels.hpp).
#include "skytrack/extended/noise_levels.hpp"

#include <algorithm>
#include <cmath>

#include "skytrack/extended/extended_existence.hpp"

namespace skytrack::extended {
namespace {

MotionSpec level_motion(const MotionSpec& motion, int level) noexcept {
  MotionSpec m = motion;
  if (level == 1) m.accel_noise = motion.manoeuvre_accel;
  return m;
}

// P(level j now | level i dt before).
Eigen::Matrix2d switching(const MotionSpec& motion, double dt) noexcept {
  const double stay_quiet = std::exp(-std::max(dt, 0.0) / motion.straight_duration);
  const double stay_turning = std::exp(-std::max(dt, 0.0) / motion.manoeuvre_duration);
  Eigen::Matrix2d p;
  p << stay_quiet, 1.0 - stay_quiet, 1.0 - stay_turning, stay_turning;
  return p;
}

int likelier(const NoiseLevels& levels) noexcept {
  return levels.probability[1] > levels.probability[0] ? 1 : 0;
}

void share_extent(NoiseLevels& levels, int from) noexcept {
  const ExtendedObject& source = levels.object[from];
  ExtendedObject& other = levels.object[1 - from];
  other.extent = source.extent;
  other.dof = source.dof;
  other.shape = source.shape;
  other.shape_cov = source.shape_cov;
}

// out's kinematics (x, P; S = P) the moment match of a and b weighted wa and wb.
void moment_match(const ExtendedObject& a, double wa, const ExtendedObject& b, double wb,
                  ExtendedObject& out) noexcept {
  out.x = wa * a.x + wb * b.x;
  const KinVec da = a.x - out.x, db = b.x - out.x;
  out.P = wa * (a.P + da * da.transpose()) + wb * (b.P + db * db.transpose());
  out.S = out.P;
}

}  // namespace

NoiseLevels start_levels(const ExtendedObject& object, const MotionSpec& motion) noexcept {
  NoiseLevels levels;
  levels.object = {object, object};
  const double total = motion.straight_duration + motion.manoeuvre_duration;
  levels.probability = {motion.straight_duration / total, motion.manoeuvre_duration / total};
  return levels;
}

ExtendedObject mix(const NoiseLevels& levels) noexcept {
  ExtendedObject out = levels.object[likelier(levels)];
  moment_match(levels.object[0], levels.probability[0], levels.object[1], levels.probability[1],
               out);
  return out;
}

void predict_levels(NoiseLevels& levels, const ExtendedEstimator& estimator,
                    const MotionSpec& motion, double dt, ExtendedObject& mixture) noexcept {
  const Eigen::Matrix2d p = switching(motion, dt);
  std::array<double, 2> predicted{};
  for (int j = 0; j < 2; ++j) {
    predicted[j] = levels.probability[0] * p(0, j) + levels.probability[1] * p(1, j);
  }
  // Each level starts from the levels' mixture weighted by where it came from.
  std::array<ExtendedObject, 2> mixed = levels.object;
  for (int j = 0; j < 2; ++j) {
    if (!(predicted[j] > 0.0)) continue;
    const double w0 = levels.probability[0] * p(0, j) / predicted[j];
    moment_match(levels.object[0], w0, levels.object[1], 1.0 - w0, mixed[j]);
  }
  levels.object = mixed;
  for (int j = 0; j < 2; ++j) estimator.predict(levels.object[j], dt, level_motion(motion, j));
  levels.probability = predicted;
  mixture = mix(levels);
}

UpdateStatus update_levels(NoiseLevels& levels, ExtendedEstimator& estimator,
                           std::span<const Eigen::Vector2d> plots, const Eigen::Matrix2d& noise,
                           const Eigen::Matrix2d& spread, ExtendedObject& mixture) noexcept {
  const PosMat H = position_matrix();
  std::array<double, 2> log_f{};
  for (int j = 0; j < 2; ++j) {
    const ExtendedObject& o = levels.object[j];
    log_f[j] = object_plots_log_density(plots, o.position(), H * o.P * H.transpose(), spread);
  }
  // Bayes over the levels; a level whose density is not finite keeps its prior weight
  // against the other only if both are (no evidence).
  if (std::isfinite(log_f[0]) && std::isfinite(log_f[1])) {
    const double top = std::max(log_f[0], log_f[1]);
    const double w0 = levels.probability[0] * std::exp(log_f[0] - top);
    const double w1 = levels.probability[1] * std::exp(log_f[1] - top);
    if (w0 + w1 > 0.0) levels.probability = {w0 / (w0 + w1), w1 / (w0 + w1)};
  }
  UpdateStatus status = UpdateStatus::kUpdated;
  for (ExtendedObject& o : levels.object) {
    if (estimator.update(o, plots, noise) == UpdateStatus::kNumericFailure) {
      status = UpdateStatus::kNumericFailure;
    }
  }
  share_extent(levels, likelier(levels));
  mixture = mix(levels);
  return status;
}

}  // namespace skytrack::extended
