// Regularised lower incomplete gamma P(a, x) by its series (x < a + 1) or continued fraction
// (Numerical Recipes §6.2 / Abramowitz & Stegun 6.5); the quantile by bisection.
#include "skytrack/core/chi_square.hpp"

#include <cmath>

namespace skytrack {
namespace {

double regularised_gamma_p(double a, double x) {
  if (x <= 0.0) return 0.0;
  const double log_prefix = a * std::log(x) - x - std::lgamma(a);
  if (x < a + 1.0) {
    double term = 1.0 / a, sum = term;
    for (int n = 1; n < 500 && std::abs(term) > std::abs(sum) * 1e-16; ++n) {
      term *= x / (a + n);
      sum += term;
    }
    return sum * std::exp(log_prefix);
  }
  // Lentz's continued fraction for Q(a, x).
  const double tiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 500; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < 1e-16) break;
  }
  return 1.0 - std::exp(log_prefix) * h;
}

}  // namespace

double chi_square_cdf(double x, int dof) noexcept {
  return regularised_gamma_p(0.5 * dof, 0.5 * x);
}

double chi_square_quantile(double p, int dof) noexcept {
  double low = 0.0, high = 10.0 * dof + 100.0;
  for (int i = 0; i < 200 && high - low > 1e-12 * high; ++i) {
    const double mid = 0.5 * (low + high);
    (chi_square_cdf(mid, dof) < p ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

}  // namespace skytrack
