// Helpers shared by the exact JPDA's planning (jpda_exact_plan.cpp) and its passes
// (jpda_exact.cpp): event counts saturate instead of overflowing.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>

namespace skytrack::jpda_exact_detail {

inline constexpr std::int64_t kMaxCount = std::numeric_limits<std::int64_t>::max();

inline std::size_t at(int i) {
  return static_cast<std::size_t>(i);
}

inline std::int64_t saturating_add(std::int64_t a, std::int64_t b) {
  std::int64_t r = 0;
  return __builtin_add_overflow(a, b, &r) ? kMaxCount : r;
}

inline std::int64_t saturating_mul(std::int64_t a, std::int64_t b) {
  std::int64_t r = 0;
  return __builtin_mul_overflow(a, b, &r) ? kMaxCount : r;
}

}  // namespace skytrack::jpda_exact_detail
