#pragma once
// The multiple-model Bernoulli particle filter, MMBPF (paper 001, Yang & Zhang 2017, §3):
// at most one target, its existence probability q (eq. 9, 13) and per motion model a fixed
// number of particles chosen by the model's manoeuvrability (BernoulliModelSpec::particles).
// Each scan, per model: the initial cloud is resampled from the previous posteriors of all
// models by the mixing probabilities (step 2, eq. 18-19) with no particle interaction,
// predicted by the model, joined by birth particles from a proposal round the previous
// scan's plots (eq. 22-23), weighted by l(x) (eq. 16, 26) and resampled back to its fixed
// count (block by block for the CV model when one plot explains its likelihood, see
// block_resampling.hpp; then regularised in velocity when its few lineages after a birth need
// it, see regularise_velocity); the model probabilities come from each model's likelihood 1 - Delta
// (eq. 17), and the output is the model-probability-weighted estimate (eq. 28), each model's
// velocity conditioned on its posterior mean position (velocity_given_position). 2-D: state [x, vx,
// y, vy] in the local ENU tracking frame. Deterministic for a seed.
#include <array>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "skytrack/bernoulli/bernoulli_estimate.hpp"
#include "skytrack/bernoulli/bernoulli_spec.hpp"
#include "skytrack/bernoulli/birth_proposal.hpp"
#include "skytrack/bernoulli/block_resampling.hpp"
#include "skytrack/bernoulli/normal_sampler.hpp"
#include "skytrack/bernoulli/particle_kernel.hpp"
#include "skytrack/bernoulli/plot_history.hpp"
#include "skytrack/bernoulli/scan_book.hpp"
#include "skytrack/measurement/plot_measurement.hpp"

namespace skytrack::bernoulli {

class MmBernoulliFilter {
 public:
  /// Allocates every buffer. The spec is used as given: model_count in [1, kMaxModels],
  /// particles >= 1 and transition rows summing to 1 are the caller's to check.
  explicit MmBernoulliFilter(const BernoulliSpec& spec);

  /// One scan at `time` [s] (after the previous scan's, else skipped and reported), from a
  /// sensor at `platform` (tracking frame; Cartesian plots only use it, polar plots carry
  /// their own platform). An empty scan is a scan in which nothing was detected.
  BernoulliEstimate step(double time, const Eigen::Vector2d& platform,
                         std::span<const PlotMeasurement> plots) noexcept;
  /// The same with plain polar plots about `platform`.
  BernoulliEstimate step(double time, const Eigen::Vector2d& platform,
                         std::span<const PolarPlot2d> plots) noexcept;

  const BernoulliEstimate& last() const noexcept { return book_.last(); }
  /// Back to no target and no history; the random engine continues.
  void reset() noexcept;

 private:
  BernoulliEstimate begin_scan(double time, int rejected) noexcept;
  void recurse(double dt, BernoulliEstimate& estimate) noexcept;
  std::size_t predict_model(int j, double survival_mass, double birth_mass,
                            const std::array<double, kMaxModels>& mu_predicted,
                            const ModelDynamics& dynamics) noexcept;
  double likelihood_integral(int j, std::size_t survivors, std::size_t count) noexcept;
  /// Model j's state estimate x_j of eq. 28 from its weighted mean `mean` and its survivors'
  /// weight and weighted mean: the survivors' velocity conditioned on their mean position.
  Eigen::Vector4d model_estimate(int j, const BlockMean& survivors,
                                 const Eigen::Vector4d& mean) const noexcept;
  /// Step 3(3) by blocks (block_resampling.hpp) when model j moves its blocks apart (CV), its
  /// survivors carry the posterior, one plot explains their likelihood and the predicted
  /// density is near the product of its blocks (kBlockShare, kBlockDependence): resamples them
  /// into posterior_[j] and gives x_j with their block mean as position. False: nothing done.
  bool block_resample_model(int j, const BlockMean& survivors, const Eigen::Vector4d& mean,
                            Eigen::Vector4d& estimate) noexcept;
  /// Eq. 26-28 and step 3(3): weights times l(x), model moments, resampling to N_j, output.
  void update_and_resample(const std::array<std::size_t, kMaxModels>& count, double dt,
                           BernoulliEstimate& estimate) noexcept;

  BernoulliSpec spec_;
  NormalSampler rng_;
  PlotHistory history_;
  BirthProposalSampler births_;
  std::array<std::vector<Particle>, kMaxModels> posterior_;  // N_j each, equal weights
  std::array<std::vector<Particle>, kMaxModels> work_;       // N_j + birth particles
  std::vector<Particle> newborn_;                            // birth cloud at scan k-1
  std::array<std::vector<double>, kMaxModels> weight_;
  std::array<std::vector<double>, kMaxModels> ratio_;  // sum_z g / kappa per particle
  std::array<double, kMaxModels> mu_{};                // mu_{k-1}
  // Per model this scan: its survivors' count and their predicted moments, exact from the
  // parents (the mixed particles before propagation) and the model's noise.
  std::array<std::size_t, kMaxModels> survivors_{};
  std::array<DominantPlot, kMaxModels> dominant_{};  // of the survivors' likelihood
  std::vector<double> block_scratch_;                // 2 N_j factor weights
  std::array<Eigen::Vector4d, kMaxModels> predicted_mean_{};
  std::array<Eigen::Matrix4d, kMaxModels> predicted_covariance_{};
  double q_ = 0.0;
  bool has_posterior_ = false;
  ScanBook book_{1};
};

}  // namespace skytrack::bernoulli
