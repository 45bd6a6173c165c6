// The closed set of extent estimators behind one interface (see extended_estimator.hpp).
#include "skytrack/extended/extended_estimator.hpp"

#include "skytrack/extended/ellipse_geometry.hpp"
#include "skytrack/extended/mem_ekf.hpp"
#include "skytrack/extended/random_matrix_filter.hpp"

namespace skytrack::extended {

ExtendedObject ExtendedEstimator::initiate(const KinVec& x, const KinMat& P,
                                           const Eigen::Matrix2d& extent) const {
  ExtendedObject object;
  object.x = x;
  object.P = P;
  object.S = P;
  object.extent = extent;
  object.dof = spec_.random_matrix.initial_dof;
  const EllipseAxes axes = ellipse_axes(extent);
  object.shape = Eigen::Vector3d(axes.orientation, axes.major, axes.minor);
  object.shape_cov = Eigen::Vector3d(spec_.mem_ekf.initial_orientation_var,
                                     spec_.mem_ekf.initial_axis_var, spec_.mem_ekf.initial_axis_var)
                         .asDiagonal();
  return object;
}

void ExtendedEstimator::predict(ExtendedObject& object, double dt,
                                const MotionSpec& motion) const noexcept {
  switch (spec_.kind) {
    case EstimatorKind::kSmf:
      smf_predict(motion, object, dt);
      return;
    case EstimatorKind::kRandomMatrix:
      random_matrix_predict(motion, spec_.random_matrix, object, dt);
      return;
    case EstimatorKind::kMemEkf:
      mem_ekf_predict(motion, spec_.mem_ekf, object, dt);
      return;
  }
}

UpdateStatus ExtendedEstimator::update(ExtendedObject& object,
                                       std::span<const Eigen::Vector2d> plots,
                                       const Eigen::Matrix2d& noise) noexcept {
  switch (spec_.kind) {
    case EstimatorKind::kSmf: {
      const double k2 = spec_.smf.bound_sigmas * spec_.smf.bound_sigmas;
      return smf_update(spec_.smf, object, plots, k2 * noise, workspace_);
    }
    case EstimatorKind::kRandomMatrix:
      return random_matrix_update(spec_.random_matrix, object, plots, noise);
    case EstimatorKind::kMemEkf:
      return mem_ekf_update(spec_.mem_ekf, object, plots, noise);
  }
  return UpdateStatus::kNumericFailure;
}

}  // namespace skytrack::extended
