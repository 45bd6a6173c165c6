#pragma once
// The IMMBPF baseline of paper 001 (its refs. [11], [12]): a Bernoulli particle filter on
// the state augmented with the model index. Each particle draws its next model from the
// Markov chain (eq. 2) and is predicted by it (the particles interact across models), one
// resampling runs over the whole cloud, so the particles of each model vary in number, and
// the model probabilities are sums of particle weights: the scheme the MMBPF improves on.
// Same spec, existence recursion (eq. 9, 13), births and outputs (eq. 28) as the MMBPF;
// the cloud holds model_count x particles_per_model particles.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "skytrack/bernoulli/bernoulli_estimate.hpp"
#include "skytrack/bernoulli/bernoulli_spec.hpp"
#include "skytrack/bernoulli/birth_proposal.hpp"
#include "skytrack/bernoulli/normal_sampler.hpp"
#include "skytrack/bernoulli/particle_kernel.hpp"
#include "skytrack/bernoulli/plot_history.hpp"
#include "skytrack/bernoulli/scan_book.hpp"

namespace skytrack::bernoulli {

class ImmBernoulliFilter {
 public:
  /// The models' own `particles` are ignored; birth_particles are drawn per model.
  ImmBernoulliFilter(const BernoulliSpec& spec, int particles_per_model);

  BernoulliEstimate step(double time, const Eigen::Vector2d& platform,
                         std::span<const PolarPlot2d> plots) noexcept;
  BernoulliEstimate step(double time, const Eigen::Vector2d& platform,
                         std::span<const PlotMeasurement> plots) noexcept;
  const BernoulliEstimate& last() const noexcept { return book_.last(); }

 private:
  BernoulliEstimate begin_scan(double time, int rejected) noexcept;
  void recurse(double dt, BernoulliEstimate& estimate) noexcept;
  std::size_t predict(double survival_mass, const std::array<double, kMaxModels>& birth_mass,
                      double q_predicted, double dt) noexcept;
  void estimate_and_resample(std::size_t count, BernoulliEstimate& estimate) noexcept;

  BernoulliSpec spec_;
  NormalSampler rng_;
  PlotHistory history_;
  BirthProposalSampler births_;
  std::vector<Particle> posterior_, work_, newborn_;
  std::vector<std::uint8_t> posterior_model_, work_model_;
  std::vector<double> weight_, ratio_;
  std::array<std::size_t, kMaxModels + 1> birth_begin_{};  // births of model j in the work cloud
  double q_ = 0.0;
  bool has_posterior_ = false;
  ScanBook book_{1};
};

}  // namespace skytrack::bernoulli
