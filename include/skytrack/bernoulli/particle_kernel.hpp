#pragma once
// The per-particle arithmetic shared by the MMBPF and its IMMBPF baseline (paper 001):
// propagation by one motion model (eq. 1, 22), the plot likelihood ratio g(z|x) / kappa(z)
// of eq. 15-16 and its gated accumulation over a block of particles, systematic resampling
// and weighted moments. State [x, vx, y, vy] in the local ENU frame, m and m/s.
#include <array>
#include <cmath>
#include <span>

#include <Eigen/Core>

#include "skytrack/bernoulli/bernoulli_spec.hpp"
#include "skytrack/bernoulli/normal_sampler.hpp"

namespace skytrack::bernoulli {

struct Particle {
  double x = 0.0, vx = 0.0, y = 0.0, vy = 0.0;  // [m, m/s, m, m/s]
};

/// One plot prepared once per scan for the likelihood, the gate and the birth proposal.
/// A polar plot measures range and azimuth about `origin`; `along` is the unit line of sight
/// at the measured azimuth and `across` the unit direction of increasing azimuth, so a
/// position p at d = p - origin has azimuth offset atan2(d.across, d.along). A Cartesian plot
/// measures `position` with independent errors along the x (`along`) and y (`across`) axes.
struct ScanPlot {
  bool polar = true;
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // in the tracking frame [m]
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();    // polar: the platform [m]
  Eigen::Vector2d along = Eigen::Vector2d::UnitX();
  Eigen::Vector2d across = Eigen::Vector2d::UnitY();
  double range = 0.0;           // polar: measured range [m]
  double inv_sigma_first = 0;   // 1/sigma_r [1/m] or 1/sigma_x
  double inv_sigma_second = 0;  // 1/sigma_az [1/rad] or 1/sigma_y
  double sigma_along = 0.0;     // position spread along `along` [m]
  double sigma_across = 0.0;    // position spread along `across` [m] (polar: r sigma_az)
  double peak_ratio = 0.0;      // g(z|x) / kappa(z) at zero residual
  std::array<double, 4> box{};  // gate box in the tracking frame: x min, x max, y min, y max
};

/// A polar plot about `origin`, azimuth in the tracking frame (clockwise from north) [rad];
/// clutter_intensity in [1/(m rad)]. Returns false for non-finite values or sigma <= 0.
bool make_polar_plot(const Eigen::Vector2d& origin, double range, double azimuth,
                     double sigma_range, double sigma_azimuth, double clutter_intensity,
                     double gate_distance_squared, ScanPlot& out) noexcept;
/// A Cartesian plot with clutter intensity [1/m^2].
bool make_cartesian_plot(const Eigen::Vector2d& position, double sigma_x, double sigma_y,
                         double clutter_intensity, double gate_distance_squared,
                         ScanPlot& out) noexcept;

/// Squared Mahalanobis distance of the plot from a particle at (x, y) in measurement space.
/// With d = p - origin, a = d.along, c = d.across and t = c / a, the azimuth offset is
/// atan(t) and the range a sqrt(1 + t^2); inside |t| <= 0.05 rad both come from their
/// series (atan to t^5, the root to t^6: errors below 1e-11 rad and 1e-10 of the range), so
/// the particles near a plot cost one division and no atan2, sqrt or hypot.
inline double plot_distance_squared(const ScanPlot& plot, double x, double y) noexcept {
  if (!plot.polar) {
    const double dx = (x - plot.position.x()) * plot.inv_sigma_first;
    const double dy = (y - plot.position.y()) * plot.inv_sigma_second;
    return dx * dx + dy * dy;
  }
  const double dx = x - plot.origin.x(), dy = y - plot.origin.y();
  const double a = dx * plot.along.x() + dy * plot.along.y();
  if (a <= 0.0) return 1e300;  // behind the sensor
  const double c = dx * plot.across.x() + dy * plot.across.y();
  const double t = c / a, t2 = t * t;
  double dazimuth = 0.0, range = 0.0;
  if (t2 <= 0.0025) {
    dazimuth = t * (1.0 - t2 * (1.0 / 3.0 - t2 * 0.2));
    range = a * (1.0 + t2 * (0.5 - t2 * (0.125 - t2 * 0.0625)));
  } else {  // far off the line of sight: a wide beam's gate
    dazimuth = std::atan2(c, a);
    range = std::sqrt(a * a + c * c);
  }
  const double er = (range - plot.range) * plot.inv_sigma_first;
  const double ea = dazimuth * plot.inv_sigma_second;
  return er * er + ea * ea;
}

/// g(z|x) / kappa(z) (eq. 15-16), 0 beyond the gate.
inline double plot_likelihood_ratio(const ScanPlot& plot, double x, double y,
                                    double gate_distance_squared) noexcept {
  const double m = plot_distance_squared(plot, x, y);
  return m < gate_distance_squared ? plot.peak_ratio * std::exp(-0.5 * m) : 0.0;
}

/// The plot with the largest share of a block's likelihood: sum_n g(z|x_n) / kappa(z) over
/// the block for that plot and for all plots together.
struct DominantPlot {
  std::size_t index = 0;  // into the plots; meaningless while sum is 0
  double sum = 0.0;
  double total = 0.0;
};

/// Adds sum_z g(z|x_n) / kappa(z) to ratio_sum[n] for each particle of `block`; a plot whose
/// gate box misses the block's bounding box is skipped without touching the particles.
/// Returns the plot that contributed most (to the block's sum of ratios).
DominantPlot accumulate_likelihood_ratios(std::span<const Particle> block,
                                          std::span<const ScanPlot> plots,
                                          double gate_distance_squared,
                                          std::span<double> ratio_sum) noexcept;

/// One model's transition over dt: x' = F x + G a, G = [dt^2/2, dt] per axis (see
/// BernoulliModelSpec), F the CV or CT matrix of the paper's §4.
struct ModelDynamics {
  double s_over_w = 1.0, one_minus_c_over_w = 0.0, c = 1.0, s = 0.0;  // CT terms (CV: dt,0,1,0)
  double g_position = 0.5, g_velocity = 1.0;                          // G scaled by sigma
};
ModelDynamics make_dynamics(const BernoulliModelSpec& model, double dt) noexcept;

[[gnu::always_inline]] inline void propagate(const ModelDynamics& m, Particle& p,
                                             NormalSampler& rng) noexcept {
  const double ax = rng.normal(), ay = rng.normal();
  const Particle q = p;
  p.x = q.x + m.s_over_w * q.vx - m.one_minus_c_over_w * q.vy + m.g_position * ax;
  p.vx = m.c * q.vx - m.s * q.vy + m.g_velocity * ax;
  p.y = q.y + m.one_minus_c_over_w * q.vx + m.s_over_w * q.vy + m.g_position * ay;
  p.vy = m.s * q.vx + m.c * q.vy + m.g_velocity * ay;
}

/// Systematic resampling of `in` with normalised `weights` into all of `out` (u0 in [0, 1)).
void systematic_resample(std::span<const Particle> in, std::span<const double> weights, double u0,
                         std::span<Particle> out) noexcept;

/// The regularised particle filter's kernel move (Musso, Oudjane & Le Gland 2001) on the
/// velocity given the position, with Liu & West's (2001) shrinkage, for a cloud just
/// resampled from a posterior of `mean` and `covariance`. With C the covariance of the
/// velocity given the position and E[v|p] the regression of the velocity on the position:
/// v <- E[v|p] + a (v - E[v|p]) + h L e, e ~ N(0, I2), L L' = C, a = sqrt(1 - h^2). The
/// cloud keeps its mean and covariance (position-velocity ones too) and the copies of one
/// parent spread over the posterior's velocity spread instead of staying identical.
/// Applied only when the kernel is wider than the next prediction's own velocity noise
/// (h^2 lambda_max(C) > prediction_velocity_variance [(m/s)^2] per axis), which otherwise
/// spreads the copies at least as much. Returns whether the cloud was moved.
bool regularise_velocity(std::span<Particle> cloud, const Eigen::Vector4d& mean,
                         const Eigen::Matrix4d& covariance, double bandwidth,
                         double prediction_velocity_variance, NormalSampler& rng) noexcept;

/// Kish's effective sample size 1 / sum w^2 of normalised weights.
double effective_sample_size(std::span<const double> weights) noexcept;

/// The bandwidth of the Gaussian kernel that minimises the mean integrated squared error
/// for a Gaussian density in 4 dimensions from `samples` independent draws,
/// h = (4 / ((d + 2) n))^(1 / (d + 4)) (Silverman 1986, eq. 4.14; Musso et al. 2001).
double optimal_kernel_bandwidth(double samples) noexcept;

/// Equal-weight mean and covariance [x, vx, y, vy] of particles added one at a time (sums
/// about the first particle, so they stay small: positions are ~1e4 m). `add` is inline on
/// scalar sums (the 10 distinct products) so a local accumulator stays in registers inside
/// the loop that already holds each particle.
class MomentAccumulator {
 public:
  void clear() noexcept { count_ = 0; }
  [[gnu::always_inline]] void add(const Particle& p) noexcept {
    if (count_ == 0) {
      reference_ = p;
      s0_ = s1_ = s2_ = s3_ = 0.0;
      s00_ = s01_ = s02_ = s03_ = s11_ = s12_ = s13_ = s22_ = s23_ = s33_ = 0.0;
    }
    const double d0 = p.x - reference_.x, d1 = p.vx - reference_.vx;
    const double d2 = p.y - reference_.y, d3 = p.vy - reference_.vy;
    s0_ += d0, s1_ += d1, s2_ += d2, s3_ += d3;
    s00_ += d0 * d0, s01_ += d0 * d1, s02_ += d0 * d2, s03_ += d0 * d3;
    s11_ += d1 * d1, s12_ += d1 * d2, s13_ += d1 * d3;
    s22_ += d2 * d2, s23_ += d2 * d3, s33_ += d3 * d3;
    ++count_;
  }
  std::size_t count() const noexcept { return count_; }
  /// Zero mean and covariance when nothing was added.
  void moments(Eigen::Vector4d& mean, Eigen::Matrix4d& covariance) const noexcept;

