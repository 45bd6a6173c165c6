#pragma once
// Small helpers shared by the point tracker's translation units (not installed).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include "skytrack/config/profile.hpp"
#include "skytrack/core/track_report.hpp"
#include "skytrack/filter/imm_filter.hpp"
#include "skytrack/filter/state.hpp"
#include "skytrack/measurement/plot_measurement.hpp"

namespace skytrack::tracking_detail {

/// Position components the track-life spread test (track_life.delete_position_sigma)
/// measures: the horizontal ones. A 3-D track's height may never be measured (a secondary
/// radar's replies without Mode C, a primary radar's plots among them): that leaves it no less
/// a track, yet its unknown height's spread (3 km at the start, growing) would delete it.
inline constexpr int kLifeSpreadDims = 2;

/// sqrt of the largest eigenvalue of the position block [m].
inline double position_spread(const Gaussian& g, int dims) {
  if (dims <= 2) {
    // The larger root of the 2x2 characteristic polynomial: no trigonometry (the 3x3 closed
    // form takes an atan2 and a sincos), called per mode of every track in every look.
    const double a = g.covariance(0, 0);
    const double d = dims == 2 ? g.covariance(2, 2) : 0.0;
    const double b = dims == 2 ? g.covariance(0, 2) : 0.0;
    const double h = 0.5 * (a - d);
    const double largest = 0.5 * (a + d) + std::sqrt(h * h + b * b);
    return std::sqrt(std::max(0.0, largest));
  }
  Eigen::Matrix3d pos = Eigen::Matrix3d::Zero();
  for (int a = 0; a < dims; ++a) {
    for (int b = 0; b < dims; ++b) pos(a, b) = g.covariance(2 * a, 2 * b);
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  eig.computeDirect(pos, Eigen::EigenvaluesOnly);  // closed form: called per track per batch
  return std::sqrt(std::max(0.0, eig.eigenvalues().maxCoeff()));
}

/// The mode-weighted spread sqrt(sum_j mu_j spread_j^2) of an IMM estimate's own modes:
/// the size of its gates (a union of per-mode gates), without the spread between the modes'
/// means, which grows by kilometres when turn modes coast but does not widen any mode's gate.
inline double mode_spread(const ImmEstimate& estimate, int dims) {
  double sum = 0.0;
  for (std::size_t j = 0; j < estimate.modes.size(); ++j) {
    const double s = position_spread(estimate.modes[j], dims);
    sum += estimate.probabilities[static_cast<Eigen::Index>(j)] * s * s;
  }
  return std::sqrt(sum);
}

/// Paper 003 §2.2: a track-plot pair is a valid association when its probability exceeds
/// the track's miss probability; a track has one when any of its pairs is valid.
inline bool valid_association(std::span<const double> beta, double miss) {
  return std::any_of(beta.begin(), beta.end(), [miss](double b) { return b > miss; });
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

/// A plot -> track decision of this frame; the plot's batch is named when it is not the
/// frame's (a plot held over to a later look).
inline void add_association(TrackFrame& frame, std::int64_t track, std::int64_t plot_id,
                            std::uint64_t plot_scan, double probability) {
  frame.associations.push_back({track, plot_id, probability, std::nullopt});
  if (plot_scan != frame.scan) frame.associations.back().scan = plot_scan;
}

/// Looks at a target between two of its plots (0: the same look), from the antenna's sweep.
inline int looks_between(double sweep_a, double sweep_b) {
  return static_cast<int>(std::lround(std::abs(sweep_b - sweep_a) / (2.0 * 3.141592653589793)));
}

/// Holds an event of this look until the look has decided it (PointLook::events).
inline void add_event(std::vector<TrackEvent>& held, TrackEventType type, std::int64_t track,
                      std::string detail) {
  held.push_back({type, track, std::move(detail), {}});
}

/// A later decision of the batch supersedes `track`'s held events of `type` (a "confirmed"
/// that §3.3 makes a lost father's continuation, a "deleted" undone by the branch that
/// replaces the father): they are never emitted.
inline void supersede(std::vector<TrackEvent>& held, TrackEventType type, std::int64_t track) {
  std::erase_if(held, [&](const TrackEvent& e) { return e.type == type && e.track == track; });
}

using Clock = std::chrono::steady_clock;

inline std::chrono::microseconds since(Clock::time_point start) {
  return std::chrono::duration_cast<std::chrono::microseconds>(Clock::now() - start);
}

// Association weights below this are not worth a Kalman update; below the second they are not
// reported in the output's associations.
inline constexpr double kNegligibleBeta = 1e-4;
inline constexpr double kAssociationReportThreshold = 1e-3;
// The manoeuvre kinds' probabilities only choose which branches to start, so their clusters
// (wide gates, chained in dense clutter) get a cheaper exact attempt and fewer joint events.
inline constexpr int kManoeuvreKBest = 10;
inline constexpr std::int64_t kManoeuvreExactStates = std::int64_t{1} << 12;
// Murty's k-best costs about k x tracks^2 x (tracks + plots): seconds for the clusters of
// hundreds of tracks a flood of random plots chains together, where k joint events are a
// vanishing share of the whole anyway. Clusters of more than this many times the exact limit
// take per-track PDA, the bound on a batch's association work.
inline constexpr int kKBestClusterFactor = 2;
// Height spread of a track started from plots without height [m].
inline constexpr double kUnknownHeightSigma = 3000.0;
// Acceleration spread of a new track, where the layout has acceleration states [m/s^2].
inline constexpr double kInitialAccelerationSigma = 10.0;

/// True when the plot measures height (elevation, z or altitude).
inline bool measures_height(const PlotMeasurement& plot) {
  return plot.model.position_components == 3;
}

}  // namespace skytrack::tracking_detail
