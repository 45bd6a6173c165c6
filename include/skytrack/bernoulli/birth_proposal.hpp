#pragma once
// Birth particles from a proposal round the measurements (paper 001, eq. 22-23, q_b(.|Z)):
// a newborn target sits on a plot of the previous scan (scan k-1), so the current scan's
// plots test it and no plot supports its own birth (adaptive birth, Ristic, Clark, Vo & Vo
// 2012). The birth density is taken equal to the proposal, so b / q_b = 1 in eq. 23.
#include <cstdint>
#include <span>
#include <vector>

#include "skytrack/bernoulli/bernoulli_spec.hpp"
#include "skytrack/bernoulli/normal_sampler.hpp"
#include "skytrack/bernoulli/particle_kernel.hpp"

namespace skytrack::bernoulli {

class BirthProposalSampler {
 public:
  explicit BirthProposalSampler(const BernoulliSpec& spec);

  /// This scan's seeds: every plot of scan k-1 (kVelocityPrior), or every pair of a scan k-2
  /// and a scan k-1 plot within max_birth_speed (kPlotPairs; pair_dt = t(k-1) - t(k-2)).
  /// Beyond `capacity` seeds, a random subset of `capacity` is kept.
  void choose_seeds(std::span<const ScanPlot> previous, std::span<const ScanPlot> before_previous,
                    double pair_dt, std::size_t capacity, NormalSampler& rng) noexcept;
  std::size_t seed_count() const noexcept { return seeds_.size(); }

  /// Fills `out` with newborn particles at the time of scan k-1, seed s filling
  /// [group_begin(s, n), group_begin(s + 1, n)) of the n = out.size() particles.
  void sample(std::span<Particle> out, NormalSampler& rng) const noexcept;
  std::size_t group_begin(std::size_t seed, std::size_t n) const noexcept {
    return seeds_.empty() ? 0 : seed * n / seeds_.size();
  }

 private:
  struct Seed {
    int newer = 0;   // index in the scan k-1 plots
    int older = -1;  // index in the scan k-2 plots (kPlotPairs)
  };

  BernoulliSpec spec_;
  std::vector<Seed> seeds_;
  std::span<const ScanPlot> previous_, before_previous_;
  double pair_dt_ = 1.0;
};

}  // namespace skytrack::bernoulli