 private:
  std::size_t count_ = 0;
  Particle reference_;
  double s0_ = 0, s1_ = 0, s2_ = 0, s3_ = 0;
  double s00_ = 0, s01_ = 0, s02_ = 0, s03_ = 0, s11_ = 0, s12_ = 0, s13_ = 0, s22_ = 0, s23_ = 0,
         s33_ = 0;
};

/// The moments a cloud of parents with `mean` and `covariance` has after `propagate` by
/// `dynamics`, exactly: F m and F P F' + G G' sigma^2 (the noise's own moments, not draws).
void predict_moments(const ModelDynamics& dynamics, Eigen::Vector4d& mean,
                     Eigen::Matrix4d& covariance) noexcept;

/// The posterior mean velocity of particles predicted with `predicted_mean` and
/// `predicted_covariance` whose posterior mean position is (x, y), by conditioning on the
/// position: the likelihood depends on the position only, so E[v|Z] = E[E[v|p] | Z], and
/// under the (Gaussian) predicted density E[v|p] = m_v + P_vp P_pp^-1 (p - m_p) is linear,
/// so E[v|Z] = m_v + P_vp P_pp^-1 (E[p|Z] - m_p). Returns false (velocity untouched) when
/// P_pp is not positive definite.
bool velocity_given_position(const Eigen::Vector4d& predicted_mean,
                             const Eigen::Matrix4d& predicted_covariance, double x, double y,
                             double& vx, double& vy) noexcept;

/// Weighted mean and covariance [x, vx, y, vy] of particles with weights summing to 1.
void weighted_moments(std::span<const Particle> particles, std::span<const double> weights,
                      Eigen::Vector4d& mean, Eigen::Matrix4d& covariance) noexcept;

/// The weight and weighted mean of a leading block of a cloud (the MMBPF's survivors).
struct BlockMean {
  double mass = 0.0;
  Eigen::Vector4d mean = Eigen::Vector4d::Zero();  // zero when mass is 0
};
/// The same, also giving the first `head` particles' BlockMean from the same pass (the
/// running sums at particle `head`), so the block costs no pass of its own.
void weighted_moments(std::span<const Particle> particles, std::span<const double> weights,
                      std::size_t head, Eigen::Vector4d& mean, Eigen::Matrix4d& covariance,
                      BlockMean& head_mean) noexcept;

}  // namespace skytrack::bernoulli
