// Paper 002's experiment: simulation and Monte Carlo runner (see paper_scenario.hpp).
#include "paper_scenario.hpp"

#include <cmath>
#include <numbers>

#include "skytrack/extended/ellipse_geometry.hpp"
#include "skytrack/extended/extended_estimator.hpp"
#include "skytrack/metrics/gaussian_wasserstein.hpp"

namespace skytrack::extended::experiment {
namespace {

double turn_rate_at(const PaperScenario& s, double t) {
  const double w = s.turn_rate * std::numbers::pi / 180.0;
  if (t >= 30.0 && t < 70.0) return w;
  if (t >= 90.0 && t < 130.0) return -w;
  return 0.0;
}

Eigen::Vector2d uniform_in_disc(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double r = std::sqrt(u(rng));
  const double phi = 2.0 * std::numbers::pi * u(rng);
  return {r * std::cos(phi), r * std::sin(phi)};
}

Eigen::Matrix2d sqrt_psd(const Eigen::Matrix2d& S) {
  const EllipseAxes a = ellipse_axes(S);
  const double c = std::cos(a.orientation), s = std::sin(a.orientation);
  Eigen::Matrix2d R;
  R << c, -s, s, c;
  return R * Eigen::Vector2d(a.major, a.minor).asDiagonal() * R.transpose();
}

}  // namespace

std::vector<ObjectTruth> paper_truth(const PaperScenario& s) {
  std::vector<ObjectTruth> truth;
  Eigen::Vector2d p = s.start_position;
  const double speed = s.start_velocity.norm();
  double heading = std::atan2(s.start_velocity.y(), s.start_velocity.x());
  constexpr int kSubsteps = 100;  // exact coordinated turn per substep
  for (double t = 0.0; t <= s.duration + 1e-9; t += s.period) {
    const Eigen::Vector2d v = speed * Eigen::Vector2d(std::cos(heading), std::sin(heading));
    truth.push_back({t, p, v, shape_from_axes(s.major_axis, s.minor_axis, heading)});
    const double dt = s.period / kSubsteps;
    for (int i = 0; i < kSubsteps; ++i) {
      const double w = turn_rate_at(s, t + (i + 0.5) * dt);
      const double h1 = heading + w * dt;
      if (std::abs(w) > 1e-12) {
        p += speed / w *
             Eigen::Vector2d(std::sin(h1) - std::sin(heading), std::cos(heading) - std::cos(h1));
      } else {
        p += speed * dt * Eigen::Vector2d(std::cos(heading), std::sin(heading));
      }
      heading = h1;
    }
  }
  return truth;
}

void sample_object_plots(const ObjectTruth& truth, int count, const Eigen::Matrix2d& bound,
                         NoiseKind noise, std::mt19937_64& rng, std::vector<Eigen::Vector2d>& out) {
  const Eigen::Matrix2d object_root = sqrt_psd(truth.extent);
  const Eigen::Matrix2d noise_root = sqrt_psd(bound);
  std::normal_distribution<double> normal(0.0, 0.5);  // N(0, U / 4) = (U^1/2 / 2) N(0, I)
  for (int i = 0; i < count; ++i) {
    Eigen::Vector2d z = truth.position + object_root * uniform_in_disc(rng);
    if (noise == NoiseKind::kBounded) {
      z += noise_root * uniform_in_disc(rng);
    } else {
      // Each draw is its own step, last argument first: the order GCC used when the scenes were
      // measured (C++ leaves the evaluation order of arguments unspecified).
      const double ny = normal(rng), nx = normal(rng);
      z += noise_root * Eigen::Vector2d(nx, ny);
    }
    out.push_back(z);
  }
}

std::vector<FilterSetup> paper_filters(const PaperScenario& scenario,
                                       const Eigen::Matrix2d& bayes_noise, bool literal_smf) {
  ExtendedSpec base;
  base.motion.time_constant = 40.0;
  base.motion.accel_noise = 0.5;
  FilterSetup smf{"SMF-EOT", base, scenario.sensor_bound};
  smf.spec.kind = EstimatorKind::kSmf;
  smf.spec.smf.bound_sigmas = 1.0;  // the filter is given U itself
  FilterSetup rm{"random matrix", base, bayes_noise};
  rm.spec.kind = EstimatorKind::kRandomMatrix;
  FilterSetup mem{"MEM-EKF*", base, bayes_noise};
  mem.spec.kind = EstimatorKind::kMemEkf;
  if (literal_smf) {
    FilterSetup literal = smf;
    literal.name = "SMF-EOT, extent step as printed";
    literal.spec.smf.literal_extent = true;
    return {smf, literal, rm, mem};
  }
  return {smf, rm, mem};
}

McResult run_paper_monte_carlo(const PaperScenario& scenario, const FilterSetup& filter, int runs,
                               std::uint64_t seed) {
  const std::vector<ObjectTruth> truth = paper_truth(scenario);
  const int steps = static_cast<int>(truth.size());
  std::vector<double> pos_sq(steps, 0.0), vel_sq(steps, 0.0);
  double gwd_sq_sum = 0.0, gwd_sum = 0.0;
  ExtendedEstimator estimator(filter.spec);
  std::vector<Eigen::Vector2d> plots;
  // P0 as printed, in our state order [x, vx, y, vy, ax, ay].
  const KinMat P0 = (KinVec() << 70.0 * 70.0, 10.0 * 10.0, 70.0 * 70.0, 10.0 * 10.0, 25.0, 25.0)
                        .finished()
                        .asDiagonal();
  for (int run = 0; run < runs; ++run) {
    std::mt19937_64 rng(seed * 1000003ULL + static_cast<std::uint64_t>(run));
    std::poisson_distribution<int> count(scenario.mean_plots);
    KinVec x0 = KinVec::Zero();
    x0 << scenario.start_position.x(), scenario.start_velocity.x(), scenario.start_position.y(),
        scenario.start_velocity.y(), 0.0, 0.0;
    ExtendedObject object = estimator.initiate(x0, P0, Eigen::Matrix2d::Identity() * 100.0 * 100.0);
    for (int k = 0; k < steps; ++k) {
      if (k > 0) estimator.predict(object, truth[k].time - truth[k - 1].time);
      plots.clear();
      sample_object_plots(truth[k], count(rng), scenario.sensor_bound, scenario.noise, rng, plots);
      estimator.update(object, plots, filter.noise);
      pos_sq[k] += (object.position() - truth[k].position).squaredNorm();
      vel_sq[k] += (object.velocity() - truth[k].velocity).squaredNorm();
      const double d2 = metrics::gaussian_wasserstein_squared(truth[k].position, truth[k].extent,
                                                              object.position(), object.extent);
      gwd_sq_sum += d2;
      gwd_sum += std::sqrt(d2);
    }
  }
  McResult result;
  for (int k = 0; k < steps; ++k) {
    result.armse_position += std::sqrt(pos_sq[k] / runs) / steps;
    result.armse_velocity += std::sqrt(vel_sq[k] / runs) / steps;
  }
  result.mean_gwd_squared = gwd_sq_sum / (runs * steps);
  result.mean_gwd = gwd_sum / (runs * steps);
  return result;
}

}  // namespace skytrack::extended::experiment
