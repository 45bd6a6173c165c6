// Cartesian and polar measurement functions with analytic Jacobians (Bar-Shalom, Li &
// Kirubarajan 2001, §10.3; range-rate: relative velocity on the line of sight).
// With d = p - p_s (ENU), b = R' d (body), rho = |b_xy|, r = |d|, v = v_t - v_s:
//   range   r = |d|                   dr/dp    = d' / r
//   azimuth az = atan2(b_x, b_y)      daz/dp   = [b_y, -b_x, 0] R' / rho^2
//   elev.   el = atan2(b_z, rho)      del/dp   = [-b_x b_z, -b_y b_z, rho^2] R' / (r^2 rho)
//   rdot    = d.v / r                 drdot/dp = (v - rdot d / r)' / r,  drdot/dv = d' / r
//   altitude h = |p - c| - R_e        dh/dp    = (p - c)' / |p - c|  (c the earth's centre)
#include "skytrack/measurement/measurement_model.hpp"

#include <cmath>

#include "skytrack/geometry/altitude.hpp"
#include "skytrack/geometry/angles.hpp"
#include "skytrack/geometry/frames.hpp"

namespace skytrack {
namespace {

/// Target position and velocity relative to the platform in ENU (2-D: z components 0).
struct Relative {
  Eigen::Vector3d d = Eigen::Vector3d::Zero();
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
};

Relative relative_to(const MeasurementModel& model, const StateVec& x) noexcept {
  Relative rel;
  for (int axis = 0; axis < model.state_dims; ++axis) {
    rel.d[axis] = x[StateLayout::position(axis)] - model.platform.position[axis];
    rel.v[axis] = x[StateLayout::velocity(axis)] - model.platform.velocity[axis];
  }
  return rel;
}

/// The state's position in the tracking frame (a 3-D state: polar height models only).
Eigen::Vector3d model_position(const StateVec& x) noexcept {
  return {x[StateLayout::position(0)], x[StateLayout::position(1)], x[StateLayout::position(2)]};
}

}  // namespace

MeasurementModel MeasurementModel::cartesian(int components, int state_dims, const MeasVec& sigma) {
  MeasurementModel model;
  model.kind = MeasurementKind::kCartesian;
  model.state_dims = state_dims;
  model.position_components = components;
  model.sigma = sigma;
  return model;
}

MeasurementModel MeasurementModel::polar(const PlatformState& platform, bool elevation,
                                         bool range_rate, int state_dims, const MeasVec& sigma) {
  MeasurementModel model;
  model.kind = MeasurementKind::kPolar;
  model.state_dims = state_dims;
  model.position_components = elevation ? 3 : 2;
  model.has_range_rate = range_rate;
  model.platform = platform;
  if (state_dims == 2) model.platform.attitude = {platform.attitude[0], 0.0, 0.0};
  model.enu_to_body = body_to_enu(model.platform.attitude).transpose();
  model.sigma = sigma;
  return model;
}

MeasurementModel MeasurementModel::polar_height(const PlatformState& platform, bool range_rate,
                                                const MeasVec& sigma) {
  MeasurementModel model = polar(platform, true, range_rate, 3, sigma);
  model.kind = MeasurementKind::kPolarHeight;
  return model;
}

MeasVec MeasurementModel::measure(const StateLayout& /*layout*/, const StateVec& x) const noexcept {
  MeasVec z(size());
  if (kind == MeasurementKind::kCartesian) {
    for (int axis = 0; axis < position_components; ++axis) {
      z[axis] = x[StateLayout::position(axis)];
    }
    return z;
  }
  const Relative rel = relative_to(*this, x);
  const Eigen::Vector3d b = enu_to_body * rel.d;
  const double r = rel.d.norm();
  z[0] = r;
  z[1] = (b.x() == 0.0 && b.y() == 0.0) ? 0.0 : std::atan2(b.x(), b.y());
  if (kind == MeasurementKind::kPolarHeight) {
    z[2] = altitude_of(model_position(x));
  } else if (position_components == 3) {
    z[2] = r == 0.0 ? 0.0 : std::atan2(b.z(), b.head<2>().norm());
  }
  if (has_range_rate) z[size() - 1] = r == 0.0 ? 0.0 : rel.d.dot(rel.v) / r;
  return z;
}

MeasJacobian MeasurementModel::jacobian(const StateLayout& layout,
                                        const StateVec& x) const noexcept {
  MeasJacobian H = MeasJacobian::Zero(size(), layout.size());
  if (kind == MeasurementKind::kCartesian) {
    for (int axis = 0; axis < position_components; ++axis) {
      H(axis, StateLayout::position(axis)) = 1.0;
    }
    return H;
  }
  const Relative rel = relative_to(*this, x);
  const Eigen::Vector3d b = enu_to_body * rel.d;
  const double r2 = rel.d.squaredNorm(), r = std::sqrt(r2);
  const double rho2 = b.head<2>().squaredNorm(), rho = std::sqrt(rho2);
  if (r == 0.0) return H;
  Eigen::RowVector3d d_range = rel.d.transpose() / r;
  Eigen::RowVector3d d_azimuth = Eigen::RowVector3d::Zero();
  Eigen::RowVector3d d_elevation = Eigen::RowVector3d::Zero();
  if (rho > 0.0) {
    d_azimuth = Eigen::RowVector3d(b.y(), -b.x(), 0.0) * enu_to_body / rho2;
    d_elevation =
        Eigen::RowVector3d(-b.x() * b.z(), -b.y() * b.z(), rho2) * enu_to_body / (r2 * rho);
  }
  const Eigen::Vector3d d_altitude = kind == MeasurementKind::kPolarHeight
                                         ? altitude_gradient(model_position(x))
                                         : Eigen::Vector3d::Zero();
  const int rr_row = size() - 1;
  const double rdot = rel.d.dot(rel.v) / r;
  for (int axis = 0; axis < state_dims; ++axis) {
    const int p = StateLayout::position(axis);
    H(0, p) = d_range[axis];
    H(1, p) = d_azimuth[axis];
    if (kind == MeasurementKind::kPolarHeight) {
      H(2, p) = d_altitude[axis];
    } else if (position_components == 3) {
      H(2, p) = d_elevation[axis];
    }
    if (has_range_rate) {
      H(rr_row, p) = (rel.v[axis] - rdot * rel.d[axis] / r) / r;
      H(rr_row, StateLayout::velocity(axis)) = rel.d[axis] / r;
    }
  }
  return H;
}

MeasVec MeasurementModel::residual(const MeasVec& z, const MeasVec& zhat) const noexcept {
  MeasVec nu = z - zhat;
  const int az = azimuth_index();
  if (az >= 0) nu[az] = wrap_angle(nu[az]);
  return nu;
}

MeasMat MeasurementModel::noise() const noexcept {
  return sigma.array().square().matrix().asDiagonal();
}

double MeasurementModel::volume_element(const MeasVec& z) const noexcept {
  if (kind == MeasurementKind::kCartesian) return 1.0;
  if (kind == MeasurementKind::kPolar && position_components == 3) {
    return z[0] * z[0] * std::cos(z[2]);
  }
  return z[0];
}

}  // namespace skytrack
