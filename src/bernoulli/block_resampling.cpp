// Block resampling (Rebeschini & van Handel 2015, §2) for paper 001's step 3(3).
#include "skytrack/bernoulli/block_resampling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/LU>

namespace skytrack::bernoulli {
namespace {

/// Output slot k of a systematic walk over `weights` (summing to `sum`) takes input index
/// pick(k); calls take(k, index) for each k in order.
template <class Take>
void systematic_walk(std::span<const double> weights, double sum, double u0, std::size_t size,
                     Take&& take) noexcept {
  const double step = sum / static_cast<double>(size);
  double cumulative = weights[0];
  std::size_t source = 0;
  const std::size_t last = weights.size() - 1;
  for (std::size_t k = 0; k < size; ++k) {
    const double target = (u0 + static_cast<double>(k)) * step;
    while (cumulative < target && source < last) cumulative += weights[++source];
    take(k, source);
  }
}

}  // namespace

double block_dependence(const ScanPlot& plot, const Eigen::Matrix4d& covariance) noexcept {
  Eigen::Matrix4d r = Eigen::Matrix4d::Zero();  // [x, vx, y, vy] -> [a, v.along, c, v.across]
  r(0, 0) = r(1, 1) = plot.along.x();
  r(0, 2) = r(1, 3) = plot.along.y();
  r(2, 0) = r(3, 1) = plot.across.x();
  r(2, 2) = r(3, 3) = plot.across.y();
  const Eigen::Matrix4d c = r * covariance * r.transpose();
  const double joint = c.determinant();
  const double along = c.topLeftCorner<2, 2>().determinant();
  const double across = c.bottomRightCorner<2, 2>().determinant();
  if (!(joint > 0.0) || !(along > 0.0) || !(across > 0.0)) {
    return std::numeric_limits<double>::infinity();
  }
  const double dependence = 0.5 * std::log(along * across / joint);
  return std::isfinite(dependence) ? std::max(dependence, 0.0)
                                   : std::numeric_limits<double>::infinity();
}

bool block_resample(std::span<const Particle> cloud, const ScanPlot& plot, double u_along,
                    double u_across, std::span<double> scratch, std::span<Particle> out,
                    Eigen::Vector4d& estimate) noexcept {
  const std::size_t n = cloud.size();
  if (n == 0 || out.empty() || scratch.size() < 2 * n) return false;
  if (!(plot.sigma_along > 0.0) || !(plot.sigma_across > 0.0)) return false;
  const Eigen::Vector2d z = plot.position, along = plot.along, across = plot.across;
  const double inv_along = 1.0 / plot.sigma_along, inv_across = 1.0 / plot.sigma_across;
  const std::span<double> g = scratch.first(n), h = scratch.subspan(n, n);
  double sum_g = 0.0, sum_h = 0.0;
  double a_mean = 0.0, c_mean = 0.0, va_mean = 0.0, vc_mean = 0.0;  // sums, then means
  for (std::size_t k = 0; k < n; ++k) {
    const Particle& p = cloud[k];
    const double dx = p.x - z.x(), dy = p.y - z.y();
    const double a = dx * along.x() + dy * along.y(), c = dx * across.x() + dy * across.y();
    const double ea = a * inv_along, ec = c * inv_across;
    g[k] = std::exp(-0.5 * ea * ea);
    h[k] = std::exp(-0.5 * ec * ec);
    sum_g += g[k];
    sum_h += h[k];
    a_mean += g[k] * a;
    va_mean += g[k] * (p.vx * along.x() + p.vy * along.y());
    c_mean += h[k] * c;
    vc_mean += h[k] * (p.vx * across.x() + p.vy * across.y());
  }
  if (!(sum_g > 0.0) || !(sum_h > 0.0) || !std::isfinite(sum_g + sum_h)) return false;
  a_mean /= sum_g, va_mean /= sum_g, c_mean /= sum_h, vc_mean /= sum_h;
  // Along block into out[k].x / .vx, across block into .y / .vy, then back to the frame.
  systematic_walk(g, sum_g, u_along, out.size(), [&](std::size_t k, std::size_t i) {
    const Particle& p = cloud[i];
    out[k].x = (p.x - z.x()) * along.x() + (p.y - z.y()) * along.y();
    out[k].vx = p.vx * along.x() + p.vy * along.y();
  });
  systematic_walk(h, sum_h, u_across, out.size(), [&](std::size_t k, std::size_t i) {
    const Particle& p = cloud[i];
    out[k].y = (p.x - z.x()) * across.x() + (p.y - z.y()) * across.y();
    out[k].vy = p.vx * across.x() + p.vy * across.y();
  });
  for (Particle& p : out) {
    const Particle b = p;  // (a, v.along, c, v.across)
    p.x = z.x() + b.x * along.x() + b.y * across.x();
    p.y = z.y() + b.x * along.y() + b.y * across.y();
    p.vx = b.vx * along.x() + b.vy * across.x();
    p.vy = b.vx * along.y() + b.vy * across.y();
  }
  estimate << z.x() + a_mean * along.x() + c_mean * across.x(),
      va_mean * along.x() + vc_mean * across.x(), z.y() + a_mean * along.y() + c_mean * across.y(),
      va_mean * along.y() + vc_mean * across.y();
  return true;
}

}  // namespace skytrack::bernoulli
