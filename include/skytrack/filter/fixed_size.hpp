#pragma once
// Runs a hot product on fixed-size Eigen matrices when the sizes are the common ones.
// StateMat and friends are bounded-dynamic (any layout fits), but Eigen's products on
// runtime sizes are several times slower than on compile-time ones; 4 and 6 states (2-D and
// 3-D position and velocity) and 2-4 measurement components cover nearly every track.
#include <type_traits>

namespace skytrack {

template <int N>
using SizeTag = std::integral_constant<int, N>;

/// Calls f(SizeTag<n>{}) for n = 4 or 6 and returns true; false (f not called) otherwise.
template <class F>
bool with_fixed_state_size(int n, F&& f) {
  switch (n) {
    case 4:
      f(SizeTag<4>{});
      return true;
    case 6:
      f(SizeTag<6>{});
      return true;
    default:
      return false;
  }
}

/// Calls f(SizeTag<n>{}, SizeTag<m>{}) for n = 4 or 6 states and m = 2, 3 or 4 measurement
/// components and returns true; false (f not called) otherwise.
template <class F>
bool with_fixed_sizes(int n, int m, F&& f) {
  return with_fixed_state_size(n,
                               [&](auto state) {
                                 switch (m) {
                                   case 2:
                                     f(state, SizeTag<2>{});
                                     return;
                                   case 3:
                                     f(state, SizeTag<3>{});
                                     return;
                                   case 4:
                                     f(state, SizeTag<4>{});
                                     return;
                                   default:
                                     return;
                                 }
                               }) &&
         m >= 2 && m <= 4;
}

}  // namespace skytrack
