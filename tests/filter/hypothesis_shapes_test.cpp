// hypothesise() with kept innovation shapes must give the numbers of a whole innovation per
// plot, bit for bit: the gater and the branch layer rely on it to leave tracks unchanged.
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "filter_test_support.hpp"
#include "skytrack/filter/imm_filter.hpp"

namespace skytrack {
namespace {

ImmFilter two_cv_modes() {
  Eigen::MatrixXd transition(2, 2);
  transition << 0.9, 0.1, 0.2, 0.8;
  auto filter = ImmFilter::create({ConstantVelocity{0.5, 1.0}, ConstantVelocity{5.0, 1.0}},
                                  {"quiet", "noisy"}, transition, test::layout_2d(), {});
  EXPECT_TRUE(filter) << filter.error().message;
  return *filter;
}

ImmEstimate posterior_at(double x, double y) {
  StateMat p1 = StateMat::Zero(4, 4), p2 = StateMat::Zero(4, 4);
  p1.diagonal() << 400, 25, 400, 25;
  p2.diagonal() << 900, 100, 900, 100;
  p1(0, 1) = p1(1, 0) = 20;
  ImmEstimate posterior;
  posterior.modes = {test::gaussian({x, 100, y, -50}, p1),
                     test::gaussian({x + 30, 110, y, -40}, p2)};
  posterior.probabilities = Eigen::Vector2d(0.8, 0.2);
  return posterior;
}

void expect_same(const PlotHypothesis& whole, const PlotHypothesis& shaped) {
  ASSERT_EQ(whole.per_mode.size(), shaped.per_mode.size());
  EXPECT_EQ(whole.usable, shaped.usable);
  EXPECT_EQ(whole.likelihood, shaped.likelihood);
  EXPECT_EQ(whole.min_nis, shaped.min_nis);
  EXPECT_EQ(whole.max_nis, shaped.max_nis);
  for (std::size_t j = 0; j < whole.per_mode.size(); ++j) {
    const Innovation& a = whole.per_mode[j];
    const Innovation& b = shaped.per_mode[j];
    EXPECT_EQ(a.ok, b.ok);
    EXPECT_EQ(a.nis, b.nis);
    EXPECT_EQ(a.log_likelihood, b.log_likelihood);
    if (!a.ok) continue;
    EXPECT_EQ(a.residual, b.residual);
    EXPECT_EQ(a.S, b.S);
    EXPECT_EQ(a.gain, b.gain);
    EXPECT_EQ(a.H, b.H);
    EXPECT_EQ(a.R, b.R);
  }
}

TEST(HypothesisShapes, KeptShapesGiveEachPlotTheNumbersOfAWholeInnovationAndItsNis) {
  const ImmFilter filter = two_cv_modes();
  // Plots of three measurement models in turn (two polar noises and a Cartesian one), so the
  // kept shapes are remade whenever the model changes, and a plot with a NaN.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<PlotMeasurement> plots;
  for (int k = 0; k < 6; ++k) {
    plots.push_back(test::polar_2d(10'000.0 + 40.0 * k, 0.785 + 0.001 * k, 30.0, 0.002));
    plots.push_back(test::polar_2d(10'020.0 - 25.0 * k, 0.786 - 0.002 * k, 30.0, 0.002));
    plots.push_back(test::polar_2d(9'990.0, 0.784, 50.0, 0.004));
    plots.push_back(test::cartesian_xy(7'100.0 + 30.0 * k, 7'000.0, 40.0));
  }
  plots.push_back(test::polar_2d(nan, 0.785, 30.0, 0.002));
  HypothesisShapes shapes;
  for (const auto& [x, y] : {std::pair{7'070.0, 7'070.0}, std::pair{7'200.0, 6'900.0}}) {
    const ImmEstimate predicted = filter.predict(posterior_at(x, y), 2.0);
    shapes.clear();  // a new prediction
    for (const PlotMeasurement& plot : plots) {
      const PlotHypothesis whole = filter.hypothesise(predicted, plot);
      const PlotHypothesis shaped = filter.hypothesise(predicted, plot, shapes);
      expect_same(whole, shaped);
      // The cheap gate test: the same smallest NIS, +infinity for a plot no mode can take.
      EXPECT_EQ(filter.min_nis(predicted, plot, shapes),
                whole.usable ? whole.min_nis : std::numeric_limits<double>::infinity());
    }
  }
  EXPECT_FALSE(
      filter.hypothesise(filter.predict(posterior_at(0, 0), 2.0), plots.back(), shapes).usable);
}

}  // namespace
}  // namespace skytrack
