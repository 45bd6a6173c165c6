// Paper 000 §3.2: the labeled box-particle PHD filter, one scan per step(): births
// (§3.2.2, eq. 12-13), prediction (eq. 14-17), update (eq. 18-22), contraction (eq. 23-27),
// N-hat (eq. 28). The label rules, extraction and resampling are in
// labeled_box_phd_labels.cpp.
//
// Slots: within one scan every particle belongs to a slot, index s of the table
// [labels_ (s < L) | newborn sets, one per previous cell (s = L + b)], so the update can
// sum each label's and each newborn set's share of every cell.
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "skytrack/group/labeled_box_phd.hpp"

namespace skytrack::group {

LabeledBoxPhd::LabeledBoxPhd(const GroupSpec& spec) : spec_(spec), rng_(spec.seed) {}

double LabeledBoxPhd::uniform(double lo, double hi) noexcept {
  // Own mapping of the engine's bits: std::uniform_real_distribution is not specified
  // bit-for-bit across standard libraries, and the filter must repeat for a seed.
  const double u = static_cast<double>(rng_() >> 11) * 0x1.0p-53;
  return lo + (hi - lo) * u;
}

const std::vector<GroupEstimate>& LabeledBoxPhd::step(double time,
                                                      std::span<const GroupCell> cells) noexcept {
  if (!std::isfinite(time)) {
    return estimates_;
  }
  double dt = has_time_ ? time - last_time_ : 0.0;
  if (!(dt > 0.0)) {
    dt = 0.0;
  }
  has_time_ = true;
  last_time_ = time;
  add_births();
  predict(dt);
  update(cells);
  apply_label_rules(cells);
  extract(cells);
  resample();
  previous_cells_.clear();
  for (const GroupCell& c : cells) {
    if (c.box.lower.allFinite() && c.box.upper.allFinite()) {
      previous_cells_.push_back(c.box);
    }
  }
  return estimates_;
}

// §3.2.2: n2 boxes at each group detected in the last scan (its label), n1 boxes at each
// measurement box of the last scan (label 0, one newborn set per box).
void LabeledBoxPhd::add_births() noexcept {
  const int n_labels = static_cast<int>(labels_.size());
  const BoxVec nominal_half(0.5 * spec_.position_width, 0.5 * spec_.velocity_width,
                            0.5 * spec_.position_width, 0.5 * spec_.velocity_width);
  for (BoxParticle& p : particles_) {
    const auto it = std::lower_bound(
        labels_.begin(), labels_.end(), p.label,
        [](const LabelState& ls, std::uint32_t label) { return ls.label < label; });
    p.slot = static_cast<int>(it - labels_.begin());
  }
  const int n2 = std::max(spec_.births_per_estimate, 0);
  const double w2 = 1.0 / std::max(spec_.boxes_per_group, 1);
  for (int s = 0; s < n_labels; ++s) {
    const LabelState& ls = labels_[static_cast<std::size_t>(s)];
    if (!ls.detected) {
      continue;
    }
    for (int k = 0; k < n2; ++k) {
      BoxParticle b;
      b.half = nominal_half;
      for (int j = 0; j < 4; ++j) {
        b.centre(j) = ls.state(j) + uniform(-1.0, 1.0) * spec_.jitter * nominal_half(j);
      }
      b.weight = w2;
      b.label = ls.label;
      b.missed = ls.missed;
      b.slot = s;
      particles_.push_back(b);
    }
  }
  const int n1 = std::max(spec_.births_per_box, 0);
  const double w1 = n1 > 0 ? spec_.birth_mass_per_box / n1 : 0.0;
  for (std::size_t c = 0; c < previous_cells_.size(); ++c) {
    const PlaneBox& z = previous_cells_[c];
    for (int k = 0; k < n1; ++k) {
      BoxParticle b;
      b.centre(0) = uniform(z.lower.x(), z.upper.x());
      b.centre(2) = uniform(z.lower.y(), z.upper.y());
      b.half(0) = std::max(nominal_half(0), 0.5 * (z.upper.x() - z.lower.x()));
      b.half(2) = std::max(nominal_half(2), 0.5 * (z.upper.y() - z.lower.y()));
      b.half(1) = spec_.birth_speed;
      b.half(3) = spec_.birth_speed;
      b.weight = w1;
      b.slot = n_labels + static_cast<int>(c);
      particles_.push_back(b);
    }
  }
}

// Eq. 14-16: interval hull of F [x], weight times Ps, labels unchanged. The prior boxes are
// kept for the contraction's constraint propagation.
void LabeledBoxPhd::predict(double dt) noexcept {
  F_ = group_transition(spec_.motion, spec_.turn_rate, dt);
  prior_centre_.resize(particles_.size());
  prior_half_.resize(particles_.size());
  const double ps = std::clamp(spec_.survival_probability, 0.0, 1.0);
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    prior_centre_[i] = particles_[i].centre;
    prior_half_[i] = particles_[i].half;
    predict_box(F_, particles_[i]);
    particles_[i].weight *= ps;
  }
}

// Eq. 18-20 (weights), 23-26 (contraction), 28 (N-hat), and each cell's owner: the slot
// with the largest share of it (ties to the lower slot, i.e. the older label).
void LabeledBoxPhd::update(std::span<const GroupCell> cells) noexcept {
  cell_boxes_.clear();
  clutter_.clear();
  const double area = spec_.surveillance_area > 0.0 ? spec_.surveillance_area : 1.0;
  for (const GroupCell& c : cells) {
    PlaneBox z = c.box;
    if (!z.lower.allFinite() || !z.upper.allFinite()) {
      z = PlaneBox{};  // no area: no particle takes weight from it
    }
    cell_boxes_.push_back(z);
    clutter_.push_back(std::max(spec_.clutter_rate, 0.0) * z.area() / area);
  }
  const int slots = static_cast<int>(labels_.size() + previous_cells_.size());
  phd_update(particles_, cell_boxes_, clutter_, spec_.detection_probability, slots, update_);
  group_count_ = 0.0;
  slot_mass_.assign(static_cast<std::size_t>(slots), 0.0);
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    BoxParticle& p = particles_[i];
    const int j = update_.best_cell[i];
    if (j >= 0) {
      contract_box(F_, prior_centre_[i], prior_half_[i], cell_boxes_[static_cast<std::size_t>(j)],
                   p);
    }
    group_count_ += p.weight;
    if (p.slot >= 0 && p.slot < slots) {
      slot_mass_[static_cast<std::size_t>(p.slot)] += p.weight;
    }
  }
  const std::size_t m = cell_boxes_.size();
  owner_.assign(m, -1);
  for (std::size_t j = 0; j < m; ++j) {
    double best = 0.0;
    for (int s = 0; s < slots; ++s) {
      const double share = update_.shares[static_cast<std::size_t>(s) * m + j];
      if (share > best) {
        best = share;
        owner_[j] = s;
      }
    }
  }
}

}  // namespace skytrack::group
