// Plot preparation, gated likelihood accumulation, dynamics and resampling of paper 001's
// particle implementation (§3.2, eq. 20-27).
#include "skytrack/bernoulli/particle_kernel.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

namespace skytrack::bernoulli {
namespace {

constexpr double kTwoPi = 6.283185307179586;

/// The gate box: the ellipse's axes along/across scaled by the gate radius.
void set_box(ScanPlot& plot, double gate_distance_squared) noexcept {
  const double g = std::sqrt(gate_distance_squared);
  const double hx = g * (std::abs(plot.along.x()) * plot.sigma_along +
                         std::abs(plot.across.x()) * plot.sigma_across);
  const double hy = g * (std::abs(plot.along.y()) * plot.sigma_along +
                         std::abs(plot.across.y()) * plot.sigma_across);
  plot.box = {plot.position.x() - hx, plot.position.x() + hx, plot.position.y() - hy,
              plot.position.y() + hy};
}

bool finite_positive(double v) noexcept {
  return std::isfinite(v) && v > 0.0;
}

}  // namespace

bool make_polar_plot(const Eigen::Vector2d& origin, double range, double azimuth,
                     double sigma_range, double sigma_azimuth, double clutter_intensity,
                     double gate_distance_squared, ScanPlot& out) noexcept {
  if (!origin.allFinite() || !finite_positive(range) || !std::isfinite(azimuth) ||
      !finite_positive(sigma_range) || !finite_positive(sigma_azimuth) ||
      !finite_positive(clutter_intensity)) {
    return false;
  }
  ScanPlot plot;
  plot.polar = true;
  plot.origin = origin;
  plot.along = {std::sin(azimuth), std::cos(azimuth)};  // azimuth clockwise from north
  plot.across = {std::cos(azimuth), -std::sin(azimuth)};
  plot.range = range;
  plot.position = origin + range * plot.along;
  plot.inv_sigma_first = 1.0 / sigma_range;
  plot.inv_sigma_second = 1.0 / sigma_azimuth;
  plot.sigma_along = sigma_range;
  plot.sigma_across = range * sigma_azimuth;
  plot.peak_ratio = 1.0 / (kTwoPi * sigma_range * sigma_azimuth * clutter_intensity);
  set_box(plot, gate_distance_squared);
  out = plot;
  return true;
}

bool make_cartesian_plot(const Eigen::Vector2d& position, double sigma_x, double sigma_y,
                         double clutter_intensity, double gate_distance_squared,
                         ScanPlot& out) noexcept {
  if (!position.allFinite() || !finite_positive(sigma_x) || !finite_positive(sigma_y) ||
      !finite_positive(clutter_intensity)) {
    return false;
  }
  ScanPlot plot;
  plot.polar = false;
  plot.position = position;
  plot.inv_sigma_first = 1.0 / sigma_x;
  plot.inv_sigma_second = 1.0 / sigma_y;
  plot.sigma_along = sigma_x;
  plot.sigma_across = sigma_y;
  plot.peak_ratio = 1.0 / (kTwoPi * sigma_x * sigma_y * clutter_intensity);
  set_box(plot, gate_distance_squared);
  out = plot;
  return true;
}

DominantPlot accumulate_likelihood_ratios(std::span<const Particle> block,
                                          std::span<const ScanPlot> plots,
                                          double gate_distance_squared,
                                          std::span<double> ratio_sum) noexcept {
  DominantPlot dominant;
  if (block.empty()) return dominant;
  double x_min = block[0].x, x_max = block[0].x, y_min = block[0].y, y_max = block[0].y;
  for (const Particle& p : block) {
    x_min = std::min(x_min, p.x);
    x_max = std::max(x_max, p.x);
    y_min = std::min(y_min, p.y);
    y_max = std::max(y_max, p.y);
  }
  for (std::size_t z = 0; z < plots.size(); ++z) {
    const ScanPlot& plot = plots[z];
    if (plot.box[0] > x_max || plot.box[1] < x_min || plot.box[2] > y_max || plot.box[3] < y_min) {
      continue;
    }
    double sum = 0.0;
    for (std::size_t n = 0; n < block.size(); ++n) {
      const Particle& p = block[n];
      if (p.x < plot.box[0] || p.x > plot.box[1] || p.y < plot.box[2] || p.y > plot.box[3]) {
        continue;
      }
      const double ratio = plot_likelihood_ratio(plot, p.x, p.y, gate_distance_squared);
      ratio_sum[n] += ratio;
      sum += ratio;
    }
    dominant.total += sum;
    if (sum > dominant.sum) dominant.sum = sum, dominant.index = z;
  }
  return dominant;
}

ModelDynamics make_dynamics(const BernoulliModelSpec& model, double dt) noexcept {
  ModelDynamics m;
  const double w = model.turn_rate;
  if (std::abs(w * dt) < 1e-9) {
    m.s_over_w = dt;
    m.one_minus_c_over_w = 0.0;
    m.c = 1.0;
    m.s = 0.0;
  } else {
    m.s = std::sin(w * dt);
    m.c = std::cos(w * dt);
    m.s_over_w = m.s / w;
    m.one_minus_c_over_w = (1.0 - m.c) / w;
  }
  m.g_position = 0.5 * dt * dt * model.accel_sigma;
  m.g_velocity = dt * model.accel_sigma;
  return m;
}

void systematic_resample(std::span<const Particle> in, std::span<const double> weights, double u0,
                         std::span<Particle> out) noexcept {
  if (in.empty() || out.empty()) return;
  // Input k fills the outputs whose points (u0 + n) / N fall in its cumulative interval. It
  // is written to the next slot unconditionally (overwritten when it gets no copy), so only
  // inputs with two or more copies branch.
  const std::size_t size = out.size();
  const auto count = static_cast<double>(size);
  Particle spare;
  double cumulative = 0.0;
  std::size_t n = 0;
  for (std::size_t k = 0; k < in.size(); ++k) {
    cumulative += weights[k];
    const double reach = cumulative * count - u0;  // outputs n with n < reach
    std::size_t end = 0;                           // ceil(reach), clamped to [0, size]
    if (reach > 0.0) {
      end = static_cast<std::size_t>(reach);
      end = std::min(size, end + (static_cast<double>(end) < reach ? 1 : 0));
    }
    *(n < size ? &out[n] : &spare) = in[k];
    for (std::size_t t = n + 1; t < end; ++t) out[t] = in[k];
    n = std::max(n, end);
  }
  for (; n < size; ++n) out[n] = in.back();  // rounding at the end of the cumulative sum
}

void weighted_moments(std::span<const Particle> particles, std::span<const double> weights,
                      Eigen::Vector4d& mean, Eigen::Matrix4d& covariance) noexcept {
  BlockMean unused;
  weighted_moments(particles, weights, 0, mean, covariance, unused);
}

void weighted_moments(std::span<const Particle> particles, std::span<const double> weights,
                      std::size_t head, Eigen::Vector4d& mean, Eigen::Matrix4d& covariance,
                      BlockMean& head_mean) noexcept {
  // One pass about a reference particle, so the sums stay small (positions are ~1e4 m).
  mean.setZero();
  covariance.setZero();
  head_mean = BlockMean{};
  if (particles.empty()) return;
  const Particle& r = particles[0];
  const Eigen::Vector4d reference(r.x, r.vx, r.y, r.vy);
  head = std::min(head, particles.size());
  double s0 = 0, s1 = 0, s2 = 0, s3 = 0, total = 0;
  double s00 = 0, s01 = 0, s02 = 0, s03 = 0, s11 = 0, s12 = 0, s13 = 0, s22 = 0, s23 = 0, s33 = 0;
  // Two loops over one set of running sums (a branch or a lambda on them in the loop would
  // keep the sums in memory): the leading block's mean is read between them.
  std::size_t n = 0;
  for (std::size_t end : {head, particles.size()}) {
    for (; n < end; ++n) {
      const Particle& p = particles[n];
      const double w = weights[n];
      const double d0 = p.x - r.x, d1 = p.vx - r.vx, d2 = p.y - r.y, d3 = p.vy - r.vy;
      const double w0 = w * d0, w1 = w * d1, w2 = w * d2, w3 = w * d3;
      total += w;
      s0 += w0, s1 += w1, s2 += w2, s3 += w3;
      s00 += w0 * d0, s01 += w0 * d1, s02 += w0 * d2, s03 += w0 * d3;
      s11 += w1 * d1, s12 += w1 * d2, s13 += w1 * d3;
      s22 += w2 * d2, s23 += w2 * d3, s33 += w3 * d3;
    }
    if (end == head && total > 0.0) {
      head_mean.mass = total;
      head_mean.mean = reference + Eigen::Vector4d(s0, s1, s2, s3) / total;
    }
  }
  const double s[4] = {s0, s1, s2, s3};
  const double ss[10] = {s00, s01, s02, s03, s11, s12, s13, s22, s23, s33};
  if (!(total > 0.0)) return;
  const Eigen::Vector4d m(s[0] / total, s[1] / total, s[2] / total, s[3] / total);
  int k = 0;
  for (int a = 0; a < 4; ++a) {
    for (int b = a; b < 4; ++b, ++k) {
      covariance(a, b) = covariance(b, a) = ss[k] / total - m[a] * m[b];
    }
  }
  mean = m + reference;
}

void MomentAccumulator::moments(Eigen::Vector4d& mean, Eigen::Matrix4d& covariance) const noexcept {
  mean.setZero();
  covariance.setZero();
  if (count_ == 0) return;
  const double n = static_cast<double>(count_);
  const Eigen::Vector4d m(s0_ / n, s1_ / n, s2_ / n, s3_ / n);
  const double ss[10] = {s00_, s01_, s02_, s03_, s11_, s12_, s13_, s22_, s23_, s33_};
  int k = 0;
  for (int a = 0; a < 4; ++a) {
    for (int b = a; b < 4; ++b, ++k) {
      covariance(a, b) = covariance(b, a) = ss[k] / n - m[a] * m[b];
    }
  }
  mean = m + Eigen::Vector4d(reference_.x, reference_.vx, reference_.y, reference_.vy);
}

void predict_moments(const ModelDynamics& d, Eigen::Vector4d& mean,
                     Eigen::Matrix4d& covariance) noexcept {
  Eigen::Matrix4d f;                                 // propagate's x' = F x, state [x, vx, y, vy]
  f << 1.0, d.s_over_w, 0.0, -d.one_minus_c_over_w,  //
      0.0, d.c, 0.0, -d.s,                           //
      0.0, d.one_minus_c_over_w, 1.0, d.s_over_w,    //
      0.0, d.s, 0.0, d.c;
  Eigen::Matrix4d q = Eigen::Matrix4d::Zero();  // G G' sigma^2 per axis
  q(0, 0) = q(2, 2) = d.g_position * d.g_position;
  q(1, 1) = q(3, 3) = d.g_velocity * d.g_velocity;
  q(0, 1) = q(1, 0) = q(2, 3) = q(3, 2) = d.g_position * d.g_velocity;
  mean = f * mean;
  covariance = f * covariance * f.transpose() + q;
}

bool velocity_given_position(const Eigen::Vector4d& predicted_mean,
                             const Eigen::Matrix4d& predicted_covariance, double x, double y,
                             double& vx, double& vy) noexcept {
  const Eigen::Matrix4d& c = predicted_covariance;
  const double pxx = c(0, 0), pxy = c(0, 2), pyy = c(2, 2);
  const double det = pxx * pyy - pxy * pxy;
  if (!(pxx > 0.0) || !(det > 0.0) || !std::isfinite(det)) return false;
  const double dx = x - predicted_mean[0], dy = y - predicted_mean[2];
  // P_pp^-1 (p - m_p), then P_vp times it.
  const double ux = (pyy * dx - pxy * dy) / det, uy = (pxx * dy - pxy * dx) / det;
  vx = predicted_mean[1] + c(1, 0) * ux + c(1, 2) * uy;
  vy = predicted_mean[3] + c(3, 0) * ux + c(3, 2) * uy;
  return std::isfinite(vx) && std::isfinite(vy);
}

bool regularise_velocity(std::span<Particle> cloud, const Eigen::Vector4d& mean,
                         const Eigen::Matrix4d& covariance, double bandwidth,
                         double prediction_velocity_variance, NormalSampler& rng) noexcept {
  if (!(bandwidth > 0.0) || !(bandwidth < 1.0)) return false;
  // [x, vx, y, vy]: position rows 0, 2; velocity rows 1, 3.
  Eigen::Matrix2d pp, vv, vp;
  pp << covariance(0, 0), covariance(0, 2), covariance(2, 0), covariance(2, 2);
  vv << covariance(1, 1), covariance(1, 3), covariance(3, 1), covariance(3, 3);
  vp << covariance(1, 0), covariance(1, 2), covariance(3, 0), covariance(3, 2);
  const double det = pp.determinant();
  if (!(det > 0.0) || !(pp(0, 0) > 0.0)) return false;
  Eigen::Matrix2d pp_inverse;
  pp_inverse << pp(1, 1), -pp(0, 1), -pp(1, 0), pp(0, 0);
  pp_inverse /= det;
  const Eigen::Matrix2d gain = vp * pp_inverse;  // E[v|p] = m_v + gain (p - m_p)
  Eigen::Matrix2d c = vv - gain * vp.transpose();
  c(0, 1) = c(1, 0) = 0.5 * (c(0, 1) + c(1, 0));
  const double half_trace = 0.5 * (c(0, 0) + c(1, 1)), half_gap = 0.5 * (c(0, 0) - c(1, 1));
  const double largest = half_trace + std::sqrt(half_gap * half_gap + c(0, 1) * c(0, 1));
  if (!(bandwidth * bandwidth * largest > prediction_velocity_variance)) return false;
  if (!(c(0, 0) > 0.0)) return false;
  const double l00 = std::sqrt(c(0, 0)), l10 = c(1, 0) / l00;
  const double l11_squared = c(1, 1) - l10 * l10;
  if (!(l11_squared > 0.0)) return false;
  const double l11 = std::sqrt(l11_squared);
  const double a = std::sqrt(1.0 - bandwidth * bandwidth);
  for (Particle& p : cloud) {
    const double dx = p.x - mean[0], dy = p.y - mean[2];
    const double cx = mean[1] + gain(0, 0) * dx + gain(0, 1) * dy;  // E[v|p]
    const double cy = mean[3] + gain(1, 0) * dx + gain(1, 1) * dy;
    const double e0 = rng.normal(), e1 = rng.normal();
    p.vx = cx + a * (p.vx - cx) + bandwidth * l00 * e0;
    p.vy = cy + a * (p.vy - cy) + bandwidth * (l10 * e0 + l11 * e1);
  }
  return true;
}

double effective_sample_size(std::span<const double> weights) noexcept {
  double sum_of_squares = 0.0;
  for (const double w : weights) sum_of_squares += w * w;
  return sum_of_squares > 0.0 ? 1.0 / sum_of_squares : 0.0;
}

double optimal_kernel_bandwidth(double samples) noexcept {
  constexpr double kDim = 4.0;
  if (!(samples > 0.0)) return 0.0;
  return std::pow(4.0 / ((kDim + 2.0) * samples), 1.0 / (kDim + 4.0));
}

}  // namespace skytrack::bernoulli
