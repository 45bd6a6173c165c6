// Paper 001's existence and model-probability equations, checked by hand.
#include "skytrack/bernoulli/bernoulli_equations.hpp"

#include <array>

#include <gtest/gtest.h>

namespace skytrack::bernoulli {
namespace {

TEST(BernoulliEquations, PredictedExistenceMixesBirthAndSurvivalEq9) {
  // 0.01 (1 - 0.3) + 0.99 0.3 = 0.007 + 0.297
  EXPECT_NEAR(predict_existence(0.3, 0.99, 0.01), 0.304, 1e-15);
  EXPECT_NEAR(predict_existence(0.0, 0.99, 0.01), 0.01, 1e-15);
}

TEST(BernoulliEquations, OneMinusDeltaEq15) {
  // 1 - 0.98 + 0.98 * 100
  EXPECT_NEAR(one_minus_delta(0.98, 100.0), 98.02, 1e-12);
  EXPECT_NEAR(one_minus_delta(0.98, 0.0), 0.02, 1e-15);  // nothing seen: only a miss
}

TEST(BernoulliEquations, UpdatedExistenceEq13) {
  // GIVEN q_pred 0.304, mu (0.5, 0.5), 1 - Delta (2, 0.5): sum = 1.25, numerator 0.38,
  // denominator 1 - 0.304 + 0.38 = 1.076
  const std::array<double, 2> mu{0.5, 0.5}, omd{2.0, 0.5};
  EXPECT_NEAR(update_existence(0.304, mu, omd), 0.38 / 1.076, 1e-15);
  // A scan with nothing in it lowers q: 0.02 q / (1 - q + 0.02 q)
  const std::array<double, 1> one{1.0}, miss{0.02};
  EXPECT_NEAR(update_existence(0.9, one, miss), 0.018 / 0.118, 1e-15);
}

TEST(BernoulliEquations, ModelProbabilitiesFollowModelLikelihoodsEq17) {
  std::array<double, 3> mu{0.5, 0.3, 0.2};
  const std::array<double, 3> omd{2.0, 1.0, 0.5};  // products 1.0, 0.3, 0.1, sum 1.4
  update_model_probabilities(mu, omd);
  EXPECT_NEAR(mu[0], 1.0 / 1.4, 1e-15);
  EXPECT_NEAR(mu[1], 0.3 / 1.4, 1e-15);
  EXPECT_NEAR(mu[2], 0.1 / 1.4, 1e-15);
}

TEST(BernoulliEquations, ModelProbabilitiesKeptWhenEveryLikelihoodIsZero) {
  std::array<double, 2> mu{0.7, 0.3};
  const std::array<double, 2> omd{0.0, 0.0};
  update_model_probabilities(mu, omd);
  EXPECT_EQ(mu[0], 0.7);
  EXPECT_EQ(mu[1], 0.3);
}

}  // namespace
}  // namespace skytrack::bernoulli
