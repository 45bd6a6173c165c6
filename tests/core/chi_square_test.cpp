#include <cmath>

#include <gtest/gtest.h>

#include "skytrack/core/chi_square.hpp"

namespace skytrack {
namespace {

TEST(ChiSquare, TwoDegreesOfFreedomHasTheClosedForm) {
  // For 2 dof, P(X <= x) = 1 - exp(-x / 2).
  for (const double p : {0.5, 0.9, 0.99, 0.9997}) {
    EXPECT_NEAR(chi_square_quantile(p, 2), -2.0 * std::log(1.0 - p), 1e-9) << p;
  }
}

TEST(ChiSquare, MatchesTabulatedQuantiles) {
  // Standard table values (e.g. Abramowitz & Stegun table 26.8).
  EXPECT_NEAR(chi_square_quantile(0.95, 1), 3.841459, 1e-5);
  EXPECT_NEAR(chi_square_quantile(0.99, 3), 11.344867, 1e-5);
  EXPECT_NEAR(chi_square_quantile(0.999, 4), 18.466827, 1e-5);
  EXPECT_NEAR(chi_square_cdf(9.487729, 4), 0.95, 1e-7);
}

}  // namespace
}  // namespace skytrack
