#pragma once
// One extent estimator chosen by the profile (ExtendedSpec::kind) behind one interface: the
// per-mode seam calls initiate, then predict and update once per scan. The dispatch is a
// switch over the closed set (one branch per object per scan, no virtual calls).
#include <span>

#include "skytrack/extended/extended_object.hpp"
#include "skytrack/extended/smf_eot.hpp"

namespace skytrack::extended {

class ExtendedEstimator {
 public:
  explicit ExtendedEstimator(const ExtendedSpec& spec) : spec_(spec) {}

  /// A new object at state x with covariance P (SMF-EOT: also its set bound S = P) and
  /// extent X (MEM-EKF: its orientation and semi-axes from X).
  ExtendedObject initiate(const KinVec& x, const KinMat& P, const Eigen::Matrix2d& extent) const;

  void predict(ExtendedObject& object, double dt) const noexcept {
    predict(object, dt, spec_.motion);
  }
  /// The same with another motion (a manoeuvring object's noise level).
  void predict(ExtendedObject& object, double dt, const MotionSpec& motion) const noexcept;

  /// One scan's plots of this object (tracking-frame positions [m]) with their noise
  /// covariance R [m^2]; SMF-EOT bounds the noise by E(0, k^2 R), k = smf.bound_sigmas.
  UpdateStatus update(ExtendedObject& object, std::span<const Eigen::Vector2d> plots,
                      const Eigen::Matrix2d& noise) noexcept;

  const ExtendedSpec& spec() const noexcept { return spec_; }

 private:
  ExtendedSpec spec_;
  SmfWorkspace workspace_;
};

}  // namespace skytrack::extended
