#pragma once
// Block (local) resampling of one model's cloud when its likelihood factorises (the block
// particle filter of Rebeschini & van Handel 2015, "Can local particle filters beat the curse
// of dimensionality?", Ann. Appl. Probab. 25(5), §2: each block of the state is resampled by
// its own likelihood factor). Used by the MMBPF (paper 001, step 3(3)) for the CV model.
//
// When one plot explains a model's likelihood, that plot's g(z|x), linearised at the plot, is
// N(a; 0, sigma_along^2) N(c; 0, sigma_across^2) in the plot's frame: a = (p - z).along,
// c = (p - z).across (a polar plot: the range residual and the cross-range r (az - az_z); a
// Cartesian plot: x and y). A constant-velocity model moves (a, v.along) and (c, v.across)
// independently, with independent noise, so its state splits into an along block and an
// across block, each informed by its own factor. Resampling the joint cloud by the product
// of the factors lets the sharp one (5 m in range against the CV prediction's 9 m) pick
// particles at random in the other block, whose sample mean then drifts by var / ESS each
// scan; the block filter resamples each block by its own factor, so the across block loses
// only what the azimuth says. The two blocks are paired by output slot (the k-th draw of
// each), which keeps the joint cloud's order and some of its dependence.
#include <span>

#include <Eigen/Core>

#include "skytrack/bernoulli/particle_kernel.hpp"

namespace skytrack::bernoulli {

/// How far a density with this covariance [x, vx, y, vy] is from the product of its two
/// blocks in the plot's frame: the mutual information [nats] between (a, v.along) and
/// (c, v.across) of the Gaussian with it, -1/2 log(det C / (det C_along det C_across)), which
/// is the Kullback-Leibler divergence of the product of the block marginals from the
/// Gaussian; 0 for independent blocks, -1/2 log(1 - rho^2) for one correlation rho across.
/// Infinite when the covariance is not positive definite.
double block_dependence(const ScanPlot& plot, const Eigen::Matrix4d& covariance) noexcept;

/// Resamples `cloud` (equal prior weights: one model's survivors) into all of `out`, the
/// along block (a, v.along) by the factor N(a; 0, sigma_along^2) and the across block
/// (c, v.across) by N(c; 0, sigma_across^2) of `plot`, each systematically (u_along,
/// u_across in [0, 1)), the k-th draws of the two paired into out[k]. `scratch` holds at
/// least 2 cloud.size() values. `estimate` gets the block posterior mean [x, vx, y, vy]: each
/// block's mean under its own factor. Returns false, `out` and `estimate` untouched, when a
/// factor vanishes on every particle or `cloud` or `out` is empty.
bool block_resample(std::span<const Particle> cloud, const ScanPlot& plot, double u_along,
                    double u_across, std::span<double> scratch, std::span<Particle> out,
                    Eigen::Vector4d& estimate) noexcept;

}  // namespace skytrack::bernoulli
