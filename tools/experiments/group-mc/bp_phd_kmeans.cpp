// BP-PHD and MS-BP-PHD with k-means state extraction (paper 000 §4.1 baselines).
#include "bp_phd_kmeans.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "skytrack/group/group_tracker.hpp"

namespace group_mc {
namespace {

using skytrack::group::PlaneBox;

skytrack::config::ClutterRejectionSpec preprocessing(const GroupSpec& spec, bool mean_shift,
                                                     double distance) {
  if (mean_shift) {
    return spec.preprocessing;
  }
  // No rejection, no mean-shift steps: the converged points are the plots, and merging them
  // within `distance` is single-linkage distance partitioning.
  skytrack::config::ClutterRejectionSpec s = spec.preprocessing;
  s.enabled = false;
  s.mean_shift.max_iterations = 0;
  s.mean_shift.merge_distance = distance;
  return s;
}

}  // namespace

BpPhdKmeans::BpPhdKmeans(const GroupSpec& spec, bool mean_shift, double partition_distance,
                         KmeansInit init)
    : spec_(spec),
      init_(init),
      partitioner_(preprocessing(spec, mean_shift, partition_distance)),
      rng_(spec.seed) {}

double BpPhdKmeans::uniform(double lo, double hi) {
  const double u = static_cast<double>(rng_() >> 11) * 0x1.0p-53;
  return lo + (hi - lo) * u;
}

const std::vector<BoxVec>& BpPhdKmeans::step(double time, std::span<const Eigen::Vector3d> plots) {
  const double dt = has_time_ ? std::max(time - last_time_, 0.0) : 0.0;
  has_time_ = true;
  last_time_ = time;
  const BoxVec nominal(0.5 * spec_.position_width, 0.5 * spec_.velocity_width,
                       0.5 * spec_.position_width, 0.5 * spec_.velocity_width);
  // Births: n2 at each previous estimate, n1 at each previous measurement box (ref. 15).
  for (const BoxVec& e : estimates_) {
    for (int k = 0; k < spec_.births_per_estimate; ++k) {
      BoxParticle b;
      b.half = nominal;
      for (int j = 0; j < 4; ++j) {
        b.centre(j) = e(j) + uniform(-1.0, 1.0) * spec_.jitter * nominal(j);
      }
      b.weight = 1.0 / spec_.boxes_per_group;
      particles_.push_back(b);
    }
  }
  for (const PlaneBox& z : previous_cells_) {
    for (int k = 0; k < spec_.births_per_box; ++k) {
      BoxParticle b;
      b.centre(0) = uniform(z.lower.x(), z.upper.x());
      b.centre(2) = uniform(z.lower.y(), z.upper.y());
      b.half(0) = std::max(nominal(0), 0.5 * (z.upper.x() - z.lower.x()));
      b.half(2) = std::max(nominal(2), 0.5 * (z.upper.y() - z.lower.y()));
      b.half(1) = b.half(3) = spec_.birth_speed;
      b.weight = spec_.birth_mass_per_box / spec_.births_per_box;
      particles_.push_back(b);
    }
  }
  // Predict, update, contract (eq. 14-26).
  const auto F = skytrack::group::group_transition(spec_.motion, spec_.turn_rate, dt);
  prior_centre_.resize(particles_.size());
  prior_half_.resize(particles_.size());
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    prior_centre_[i] = particles_[i].centre;
    prior_half_[i] = particles_[i].half;
    skytrack::group::predict_box(F, particles_[i]);
    particles_[i].weight *= spec_.survival_probability;
  }
  const auto& parts = partitioner_.partition(plots, 2);
  skytrack::group::make_cells(plots, parts, spec_.measurement_box_padding, cells_);
  std::vector<PlaneBox> boxes;
  std::vector<double> clutter;
  for (const auto& c : cells_) {
    boxes.push_back(c.box);
    clutter.push_back(spec_.clutter_rate * c.box.area() / spec_.surveillance_area);
  }
  skytrack::group::phd_update(particles_, boxes, clutter, spec_.detection_probability, 0, update_);
  group_count_ = 0.0;
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    const int j = update_.best_cell[i];
    if (j >= 0) {
      skytrack::group::contract_box(F, prior_centre_[i], prior_half_[i],
                                    boxes[static_cast<std::size_t>(j)], particles_[i]);
    }
    group_count_ += particles_[i].weight;
  }
  // Resample to N_box per estimated group, re-inflate, jitter; then k-means.
  const int k = static_cast<int>(std::lround(group_count_));
  std::vector<double> weights;
  for (const auto& p : particles_) {
    weights.push_back(p.weight);
  }
  std::vector<int> picks;
  skytrack::group::systematic_resample(weights, std::max(k, 0) * spec_.boxes_per_group,
                                       uniform(0.0, 1.0), picks);
  std::vector<BoxParticle> next;
  for (const int i : picks) {
    BoxParticle b = particles_[static_cast<std::size_t>(i)];
    for (int j = 0; j < 4; ++j) {
      b.centre(j) += uniform(-1.0, 1.0) * spec_.jitter * nominal(j);
    }
    b.half = nominal;
    b.weight = group_count_ / static_cast<double>(picks.size());
    next.push_back(b);
  }
  particles_.swap(next);
  kmeans(k);
  previous_cells_ = boxes;
  return estimates_;
}

