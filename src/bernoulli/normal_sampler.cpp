// Ziggurat tables and the rare branches (Doornik 2005, "An improved ziggurat method to
// generate normal random samples", ZIGNOR with C = 128, R = 3.442619855899,
// V = 9.91256303526217e-3).
#include "skytrack/bernoulli/normal_sampler.hpp"

#include <cmath>
#include <limits>

namespace skytrack::bernoulli {
namespace {

constexpr double kTailStart = 3.442619855899;       // R: the base layer's right edge
constexpr double kLayerArea = 9.91256303526217e-3;  // V

}  // namespace

NormalSampler::NormalSampler(std::uint64_t seed) {
  for (std::uint64_t& word : state_) {  // splitmix64: never an all-zero state
    seed += 0x9E3779B97F4A7C15ULL;
    std::uint64_t z = seed;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    word = z ^ (z >> 31);
  }
  double f = std::exp(-0.5 * kTailStart * kTailStart);
  x_[0] = kLayerArea / f;  // the base layer: rectangle plus tail
  x_[1] = kTailStart;
  x_[128] = 0.0;
  for (int i = 2; i < 128; ++i) {
    x_[i] = std::sqrt(-2.0 * std::log(kLayerArea / x_[i - 1] + f));
    f = std::exp(-0.5 * x_[i] * x_[i]);
  }
  for (int i = 0; i < 128; ++i) ratio_[i] = x_[i + 1] / x_[i];
}

double NormalSampler::rare_case(int layer, double u) noexcept {
  if (layer == 0) {  // the tail beyond R (Marsaglia 1964)
    double x = 0.0, y = 0.0;
    do {
      x = std::log(uniform()) / kTailStart;
      y = std::log(uniform());
    } while (-2.0 * y < x * x);
    return u < 0.0 ? x - kTailStart : kTailStart - x;
  }
  const double x = u * x_[layer];
  const double f0 = std::exp(-0.5 * (x_[layer] * x_[layer] - x * x));
  const double f1 = std::exp(-0.5 * (x_[layer + 1] * x_[layer + 1] - x * x));
  if (f1 + uniform() * (f0 - f1) < 1.0) return x;
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace skytrack::bernoulli
