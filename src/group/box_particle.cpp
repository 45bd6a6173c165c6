// Paper 000 §3.2.3-3.2.5 and 3.2.9: interval prediction (eq. 14), box likelihood (eq. 19),
// PHD update (eq. 18, 20), contracting box (eq. 23-24), contraction (eq. 25-26) and
// systematic resampling of box particles.
#include "skytrack/group/box_particle.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace skytrack::group {
namespace {

constexpr int kPosX = 0;
constexpr int kPosY = 2;
constexpr double kTinyCoefficient = 1e-12;  // below this a row does not constrain a variable

struct Interval {
  double lo = 0.0;
  double hi = 0.0;
};

Interval intersect(Interval a, Interval b) {
  return {std::max(a.lo, b.lo), std::min(a.hi, b.hi)};
}

// One forward-backward pass of the constraint sum_j a_j p_j in target over the box p:
// each p_j is narrowed to (target - sum_{l != j} a_l p_l) / a_j (HC4-revise of a linear row).
void contract_row(const Eigen::Matrix<double, 1, 4>& a, Interval target, Interval (&p)[4]) {
  for (int j = 0; j < 4; ++j) {
    if (std::abs(a(j)) < kTinyCoefficient) {
      continue;
    }
    Interval rest{0.0, 0.0};
    for (int l = 0; l < 4; ++l) {
      if (l == j) {
        continue;
      }
      const double x = a(l) * p[l].lo;
      const double y = a(l) * p[l].hi;
      rest.lo += std::min(x, y);
      rest.hi += std::max(x, y);
    }
    const double u = (target.lo - rest.hi) / a(j);
    const double v = (target.hi - rest.lo) / a(j);
    const Interval narrowed = intersect(p[j], {std::min(u, v), std::max(u, v)});
    if (narrowed.lo <= narrowed.hi) {
      p[j] = narrowed;  // an empty result (rounding) leaves the variable as it was
    }
  }
}

}  // namespace

double PlaneBox::area() const noexcept {
  const Eigen::Vector2d side = upper - lower;
  if (!(side.x() > 0.0) || !(side.y() > 0.0)) {
    return 0.0;
  }
  return side.x() * side.y();
}

BoxMat group_transition(GroupMotion motion, double turn_rate, double dt) noexcept {
  BoxMat F = BoxMat::Identity();
  const double w = motion == GroupMotion::kCoordinatedTurn ? turn_rate : 0.0;
  if (std::abs(w * dt) < 1e-9) {
    F(0, 1) = dt;
    F(2, 3) = dt;
    return F;
  }
  const double s = std::sin(w * dt);
  const double c = std::cos(w * dt);
  F << 1.0, s / w, 0.0, -(1.0 - c) / w,  //
      0.0, c, 0.0, -s,                   //
      0.0, (1.0 - c) / w, 1.0, s / w,    //
      0.0, s, 0.0, c;
  return F;
}

void predict_box(const BoxMat& F, BoxParticle& box) noexcept {
  const BoxVec centre = F * box.centre;
  const BoxVec half = F.cwiseAbs() * box.half;
  box.centre = centre;
  box.half = half;
}

double box_likelihood(const BoxParticle& box, const PlaneBox& z) noexcept {
  const double hx = box.half(kPosX);
  const double hy = box.half(kPosY);
  const double own = 4.0 * hx * hy;
  if (!(own > 0.0)) {
    return 0.0;
  }
  const double ox =
      std::min(box.centre(kPosX) + hx, z.upper.x()) - std::max(box.centre(kPosX) - hx, z.lower.x());
  const double oy =
      std::min(box.centre(kPosY) + hy, z.upper.y()) - std::max(box.centre(kPosY) - hy, z.lower.y());
  if (!(ox > 0.0) || !(oy > 0.0)) {
    return 0.0;
  }
  return (ox * oy) / own;
}

bool contract_box(const BoxMat& F, const BoxVec& prior_centre, const BoxVec& prior_half,
                  const PlaneBox& z, BoxParticle& box) noexcept {
  const Interval px{box.centre(kPosX) - box.half(kPosX), box.centre(kPosX) + box.half(kPosX)};
  const Interval py{box.centre(kPosY) - box.half(kPosY), box.centre(kPosY) + box.half(kPosY)};
  const Interval x = intersect(px, {z.lower.x(), z.upper.x()});
  const Interval y = intersect(py, {z.lower.y(), z.upper.y()});
  if (!(x.lo <= x.hi) || !(y.lo <= y.hi)) {
    return false;
  }
  Interval p[4];
  for (int j = 0; j < 4; ++j) {
    p[j] = {prior_centre(j) - prior_half(j), prior_centre(j) + prior_half(j)};
  }
  contract_row(F.row(kPosX), x, p);
  contract_row(F.row(kPosY), y, p);
  BoxParticle prior;
  for (int j = 0; j < 4; ++j) {
    prior.centre(j) = 0.5 * (p[j].lo + p[j].hi);
    prior.half(j) = 0.5 * (p[j].hi - p[j].lo);
  }
  predict_box(F, prior);
  // Position: the intersection (eq. 26); velocity: propagated from the contracted prior,
  // kept inside the predicted velocity interval.
  const Interval rows[4] = {x, {0.0, 0.0}, y, {0.0, 0.0}};
  for (int j = 0; j < 4; ++j) {
    Interval r = rows[j];
    if (j == 1 || j == 3) {
      r = intersect({prior.centre(j) - prior.half(j), prior.centre(j) + prior.half(j)},
                    {box.centre(j) - box.half(j), box.centre(j) + box.half(j)});
      if (!(r.lo <= r.hi)) {
        continue;
      }
    }
    box.centre(j) = 0.5 * (r.lo + r.hi);
    box.half(j) = 0.5 * (r.hi - r.lo);
  }
  return true;
}

