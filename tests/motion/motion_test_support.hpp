#pragma once
// Helpers shared by the motion-model tests.
#include <functional>

#include <Eigen/Eigenvalues>

#include "skytrack/filter/state.hpp"

namespace skytrack::test {

/// Simpson's rule for a matrix-valued integrand on [0, t].
inline StateMat integrate(const std::function<StateMat(double)>& f, double t,
                          int intervals = 2000) {
  const double h = t / intervals;
  StateMat sum = f(0.0) + f(t);
  for (int k = 1; k < intervals; ++k) sum += (k % 2 == 1 ? 4.0 : 2.0) * f(k * h);
  return sum * h / 3.0;
}

/// Q(T) = integral_0^T F(s) Qc F(s)' ds: the exact discretisation of a linear model driven by
/// continuous white noise of spectral density Qc.
inline StateMat van_loan_noise(const std::function<StateMat(double)>& transition,
                               const StateMat& continuous_noise, double t) {
  return integrate(
      [&](double s) -> StateMat {
        const StateMat F = transition(s);
        return F * continuous_noise * F.transpose();
      },
      t);
}

inline double min_eigenvalue(const StateMat& m) {
  const Eigen::MatrixXd dense = m;
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(dense).eigenvalues().minCoeff();
}

inline StateLayout make_layout(int dims, bool acceleration = false, bool turn_rate = false) {
  StateLayout layout;
  layout.dims = dims;
  layout.acceleration = acceleration;
  layout.turn_rate = turn_rate;
  return layout;
}

}  // namespace skytrack::test
