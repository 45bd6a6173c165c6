#pragma once
// Helpers shared by the filter tests.
#include <Eigen/Core>

#include "skytrack/filter/imm_filter.hpp"
#include "skytrack/filter/state.hpp"
#include "skytrack/measurement/plot_measurement.hpp"

namespace skytrack::test {

inline StateLayout layout_2d() {
  return StateLayout{2, false, false};
}
inline StateLayout layout_3d() {
  return StateLayout{3, false, false};
}

/// A Cartesian (x, y) plot measurement of a 2-D state.
inline PlotMeasurement cartesian_xy(double x, double y, double sigma, std::int64_t id = 0) {
  MeasVec z(2), s(2);
  z << x, y;
  s << sigma, sigma;
  return {MeasurementModel::cartesian(2, 2, s), z, 0.0, id};
}

/// A polar (range, azimuth) measurement from a level platform at the origin (2-D tracker).
inline PlotMeasurement polar_2d(double range, double azimuth, double sigma_r, double sigma_a) {
  MeasVec z(2), s(2);
  z << range, azimuth;
  s << sigma_r, sigma_a;
  return {MeasurementModel::polar(PlatformState{}, false, false, 2, s), z, 0.0, 0};
}

inline Gaussian gaussian(std::initializer_list<double> mean, const StateMat& covariance) {
  Gaussian g;
  g.mean.resize(static_cast<Eigen::Index>(mean.size()));
  Eigen::Index i = 0;
  for (double v : mean) g.mean[i++] = v;
  g.covariance = covariance;
  return g;
}

/// Two modes' estimates at time 0 that differ, mu = (0.7, 0.3): the scenario of the IMM's
/// hand computation.
inline ImmEstimate two_mode_posterior() {
  ImmEstimate posterior;
  StateMat P1 = StateMat::Zero(4, 4), P2 = StateMat::Zero(4, 4);
  P1.diagonal() << 4, 1, 4, 1;
  P2.diagonal() << 9, 4, 9, 4;
  posterior.modes = {gaussian({0, 10, 0, 0}, P1), gaussian({2, 12, 1, -1}, P2)};
  posterior.probabilities = Eigen::Vector2d(0.7, 0.3);
  posterior.time = 0.0;
  return posterior;
}

}  // namespace skytrack::test