void phd_update(std::span<BoxParticle> particles, std::span<const PlaneBox> cells,
                std::span<const double> clutter_intensity, double detection_probability, int slots,
                PhdUpdateResult& out) noexcept {
  const std::size_t n = particles.size();
  const std::size_t m = cells.size();
  const double pd = std::clamp(detection_probability, 0.0, 1.0);
  out.slots = std::max(slots, 0);
  out.best_cell.assign(n, -1);
  out.denominators.assign(m, 0.0);
  out.shares.assign(static_cast<std::size_t>(out.slots) * m, 0.0);
  // Cells by lower x bound; the widest cell bounds how far left a meeting cell can start.
  out.cells_by_x.resize(m);
  for (std::size_t j = 0; j < m; ++j) {
    out.cells_by_x[j] = static_cast<int>(j);
  }
  std::sort(out.cells_by_x.begin(), out.cells_by_x.end(), [&cells](int a, int b) {
    const double xa = cells[static_cast<std::size_t>(a)].lower.x();
    const double xb = cells[static_cast<std::size_t>(b)].lower.x();
    return xa < xb || (xa == xb && a < b);
  });
  out.lower_x.resize(m);
  double widest = 0.0;
  for (std::size_t r = 0; r < m; ++r) {
    const PlaneBox& z = cells[static_cast<std::size_t>(out.cells_by_x[r])];
    out.lower_x[r] = z.lower.x();
    widest = std::max(widest, z.upper.x() - z.lower.x());
  }
  // Eq. 19 for the pairs that can meet, and eq. 20: lambda c([z_j]) + sum_i g_ij Pd w_i.
  out.pairs.clear();
  out.offsets.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    BoxParticle& b = particles[i];
    if (!std::isfinite(b.weight) || b.weight < 0.0) {
      b.weight = 0.0;
    }
    out.offsets[i] = out.pairs.size();
    const double x_lo = b.centre(kPosX) - b.half(kPosX);
    const double x_hi = b.centre(kPosX) + b.half(kPosX);
    if (!(x_lo <= x_hi) || !(widest >= 0.0)) {
      continue;
    }
    auto r = static_cast<std::size_t>(
        std::lower_bound(out.lower_x.begin(), out.lower_x.end(), x_lo - widest) -
        out.lower_x.begin());
    for (; r < m && out.lower_x[r] <= x_hi; ++r) {
      const int j = out.cells_by_x[r];
      const double g = box_likelihood(b, cells[static_cast<std::size_t>(j)]);
      if (g > 0.0) {
        out.pairs.emplace_back(j, g);
        out.denominators[static_cast<std::size_t>(j)] += g * pd * b.weight;
      }
    }
  }
  out.offsets[n] = out.pairs.size();
  for (std::size_t j = 0; j < m; ++j) {
    const double clutter = j < clutter_intensity.size() ? clutter_intensity[j] : 0.0;
    out.denominators[j] += std::isfinite(clutter) && clutter > 0.0 ? clutter : 0.0;
  }
  // Eq. 18 and 23-24.
  for (std::size_t i = 0; i < n; ++i) {
    BoxParticle& b = particles[i];
    double factor = 1.0 - pd;
    double best = 0.0;
    for (std::size_t e = out.offsets[i]; e < out.offsets[i + 1]; ++e) {
      const auto [j, g] = out.pairs[e];
      const double d = out.denominators[static_cast<std::size_t>(j)];
      if (!(d > 0.0)) {
        continue;
      }
      const double wj = g * pd / d;  // eq. 24 without the prior weight
      factor += wj;
      if (wj > best || (wj == best && j < out.best_cell[i])) {
        best = wj;
        out.best_cell[i] = j;
      }
      if (b.slot >= 0 && b.slot < out.slots) {
        out.shares[static_cast<std::size_t>(b.slot) * m + static_cast<std::size_t>(j)] +=
            wj * b.weight;
      }
    }
    b.weight *= factor;
  }
}

void systematic_resample(std::span<const double> weights, int count, double u0,
                         std::vector<int>& out) noexcept {
  out.clear();
  const int n = static_cast<int>(weights.size());
  if (n == 0 || count <= 0) {
    return;
  }
  double total = 0.0;
  for (const double w : weights) {
    total += std::isfinite(w) && w > 0.0 ? w : 0.0;
  }
  const double u = std::clamp(u0, 0.0, std::nextafter(1.0, 0.0));
  if (!(total > 0.0) || !std::isfinite(total)) {
    for (int k = 0; k < count; ++k) {
      out.push_back(std::min(n - 1, static_cast<int>((k + u) * n / count)));
    }
    return;
  }
  double cumulative = 0.0;
  int i = 0;
  for (int k = 0; k < count; ++k) {
    const double target = (k + u) / count * total;
    while (i < n - 1) {
      const double w = std::isfinite(weights[static_cast<std::size_t>(i)]) &&
                               weights[static_cast<std::size_t>(i)] > 0.0
                           ? weights[static_cast<std::size_t>(i)]
                           : 0.0;
      if (cumulative + w > target) {
        break;
      }
      cumulative += w;
      ++i;
    }
    out.push_back(i);
  }
}

}  // namespace skytrack::group
