#include "skytrack/motion/motion_model.hpp"

#include <cmath>
#include <random>
#include <type_traits>

#include <gtest/gtest.h>

#include "motion_test_support.hpp"

namespace skytrack {
namespace {

using test::make_layout;

// One contract, every model: each case names a model and the states it needs.
struct CvCase {
  static AnyMotionModel model() { return ConstantVelocity{1.7, 0.4}; }
  static constexpr bool kAcceleration = false, kTurnRate = false;
};
struct CaCase {
  static AnyMotionModel model() { return ConstantAcceleration{0.8, 0.4}; }
  static constexpr bool kAcceleration = true, kTurnRate = false;
};
struct CtLeftCase {
  static AnyMotionModel model() { return CoordinatedTurn{0.05236, 3.0, 0.4}; }
  static constexpr bool kAcceleration = false, kTurnRate = false;
};
struct CtRightCase {
  static AnyMotionModel model() { return CoordinatedTurn{-0.3, 3.0, 0.4}; }
  static constexpr bool kAcceleration = false, kTurnRate = false;
};
struct CtEstimatedCase {
  static AnyMotionModel model() { return CoordinatedTurnEstimated{2.0, 0.01, 0.4, 0.05}; }
  static constexpr bool kAcceleration = false, kTurnRate = true;
};
struct SingerCase {
  static AnyMotionModel model() { return Singer{5.0, 7.0, 0.4}; }
  static constexpr bool kAcceleration = true, kTurnRate = false;
};

template <class Case>
class MotionModelContract : public ::testing::Test {
 protected:
  /// The smallest layouts the model runs on, and the full one, in 2-D and 3-D.
  static std::vector<StateLayout> layouts() {
    std::vector<StateLayout> out;
    for (int dims : {2, 3}) {
      out.push_back(make_layout(dims, Case::kAcceleration, Case::kTurnRate));
      out.push_back(make_layout(dims, true, true));
    }
    return out;
  }
  static StateVec some_state(const StateLayout& layout) {
    std::mt19937 rng(42);
    std::normal_distribution<double> normal(0.0, 100.0);
    StateVec x(layout.size());
    for (int i = 0; i < x.size(); ++i) x[i] = normal(rng);
    if (layout.turn_rate) x[layout.turn_rate_index()] = 0.04;
    return x;
  }
  /// F and Q of the model at x over dt, whatever its kind.
  static void terms(const StateLayout& layout, const StateVec& x, double dt, StateMat& F,
                    StateMat& Q) {
    std::visit(
        [&](const auto& m) {
          if constexpr (std::is_same_v<std::decay_t<decltype(m)>, CoordinatedTurnEstimated>) {
            m.linearise(layout, x, dt, F, Q);
          } else {
            m.discretise(layout, dt, F, Q);
          }
        },
        Case::model());
  }
};

using AllModels =
    ::testing::Types<CvCase, CaCase, CtLeftCase, CtRightCase, CtEstimatedCase, SingerCase>;
TYPED_TEST_SUITE(MotionModelContract, AllModels);

TYPED_TEST(MotionModelContract, ProcessNoiseIsSymmetricPsd) {
  for (const StateLayout& layout : this->layouts()) {
    for (double dt : {0.01, 1.0, 10.0, 60.0}) {
      // GIVEN the model on a layout; WHEN Q(dt) is built
      StateMat F, Q;
      this->terms(layout, this->some_state(layout), dt, F, Q);
      // THEN Q is square of the layout's size, symmetric and positive semi-definite
      ASSERT_EQ(Q.rows(), layout.size());
      ASSERT_EQ(F.rows(), layout.size());
      EXPECT_LT((Q - Q.transpose()).norm(), 1e-12 * (1.0 + Q.norm()));
      EXPECT_GE(test::min_eigenvalue(Q), -1e-9 * (1.0 + Q.norm()))
          << "dims " << layout.dims << " dt " << dt;
    }
  }
}

TYPED_TEST(MotionModelContract, SupportsItsMinimalLayoutAndPredictsSymmetricPsd) {
  for (const StateLayout& layout : this->layouts()) {
    const AnyMotionModel model = TypeParam::model();
    ASSERT_TRUE(supports(model, layout));
    // GIVEN a random PD prior; WHEN predicted 3 s; THEN P stays symmetric PSD and finite
    Gaussian prior;
    prior.mean = this->some_state(layout);
    const int n = layout.size();
    Eigen::MatrixXd A = Eigen::MatrixXd::Random(n, n);
    prior.covariance = A * A.transpose() + Eigen::MatrixXd::Identity(n, n);
    const Gaussian predicted = predict(model, layout, prior, 3.0);
    ASSERT_EQ(predicted.mean.size(), n);
    EXPECT_TRUE(predicted.covariance.allFinite());
    EXPECT_EQ((predicted.covariance - predicted.covariance.transpose()).norm(), 0.0);
    EXPECT_GE(test::min_eigenvalue(predicted.covariance), -1e-9 * predicted.covariance.norm());
  }
}

TYPED_TEST(MotionModelContract, LinearDiscretisationComposesOverSplitIntervals) {
  // F(a + b) = F(b) F(a) and Q(a + b) = F(b) Q(a) F(b)' + Q(b): the discretisation is exact.
  if (std::is_same_v<TypeParam, CtEstimatedCase>) GTEST_SKIP() << "non-linear";
  for (const StateLayout& layout : this->layouts()) {
    const StateVec x = this->some_state(layout);
    StateMat Fa, Qa, Fb, Qb, Fab, Qab;
    this->terms(layout, x, 1.3, Fa, Qa);
    this->terms(layout, x, 2.9, Fb, Qb);
    this->terms(layout, x, 4.2, Fab, Qab);
    EXPECT_LT((Fab - Fb * Fa).norm(), 1e-10 * Fab.norm());
    EXPECT_LT((Qab - (Fb * Qa * Fb.transpose() + Qb)).norm(), 1e-10 * Qab.norm());
  }
}

TYPED_TEST(MotionModelContract, APredictionThroughTheMemoIsThePlainPredictionToTheBit) {
  // GIVEN one memo for the model, and intervals that repeat, alternate, and replace its two
  // kept entries (a snapshot radar's 4 s, a missed look's 8 s, a rotating radar's odd ones)
  for (const StateLayout& layout : this->layouts()) {
    const AnyMotionModel model = TypeParam::model();
    DiscretisationMemo memo;
    Gaussian prior;
    prior.mean = this->some_state(layout);
    const int n = layout.size();
    const Eigen::MatrixXd A = Eigen::MatrixXd::Random(n, n);
    prior.covariance = A * A.transpose() + Eigen::MatrixXd::Identity(n, n);
    Gaussian through_memo;
    for (double dt : {4.0, 4.0, 8.0, 4.0, 8.0, 3.7, 4.0, 0.0, -2.5, 3.7, 4.0}) {
      // WHEN predicted through the memo and without it
      predict(model, layout, prior, dt, memo, through_memo);
      const Gaussian plain = predict(model, layout, prior, dt);
      // THEN the numbers are identical, not just close
      EXPECT_EQ(through_memo.mean, plain.mean) << "dt " << dt;
      EXPECT_EQ(through_memo.covariance, plain.covariance) << "dt " << dt;
    }
  }
}

TEST(DiscretisationMemo, DiscretisesEachOfItsLastTwoIntervalsOnce) {
  DiscretisationMemo memo;
  int discretised = 0;
  const auto discretise = [&](double dt, StateMat& F, StateMat& Q) {
    ++discretised;
    F = StateMat::Identity(4, 4) * dt;
    Q = StateMat::Identity(4, 4);
  };
  // GIVEN predictions over 4 s and 8 s, alternating; THEN each is discretised once
  for (int k = 0; k < 5; ++k) {
    EXPECT_EQ(memo.at(4.0, discretise).F(0, 0), 4.0);
    EXPECT_EQ(memo.at(8.0, discretise).F(0, 0), 8.0);
  }
  EXPECT_EQ(discretised, 2);
  // WHEN a third interval comes; THEN it replaces the older entry, and the newer stays
  EXPECT_EQ(memo.at(3.0, discretise).F(0, 0), 3.0);
  EXPECT_EQ(memo.at(8.0, discretise).F(0, 0), 8.0);
  EXPECT_EQ(discretised, 3);
  EXPECT_EQ(memo.at(4.0, discretise).F(0, 0), 4.0);
  EXPECT_EQ(discretised, 4);
}

TYPED_TEST(MotionModelContract, ZeroDtIsIdentity) {
  const StateLayout layout = this->layouts().front();
  Gaussian prior;
  prior.mean = this->some_state(layout);
  prior.covariance = StateMat::Identity(layout.size(), layout.size());
  const Gaussian predicted = predict(TypeParam::model(), layout, prior, 0.0);
  EXPECT_EQ(predicted.mean, prior.mean);
  EXPECT_EQ(predicted.covariance, prior.covariance);
}

TEST(MotionModel, MakeMotionModelReadsTheParametersOfItsType) {
  using config::MotionModelType;
  config::MotionModelSpec spec{.name = "ct",
                               .type = MotionModelType::kCoordinatedTurn,
                               .accel_sigma = 3.0,
                               .turn_rate = -0.05,
                               .vertical_accel_sigma = 0.2};
  const AnyMotionModel ct = make_motion_model(spec);
  ASSERT_TRUE(std::holds_alternative<CoordinatedTurn>(ct));
  EXPECT_EQ(std::get<CoordinatedTurn>(ct).turn_rate, -0.05);
  EXPECT_EQ(std::get<CoordinatedTurn>(ct).accel_sigma, 3.0);
  EXPECT_EQ(std::get<CoordinatedTurn>(ct).vertical_accel_sigma, 0.2);
  spec.type = MotionModelType::kSinger;
  spec.time_constant = 12.0;
  const AnyMotionModel singer = make_motion_model(spec);
  ASSERT_TRUE(std::holds_alternative<Singer>(singer));
  EXPECT_EQ(std::get<Singer>(singer).time_constant, 12.0);
  spec.type = MotionModelType::kConstantAcceleration;
  spec.jerk_sigma = 0.7;
  EXPECT_EQ(std::get<ConstantAcceleration>(make_motion_model(spec)).jerk_sigma, 0.7);
  spec.type = MotionModelType::kCoordinatedTurnEstimated;
  spec.turn_rate_sigma = 0.02;
  EXPECT_EQ(std::get<CoordinatedTurnEstimated>(make_motion_model(spec)).turn_rate_sigma, 0.02);
}

TEST(MotionModel, LayoutForAddsOnlyTheStatesTheModelsNeed) {
  using config::MotionModelType;
  std::vector<config::MotionModelSpec> specs = {
      {.name = "cv", .type = MotionModelType::kConstantVelocity},
      {.name = "ct_left", .type = MotionModelType::kCoordinatedTurn, .turn_rate = 0.05},
      {.name = "ct_right", .type = MotionModelType::kCoordinatedTurn, .turn_rate = -0.05}};
  EXPECT_EQ(layout_for(specs, 3), make_layout(3));
  specs.push_back({.name = "singer", .type = MotionModelType::kSinger});
  EXPECT_EQ(layout_for(specs, 2), make_layout(2, true, false));
  specs.push_back({.name = "ctw", .type = MotionModelType::kCoordinatedTurnEstimated});
  const StateLayout full = layout_for(specs, 3);
  EXPECT_EQ(full, make_layout(3, true, true));
  EXPECT_EQ(full.size(), 10);
  EXPECT_FALSE(supports(Singer{}, make_layout(3)));
  EXPECT_FALSE(supports(CoordinatedTurnEstimated{}, make_layout(3, true)));
  EXPECT_TRUE(supports(ConstantVelocity{}, full));
}

}  // namespace
}  // namespace skytrack
