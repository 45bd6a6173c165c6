// Measurement-driven birth proposal of paper 001 (eq. 22-23): single plots with a velocity
// prior (the paper's m_b / Q_b velocity) or two-point initiation from plot pairs.
#include "skytrack/bernoulli/birth_proposal.hpp"

#include <algorithm>

namespace skytrack::bernoulli {
namespace {

/// The plot's position with a draw of its measurement noise (first order in the azimuth
/// error: at sigma 3 mrad the curvature term is below a millimetre at 25 km).
Eigen::Vector2d noisy_position(const ScanPlot& plot, NormalSampler& rng) noexcept {
  const double a = plot.sigma_along * rng.normal();
  const double c = plot.sigma_across * rng.normal();
  return plot.position + a * plot.along + c * plot.across;
}

}  // namespace

BirthProposalSampler::BirthProposalSampler(const BernoulliSpec& spec) : spec_(spec) {
  seeds_.reserve(static_cast<std::size_t>(std::max(spec.birth_particles, 1)));
}

void BirthProposalSampler::choose_seeds(std::span<const ScanPlot> previous,
                                        std::span<const ScanPlot> before_previous, double pair_dt,
                                        std::size_t capacity, NormalSampler& rng) noexcept {
  seeds_.clear();
  previous_ = previous;
  before_previous_ = before_previous;
  pair_dt_ = pair_dt;
  // Reservoir sampling keeps a uniform subset when the seeds exceed the capacity.
  std::size_t seen = 0;
  const auto offer = [&](Seed seed) {
    ++seen;
    if (seeds_.size() < capacity) {
      seeds_.push_back(seed);
      return;
    }
    const std::uint32_t slot = rng.index(static_cast<std::uint32_t>(seen));
    if (slot < capacity) seeds_[slot] = seed;
  };
  if (capacity == 0) return;
  if (spec_.birth_proposal == BirthProposal::kVelocityPrior) {
    for (std::size_t i = 0; i < previous.size(); ++i) offer({static_cast<int>(i), -1});
    return;
  }
  if (!(pair_dt > 0.0)) return;
  for (std::size_t i = 0; i < previous.size(); ++i) {
    for (std::size_t j = 0; j < before_previous.size(); ++j) {
      const double slack =
          3.0 * (std::max(previous[i].sigma_along, previous[i].sigma_across) +
                 std::max(before_previous[j].sigma_along, before_previous[j].sigma_across));
      const double reach = spec_.max_birth_speed * pair_dt + slack;
      if ((previous[i].position - before_previous[j].position).squaredNorm() <= reach * reach) {
        offer({static_cast<int>(i), static_cast<int>(j)});
      }
    }
  }
}

void BirthProposalSampler::sample(std::span<Particle> out, NormalSampler& rng) const noexcept {
  const std::size_t n = out.size();
  for (std::size_t s = 0; s < seeds_.size(); ++s) {
    const ScanPlot& newer = previous_[static_cast<std::size_t>(seeds_[s].newer)];
    for (std::size_t k = group_begin(s, n); k < group_begin(s + 1, n); ++k) {
      const Eigen::Vector2d p = noisy_position(newer, rng);
      Eigen::Vector2d v;
      if (seeds_[s].older >= 0) {
        const ScanPlot& older = before_previous_[static_cast<std::size_t>(seeds_[s].older)];
        v = (p - noisy_position(older, rng)) / pair_dt_;
      } else {
        // Each draw is its own step, last argument first: the order GCC used when the figures were
        // measured (C++ leaves the evaluation order of arguments unspecified).
        const double e_y = rng.normal(), e_x = rng.normal();
        v = Eigen::Vector2d(spec_.birth_velocity[0] + spec_.birth_velocity_sigma * e_x,
                            spec_.birth_velocity[1] + spec_.birth_velocity_sigma * e_y);
      }
      out[k] = {p.x(), v.x(), p.y(), v.y()};
    }
  }
}

}  // namespace skytrack::bernoulli
