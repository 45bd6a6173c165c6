// Paper 000 §3.2.7-3.2.9: label rules (eq. 29-30), per-label state extraction (eq. 31-32)
// and per-label resampling with re-inflation; plus the extent and member count of each
// label, estimated from the cells it took (docs/group.md).
#include <algorithm>
#include <cmath>
#include <cstddef>

#include <Eigen/Eigenvalues>

#include "skytrack/group/labeled_box_phd.hpp"

namespace skytrack::group {

// §3.2.7. A label is detected when its weight sum N-hat^m reaches chi'; otherwise l2 += 1
// and it dies when l2 > chi (double label) or at once (single label). A newborn set whose
// weight sum exceeds chi' becomes a new group l_max + 1, ... in cell order.
// With exclusive_cells (ours) the weight counted for that test is the target mass of the
// cells the slot owns, sum over all slots of their shares (eq. 24) of each owned cell: a
// cell detects one group. Two labels on one merged group then split its mass ~0.5 / 0.5,
// and the owner is detected while the other coasts and dies, instead of both missing.
void LabeledBoxPhd::apply_label_rules(std::span<const GroupCell> /*cells*/) noexcept {
  const std::size_t n_labels = labels_.size();
  const std::size_t slots = n_labels + previous_cells_.size();
  const double chi_prime = spec_.extraction_threshold;
  std::vector<double>& credit = credit_;
  if (spec_.exclusive_cells) {
    credit.assign(slots, 0.0);
    const std::size_t m = owner_.size();
    for (std::size_t j = 0; j < m; ++j) {
      if (owner_[j] < 0) {
        continue;
      }
      double cell_mass = 0.0;
      for (std::size_t s = 0; s < slots; ++s) {
        cell_mass += update_.shares[s * m + j];
      }
      credit[static_cast<std::size_t>(owner_[j])] += cell_mass;
    }
  } else {
    credit.assign(slot_mass_.begin(), slot_mass_.end());
  }
  slot_label_.assign(slots, 0);
  std::size_t kept = 0;
  for (std::size_t s = 0; s < n_labels; ++s) {
    LabelState ls = labels_[s];
    ls.slot = static_cast<int>(s);
    ls.detected = credit[s] >= chi_prime;
    if (ls.detected) {
      ls.missed = 0;
    } else {
      ++ls.missed;
      if (spec_.labels == LabelModel::kSingle || ls.missed > spec_.max_missed) {
        continue;  // dead: its boxes get l1 = 0 and are dropped at resampling
      }
    }
    slot_label_[s] = ls.label;
    labels_[kept++] = ls;
  }
  labels_.resize(kept);
  for (std::size_t s = n_labels; s < slots; ++s) {
    if (credit[s] > chi_prime) {
      LabelState ls;
      ls.label = next_label_++;
      ls.detected = true;
      ls.slot = static_cast<int>(s);
      slot_label_[s] = ls.label;
      labels_.push_back(ls);
    }
  }
}

// Pooled mean and covariance of the plots of the cells the slot owns, less the measurement
// noise, smoothed over the scans the label is detected in.
void LabeledBoxPhd::shape_update(LabelState& ls, int slot,
                                 std::span<const GroupCell> cells) noexcept {
  double n = 0.0;
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  Eigen::Matrix2d second = Eigen::Matrix2d::Zero();
  for (std::size_t j = 0; j < cells.size() && j < owner_.size(); ++j) {
    const GroupCell& c = cells[j];
    if (owner_[j] != slot || c.plots <= 0 || !c.mean.allFinite() || !c.scatter.allFinite()) {
      continue;
    }
    n += c.plots;
    sum += c.plots * c.mean;
    second += c.plots * (c.scatter + c.mean * c.mean.transpose());
  }
  if (!(n > 0.0)) {
    return;
  }
  const Eigen::Vector2d mean = sum / n;
  Eigen::Matrix2d cov = second / n - mean * mean.transpose();
  cov -= spec_.measurement_sigma * spec_.measurement_sigma * Eigen::Matrix2d::Identity();
  cov = 0.5 * (cov + cov.transpose()).eval();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov);
  const Eigen::Vector2d values = eig.eigenvalues().cwiseMax(0.0);
  const Eigen::Matrix2d extent =
      eig.eigenvectors() * values.asDiagonal() * eig.eigenvectors().transpose();
  const double pm =
      spec_.member_detection_probability > 0.0 ? spec_.member_detection_probability : 1.0;
  const double members = n / pm;
  const double a = std::clamp(spec_.shape_smoothing, 0.0, 1.0);
  if (!ls.has_shape) {
    ls.extent = extent;
    ls.members = members;
    ls.has_shape = true;
  } else {
    ls.extent = (1.0 - a) * ls.extent + a * extent;
    ls.members = (1.0 - a) * ls.members + a * members;
  }
}

