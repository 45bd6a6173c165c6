// The ziggurat normal sampler: moments, tails and determinism.
#include "skytrack/bernoulli/normal_sampler.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace skytrack::bernoulli {
namespace {

TEST(BernoulliNormalSampler, MomentsAndTailsOfAStandardNormal) {
  NormalSampler rng(7);
  constexpr int kDraws = 400000;
  double sum = 0, sum2 = 0, sum4 = 0;
  int beyond_3 = 0, beyond_1 = 0;
  for (int i = 0; i < kDraws; ++i) {
    const double x = rng.normal();
    sum += x;
    sum2 += x * x;
    sum4 += x * x * x * x;
    beyond_3 += std::abs(x) > 3.0;
    beyond_1 += std::abs(x) > 1.0;
  }
  // Tolerances: about 5 standard errors at 4e5 draws.
  EXPECT_NEAR(sum / kDraws, 0.0, 0.008);
  EXPECT_NEAR(sum2 / kDraws, 1.0, 0.012);
  EXPECT_NEAR(sum4 / kDraws, 3.0, 0.06);
  EXPECT_NEAR(static_cast<double>(beyond_1) / kDraws, 0.317311, 0.004);
  EXPECT_NEAR(static_cast<double>(beyond_3) / kDraws, 0.0026998, 0.0004);
}

TEST(BernoulliNormalSampler, SameSeedSameDrawsOtherSeedOtherDraws) {
  NormalSampler a(42), b(42), c(43);
  int differ = 0;
  for (int i = 0; i < 1000; ++i) {
    const double x = a.normal();
    EXPECT_EQ(x, b.normal());
    differ += x != c.normal();
  }
  EXPECT_GT(differ, 990);
}

TEST(BernoulliNormalSampler, UniformAndIndexStayInRange) {
  NormalSampler rng(3);
  double sum = 0;
  for (int i = 0; i < 100000; ++i) {
    const double u = rng.uniform();
    ASSERT_GT(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
    ASSERT_LT(rng.index(7), 7u);
  }
  EXPECT_NEAR(sum / 100000, 0.5, 0.005);
}

}  // namespace
}  // namespace skytrack::bernoulli
