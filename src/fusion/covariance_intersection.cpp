// Fast covariance intersection and the constant-velocity alignment in time
// (include/skytrack/fusion/covariance_intersection.hpp).
#include "skytrack/fusion/covariance_intersection.hpp"

#include <algorithm>

#include <Eigen/Cholesky>

namespace skytrack::fusion {
namespace {

/// CI over the N x N block at `offset` of the tracks selected by `use`.
template <int N, class Use>
bool fuse_block(std::span<const StateEstimate> tracks, int offset, Use use,
                StateEstimate& out) noexcept {
  using Vec = Eigen::Matrix<double, N, 1>;
  using Mat = Eigen::Matrix<double, N, N>;
  double inverse_trace_sum = 0.0;
  for (const StateEstimate& t : tracks) {
    if (use(t)) inverse_trace_sum += 1.0 / t.P.template block<N, N>(offset, offset).trace();
  }
  Mat info = Mat::Zero();
  Vec info_x = Vec::Zero();
  for (const StateEstimate& t : tracks) {
    if (!use(t)) continue;
    const Mat p = t.P.template block<N, N>(offset, offset);
    const double w = (1.0 / p.trace()) / inverse_trace_sum;
    const Eigen::LLT<Mat> llt(p);
    if (llt.info() != Eigen::Success) return false;
    const Mat p_inv = llt.solve(Mat::Identity());
    info += w * p_inv;
    info_x += w * (p_inv * t.x.template segment<N>(offset));
  }
  const Eigen::LLT<Mat> llt(info);
  if (llt.info() != Eigen::Success) return false;
  Mat p = llt.solve(Mat::Identity());
  p = 0.5 * (p + p.transpose()).eval();
  out.P.template block<N, N>(offset, offset) = p;
  out.x.template segment<N>(offset) = p * info_x;
  return true;
}

}  // namespace

FusedEstimate covariance_intersection(std::span<const StateEstimate> tracks) noexcept {
  FusedEstimate result;
  if (tracks.empty()) return result;
  if (tracks.size() == 1) return {tracks.front(), true};
  const auto all = [](const StateEstimate&) { return true; };
  const auto three = [](const StateEstimate& t) { return t.dims >= 3; };
  const bool all_3d = std::all_of(tracks.begin(), tracks.end(), three);
  const bool any_3d = std::any_of(tracks.begin(), tracks.end(), three);
  StateEstimate& out = result.estimate;
  out.x.setZero();
  out.P.setZero();
  if (all_3d) {
    out.dims = 3;
    result.ok = fuse_block<6>(tracks, 0, all, out);
    return result;
  }
  out.dims = any_3d ? 3 : 2;
  result.ok = fuse_block<4>(tracks, 0, all, out);
  if (result.ok && any_3d) result.ok = fuse_block<2>(tracks, 4, three, out);
  if (!any_3d) out.P.bottomRightCorner<2, 2>().setIdentity();  // unused, kept regular
  return result;
}

StateEstimate predict_cv(const StateEstimate& s, double dt, double accel_psd) noexcept {
  StateEstimate out = s;
  if (dt == 0.0) return out;
  Eigen::Matrix2d f;
  f << 1.0, dt, 0.0, 1.0;
  Eigen::Matrix2d q;
  const double adt = std::abs(dt);
  q << adt * adt * adt / 3.0, adt * adt / 2.0, adt * adt / 2.0, adt;
  q *= accel_psd;
  const int axes = s.dims >= 3 ? 3 : 2;
  StateEstimate::Mat big_f = StateEstimate::Mat::Identity();
  for (int k = 0; k < axes; ++k) big_f.block<2, 2>(2 * k, 2 * k) = f;
  out.x = big_f * s.x;
  out.P = big_f * s.P * big_f.transpose();
  for (int k = 0; k < axes; ++k) out.P.block<2, 2>(2 * k, 2 * k) += q;
  return out;
}

}  // namespace skytrack::fusion
