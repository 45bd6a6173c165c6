#pragma once
// Small helpers shared by the point tracker's translation units (not installed).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include "skytrack/core/track_report.hpp"
#include "skytrack/filter/state.hpp"

namespace skytrack::tracking_detail {

/// sqrt of the largest eigenvalue of the position block [m].
inline double position_spread(const Gaussian& g, int dims) {
  Eigen::Matrix3d pos = Eigen::Matrix3d::Zero();
  for (int a = 0; a < dims; ++a) {
    for (int b = 0; b < dims; ++b) pos(a, b) = g.covariance(2 * a, 2 * b);
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  eig.computeDirect(pos, Eigen::EigenvaluesOnly);  // closed form: called per track per batch
  return std::sqrt(std::max(0.0, eig.eigenvalues().maxCoeff()));
}

inline Eigen::Vector3d position_of(const StateVec& x, int dims) {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (int a = 0; a < dims; ++a) p[a] = x[StateLayout::position(a)];
  return p;
}

inline Eigen::Vector3d velocity_of(const StateVec& x, int dims) {
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  for (int a = 0; a < dims; ++a) v[a] = x[StateLayout::velocity(a)];
  return v;
}

inline void add_event(TrackFrame& frame, const char* type, std::int64_t track, std::string detail) {
  frame.events.push_back({type, track, std::move(detail)});
}

}  // namespace skytrack::tracking_detail
