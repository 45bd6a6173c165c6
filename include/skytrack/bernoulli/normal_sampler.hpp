#pragma once
// Fast seeded standard-normal and uniform draws for the particle filters: a particle filter
// draws thousands of normals per scan, and std::normal_distribution over std::mt19937_64
// costs several times the rest of a particle's prediction. Engine: xoshiro256++ (Blackman &
// Vigna 2021), seeded through splitmix64; normals: the ziggurat with 128 layers (Marsaglia &
// Tsang 2000, in Doornik's 2005 form "An improved ziggurat method"), exact up to the double
// resolution. Deterministic for a seed.
#include <array>
#include <cmath>
#include <cstdint>

namespace skytrack::bernoulli {

class NormalSampler {
 public:
  explicit NormalSampler(std::uint64_t seed);

  /// A draw from N(0, 1).
  double normal() noexcept {
    for (;;) {
      const std::uint64_t bits = next();
      const int layer = static_cast<int>(bits & 0x7F);
      const double u = 2.0 * to_unit(bits) - 1.0;  // uses the top 53 bits, not the layer's
      if (std::abs(u) < ratio_[layer]) return u * x_[layer];
      const double value = rare_case(layer, u);
      if (value == value) return value;  // NaN: rejected in a wedge, draw again
    }
  }
  /// A draw from U(0, 1), never 0.
  double uniform() noexcept { return to_unit(next()); }
  /// An index uniform in [0, n) (Lemire's multiply-shift; bias below 2^-32 for n < 2^32).
  std::uint32_t index(std::uint32_t n) noexcept {
    return static_cast<std::uint32_t>(((next() >> 32) * static_cast<std::uint64_t>(n)) >> 32);
  }

 private:
  static double to_unit(std::uint64_t bits) noexcept {
    return (static_cast<double>(bits >> 11) + 0.5) * 0x1.0p-53;
  }
  double rare_case(int layer, double u) noexcept;  // the tail and the wedges

  std::uint64_t next() noexcept {  // xoshiro256++
    const std::uint64_t result = rotl(state_[0] + state_[3], 23) + state_[0];
    const std::uint64_t t = state_[1] << 17;
    state_[2] ^= state_[0];
    state_[3] ^= state_[1];
    state_[1] ^= state_[2];
    state_[0] ^= state_[3];
    state_[2] ^= t;
    state_[3] = rotl(state_[3], 45);
    return result;
  }
  static std::uint64_t rotl(std::uint64_t x, int k) noexcept { return (x << k) | (x >> (64 - k)); }

  std::array<std::uint64_t, 4> state_{};
  std::array<double, 129> x_{};      // layer edges
  std::array<double, 128> ratio_{};  // x_[i + 1] / x_[i]
};

}  // namespace skytrack::bernoulli