// Eq. 31-32: W_j = sum of the label's weights, x_j = sum mid([x]) w / W_j.
void LabeledBoxPhd::extract(std::span<const GroupCell> cells) noexcept {
  const std::size_t slots = slot_label_.size();
  slot_sum_.assign(slots, BoxVec::Zero());
  slot_plain_.assign(slots, BoxVec::Zero());
  slot_count_.assign(slots, 0);
  for (const BoxParticle& p : particles_) {
    if (p.slot < 0 || static_cast<std::size_t>(p.slot) >= slots) {
      continue;
    }
    const auto s = static_cast<std::size_t>(p.slot);
    slot_sum_[s] += p.weight * p.centre;
    slot_plain_[s] += p.centre;
    ++slot_count_[s];
  }
  estimates_.clear();
  for (LabelState& ls : labels_) {
    const auto s = static_cast<std::size_t>(ls.slot);
    const double w = slot_mass_[s];
    if (w > 0.0) {
      ls.state = slot_sum_[s] / w;
    } else if (slot_count_[s] > 0) {
      ls.state = slot_plain_[s] / slot_count_[s];  // a missed group coasts on its boxes
    }
    ls.weight = w;
    if (ls.detected) {
      shape_update(ls, ls.slot, cells);
    }
  }
  for (const bool detected : {true, false}) {
    for (const LabelState& ls : labels_) {
      if (ls.detected != detected) {
        continue;
      }
      GroupEstimate e;
      e.label = ls.label;
      e.position = Eigen::Vector2d(ls.state(0), ls.state(2));
      e.velocity = Eigen::Vector2d(ls.state(1), ls.state(3));
      e.extent = ls.extent;
      e.members = ls.members;
      e.weight = ls.weight;
      e.missed_scans = ls.missed;
      estimates_.push_back(e);
    }
  }
}

// §3.2.9: boxes with l1 = 0 (dead groups, newborn sets not taken) are dropped; each label is
// resampled to N_box boxes of weight 1 / N_box, re-inflated to the nominal size and jittered.
void LabeledBoxPhd::resample() noexcept {
  const int count = std::max(spec_.boxes_per_group, 1);
  const BoxVec nominal_half(0.5 * spec_.position_width, 0.5 * spec_.velocity_width,
                            0.5 * spec_.position_width, 0.5 * spec_.velocity_width);
  next_.clear();
  // Particles bucketed by slot (counting sort over slot_count_ from extract()).
  const std::size_t slots = slot_count_.size();
  bucket_start_.assign(slots + 1, 0);
  for (std::size_t s = 0; s < slots; ++s) {
    bucket_start_[s + 1] = bucket_start_[s] + slot_count_[s];
  }
  members_of_label_.resize(static_cast<std::size_t>(bucket_start_[slots]));
  picks_.assign(bucket_start_.begin(), bucket_start_.end() - 1);  // fill cursors
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    const int s = particles_[i].slot;
    if (s >= 0 && static_cast<std::size_t>(s) < slots) {
      members_of_label_[static_cast<std::size_t>(picks_[static_cast<std::size_t>(s)]++)] =
          static_cast<int>(i);
    }
  }
  for (const LabelState& ls : labels_) {
    const auto s = static_cast<std::size_t>(ls.slot);
    const auto first = static_cast<std::size_t>(bucket_start_[s]);
    const auto last = static_cast<std::size_t>(bucket_start_[s + 1]);
    if (first == last) {
      continue;
    }
    weights_.clear();
    for (std::size_t k = first; k < last; ++k) {
      weights_.push_back(particles_[static_cast<std::size_t>(members_of_label_[k])].weight);
    }
    systematic_resample(weights_, count, uniform(0.0, 1.0), picks_);
    for (const int k : picks_) {
      BoxParticle b = particles_[static_cast<std::size_t>(
          members_of_label_[first + static_cast<std::size_t>(k)])];
      for (int j = 0; j < 4; ++j) {
        b.centre(j) += uniform(-1.0, 1.0) * spec_.jitter * nominal_half(j);
      }
      b.half = nominal_half;
      b.weight = 1.0 / count;
      b.label = ls.label;
      b.missed = ls.missed;
      b.slot = -1;
      next_.push_back(b);
    }
  }
  particles_.swap(next_);
}

}  // namespace skytrack::group
