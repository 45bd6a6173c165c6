#pragma once
// Test helpers for the JPDA family: brute-force enumeration of every feasible joint event
// with the textbook weight (lambda^(m - d), NOT the solvers' divided form) and cluster
// generators with fixed seeds.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include <Eigen/Core>

#include "skytrack/association/jpda_problem.hpp"

namespace skytrack::test {

struct JointEvent {
  std::vector<int> plot_of_track;  // -1 = undetected
  double weight = 0.0;
};

struct BruteForceJpda {
  Eigen::MatrixXd beta;  // tracks x (plots + 1)
  double total = 0.0;
  std::vector<JointEvent> events;  // every event with weight > 0, enumeration order
};

namespace detail {

inline void enumerate(const JpdaProblem& p, int t, std::vector<int>& plot_of_track,
                      std::vector<char>& used, BruteForceJpda& out) {
  const int tracks = static_cast<int>(p.likelihood.rows());
  const int plots = static_cast<int>(p.likelihood.cols());
  if (t == tracks) {
    double w = 1.0;
    int detected = 0;
    for (int u = 0; u < tracks; ++u) {
      const int j = plot_of_track[static_cast<std::size_t>(u)];
      w *= j < 0 ? p.miss(u) : p.likelihood(u, j);
      detected += j < 0 ? 0 : 1;
    }
    w *= std::pow(p.clutter_density, plots - detected);  // eq. of jpda_problem.hpp
    if (w > 0.0) out.events.push_back({plot_of_track, w});
    return;
  }
  plot_of_track[static_cast<std::size_t>(t)] = -1;
  enumerate(p, t + 1, plot_of_track, used, out);
  for (int j = 0; j < plots; ++j) {
    if (used[static_cast<std::size_t>(j)] != 0 || !(p.likelihood(t, j) > 0.0)) continue;
    used[static_cast<std::size_t>(j)] = 1;
    plot_of_track[static_cast<std::size_t>(t)] = j;
    enumerate(p, t + 1, plot_of_track, used, out);
    used[static_cast<std::size_t>(j)] = 0;
  }
}

}  // namespace detail

inline BruteForceJpda brute_force_jpda(const JpdaProblem& p) {
  const int tracks = static_cast<int>(p.likelihood.rows());
  const int plots = static_cast<int>(p.likelihood.cols());
  BruteForceJpda out;
  std::vector<int> plot_of_track(static_cast<std::size_t>(tracks), -1);
  std::vector<char> used(static_cast<std::size_t>(plots), 0);
  detail::enumerate(p, 0, plot_of_track, used, out);
  out.beta = Eigen::MatrixXd::Zero(tracks, plots + 1);
  for (const JointEvent& e : out.events) {
    out.total += e.weight;
    for (int t = 0; t < tracks; ++t)
      out.beta(t, 1 + e.plot_of_track[static_cast<std::size_t>(t)]) += e.weight;
  }
  if (out.total > 0.0) out.beta /= out.total;
  return out;
}

/// Random cluster: each pair gated with a random probability, likelihoods and miss weights
/// random; occasionally a miss weight of 0 (PD * PG = 1).
inline JpdaProblem random_problem(int tracks, int plots, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double density = 0.2 + 0.7 * unit(rng);
  JpdaProblem p;
  p.likelihood = Eigen::MatrixXd::Zero(tracks, plots);
  p.miss = Eigen::VectorXd::Zero(tracks);
  for (int t = 0; t < tracks; ++t) {
    for (int j = 0; j < plots; ++j) {
      if (unit(rng) < density) p.likelihood(t, j) = 0.05 + 3.0 * unit(rng);
    }
    p.miss(t) = unit(rng) < 0.1 ? 0.0 : 0.05 + 0.5 * unit(rng);
  }
  p.clutter_density = 0.3 + 1.7 * unit(rng);
  return p;
}

/// Realistic cluster: `tracks` targets on a line `spacing` apart (units of the innovation
/// sigma, S = I in 2-D), each detected with PD = 0.9 at N(predicted, I), Poisson clutter of
/// density `clutter_density` [1/sigma^2], gate nu'nu <= 9.21 (PG = 0.99). Plots gated by no
/// track are dropped.
inline JpdaProblem chain_cluster(int tracks, double spacing, double clutter_density,
                                 std::mt19937_64& rng) {
  constexpr double kPd = 0.9, kPg = 0.99, kGate = 9.21, kMargin = 4.0;
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Eigen::Vector2d> predicted, plots;
  for (int t = 0; t < tracks; ++t) predicted.emplace_back(t * spacing, 0.3 * normal(rng));
  for (const Eigen::Vector2d& x : predicted) {
    if (unit(rng) < kPd) {
      // Each draw is its own step, last argument first: the order GCC used when the scenes were
      // measured (C++ leaves the evaluation order of arguments unspecified).
      const double dy = normal(rng), dx = normal(rng);
      plots.emplace_back(x + Eigen::Vector2d(dx, dy));
    }
  }
  const double width = (tracks - 1) * spacing + 2.0 * kMargin, height = 2.0 * kMargin;
  std::poisson_distribution<int> clutter(clutter_density * width * height);
  for (int n = clutter(rng); n > 0; --n) {
    const double uy = unit(rng), ux = unit(rng);
    plots.emplace_back(-kMargin + width * ux, -kMargin + height * uy);
  }
  std::vector<std::vector<double>> columns;
  for (const Eigen::Vector2d& z : plots) {
    std::vector<double> column(static_cast<std::size_t>(tracks), 0.0);
    bool gated = false;
    for (int t = 0; t < tracks; ++t) {
      const double d2 = (z - predicted[static_cast<std::size_t>(t)]).squaredNorm();
      if (d2 > kGate) continue;
      column[static_cast<std::size_t>(t)] = kPd * std::exp(-0.5 * d2) / (2.0 * std::numbers::pi);
      gated = true;
    }
    if (gated) columns.push_back(column);
  }
  JpdaProblem p;
  p.likelihood = Eigen::MatrixXd::Zero(tracks, static_cast<Eigen::Index>(columns.size()));
  for (std::size_t j = 0; j < columns.size(); ++j) {
    for (int t = 0; t < tracks; ++t) {
      p.likelihood(t, static_cast<Eigen::Index>(j)) = columns[j][static_cast<std::size_t>(t)];
    }
  }
  p.miss = Eigen::VectorXd::Constant(tracks, 1.0 - kPd * kPg);
  p.clutter_density = clutter_density;
  return p;
}

}  // namespace skytrack::test