// Lloyd's k-means over the box centres' positions, 20 iterations, seeded as init_ says.
void BpPhdKmeans::kmeans(int k) {
  estimates_.clear();
  const std::size_t n = particles_.size();
  if (k <= 0 || n == 0) {
    return;
  }
  const auto pos = [&](std::size_t i) {
    return Eigen::Vector2d(particles_[i].centre(0), particles_[i].centre(2));
  };
  std::vector<Eigen::Vector2d> centres;
  centres.push_back(pos(static_cast<std::size_t>(uniform(0.0, 1.0) * n) % n));
  std::vector<double> d2(n);
  while (init_ == KmeansInit::kRandom && static_cast<int>(centres.size()) < k) {
    centres.push_back(pos(static_cast<std::size_t>(uniform(0.0, 1.0) * n) % n));
  }
  while (static_cast<int>(centres.size()) < k) {
    double total = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      double best = std::numeric_limits<double>::infinity();
      for (const auto& c : centres) {
        best = std::min(best, (pos(i) - c).squaredNorm());
      }
      d2[i] = best;
      total += best;
    }
    double target = uniform(0.0, total);
    std::size_t pick = 0;
    for (; pick + 1 < n && target > d2[pick]; ++pick) {
      target -= d2[pick];
    }
    centres.push_back(pos(pick));
  }
  assignment_.assign(n, 0);
  for (int iteration = 0; iteration < 20; ++iteration) {
    for (std::size_t i = 0; i < n; ++i) {
      double best = std::numeric_limits<double>::infinity();
      for (int c = 0; c < k; ++c) {
        const double d = (pos(i) - centres[static_cast<std::size_t>(c)]).squaredNorm();
        if (d < best) {
          best = d;
          assignment_[i] = c;
        }
      }
    }
    std::vector<Eigen::Vector2d> sum(static_cast<std::size_t>(k), Eigen::Vector2d::Zero());
    std::vector<int> count(static_cast<std::size_t>(k), 0);
    for (std::size_t i = 0; i < n; ++i) {
      sum[static_cast<std::size_t>(assignment_[i])] += pos(i);
      ++count[static_cast<std::size_t>(assignment_[i])];
    }
    for (int c = 0; c < k; ++c) {
      if (count[static_cast<std::size_t>(c)] > 0) {
        centres[static_cast<std::size_t>(c)] =
            sum[static_cast<std::size_t>(c)] / count[static_cast<std::size_t>(c)];
      }
    }
  }
  std::vector<BoxVec> state(static_cast<std::size_t>(k), BoxVec::Zero());
  std::vector<int> count(static_cast<std::size_t>(k), 0);
  for (std::size_t i = 0; i < n; ++i) {
    state[static_cast<std::size_t>(assignment_[i])] += particles_[i].centre;
    ++count[static_cast<std::size_t>(assignment_[i])];
  }
  for (int c = 0; c < k; ++c) {
    if (count[static_cast<std::size_t>(c)] > 0) {
      estimates_.push_back(state[static_cast<std::size_t>(c)] / count[static_cast<std::size_t>(c)]);
    }
  }
}

}  // namespace group_mc
