// Tests of plot-to-plot initiation: a target's chain keeps its own plot when a clutter
// chain's wide gate reaches it too, and a chain of M plots within N looks starts a track.
#include "skytrack/tracking/initiator.hpp"

#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

namespace skytrack {
namespace {

PlotMeasurement plot(std::int64_t id, double time, double x, double y) {
  PlotMeasurement p;
  MeasVec sigma = MeasVec::Constant(2, 50.0);
  p.model = MeasurementModel::cartesian(2, 2, sigma);
  p.z = MeasVec::Zero(2);
  p.z << x, y;
  p.time = time;
  p.plot_id = id;
  return p;
}

/// A 2-D radar plot (range sigma 30 m, azimuth 2 mrad) of a target at (x, y), the radar at
/// the origin; azimuth clockwise from north.
PlotMeasurement polar_plot(std::int64_t id, double time, double x, double y) {
  PlotMeasurement p;
  MeasVec sigma = MeasVec::Zero(2);
  sigma << 30.0, 0.002;
  p.model = MeasurementModel::polar(PlatformState{}, false, false, 2, sigma);
  p.z = MeasVec::Zero(2);
  p.z << std::hypot(x, y), std::atan2(x, y);
  p.time = time;
  p.plot_id = id;
  return p;
}

std::vector<std::int64_t> ids(const Initiation& initiation) {
  std::vector<std::int64_t> out;
  for (const PlotMeasurement& p : initiation.plots) out.push_back(p.plot_id);
  return out;
}

const Initiator::Coverage kEverywhere = [](const Eigen::Vector3d&) { return true; };

TEST(Initiator, TargetChainKeepsItsPlotAgainstAnOlderClutterChain) {
  Initiator initiator(config::InitiationSpec{}, 2);
  // Target 1 east at 250 m/s from the origin; clutter plots 2 north-east at 150 m/s, whose
  // chain is made first (its plot comes first in the second batch).
  ASSERT_TRUE(
      initiator.step(1, 10.0, {plot(11, 10.0, 0, 0), plot(21, 10.0, 4000, -4000)}, kEverywhere)
          .empty());
  ASSERT_TRUE(
      initiator.step(2, 20.0, {plot(22, 20.0, 4000, -2500), plot(12, 20.0, 2500, 0)}, kEverywhere)
          .empty());
  ASSERT_EQ(initiator.candidates(), 2u);
  // The target's third plot lies on its chain's prediction and 1.4 km from the clutter
  // chain's, inside that chain's 6 g gate (3.4 km): the nearer chain takes it.
  const std::vector<Initiation>& started =
      initiator.step(3, 30.0, {plot(13, 30.0, 5000, 0)}, kEverywhere);
  ASSERT_EQ(started.size(), 1u);
  EXPECT_EQ(ids(started.front()), (std::vector<std::int64_t>{11, 12, 13}));
  EXPECT_EQ(started.front().scans, 3);
}

TEST(Initiator, CompletedChainNamesItsLastPlotInTheBatch) {
  // The tracker weighs a new track's last plot against the clutter density at that plot of
  // the batch, which it finds by this index.
  Initiator initiator(config::InitiationSpec{}, 2);
  initiator.step(1, 10.0, {plot(1, 10.0, 0, 0)}, kEverywhere);
  initiator.step(2, 20.0, {plot(9, 20.0, -30000, 0), plot(2, 20.0, 2500, 0)}, kEverywhere);
  const std::vector<Initiation>& started = initiator.step(
      3, 30.0, {plot(7, 30.0, 0, 30000), plot(8, 30.0, 0, -30000), plot(3, 30.0, 5000, 0)},
      kEverywhere);
  ASSERT_EQ(started.size(), 1u);
  EXPECT_EQ(ids(started.front()), (std::vector<std::int64_t>{1, 2, 3}));
  EXPECT_EQ(started.front().last, 2);
}

TEST(Initiator, ChainWithoutItsThirdPlotWithinNLooksIsDropped) {
  config::InitiationSpec spec;
  spec.n = 3;  // m = 3 of n = 3: no look may be missed
  Initiator initiator(spec, 2);
  initiator.step(1, 10.0, {plot(1, 10.0, 0, 0)}, kEverywhere);
  initiator.step(2, 20.0, {plot(2, 20.0, 2500, 0)}, kEverywhere);
  ASSERT_EQ(initiator.candidates(), 1u);
  EXPECT_TRUE(initiator.step(3, 30.0, {}, kEverywhere).empty());
  EXPECT_EQ(initiator.candidates(), 0u);
  EXPECT_TRUE(initiator.step(4, 40.0, {plot(4, 40.0, 7500, 0)}, kEverywhere).empty());
}

/// A chain of three plots east at 250 m/s (10, 20 and 30 s), completed and held by the
/// tracker with existence 0.01.
void hold_a_chain(Initiator& initiator) {
  initiator.step(1, 10.0, {plot(1, 10.0, 0, 0)}, kEverywhere);
  initiator.step(2, 20.0, {plot(2, 20.0, 2500, 0)}, kEverywhere);
  const std::vector<Initiation> started =
      initiator.step(3, 30.0, {plot(3, 30.0, 5000, 0)}, kEverywhere);
  ASSERT_EQ(started.size(), 1u);
  EXPECT_FALSE(started.front().held);
  initiator.hold(started.front(), 0.01);
  EXPECT_EQ(initiator.candidates(), 1u);
}

TEST(Initiator, AHeldChainCompletesAgainWithItsNextPlot) {
  Initiator initiator(config::InitiationSpec{}, 2);
  hold_a_chain(initiator);
  // Its next plot, on its constant-velocity line, completes it again, held, with the
  // existence the tracker gave it.
  const std::vector<Initiation>& again =
      initiator.step(4, 40.0, {plot(9, 40.0, 0, 30000), plot(4, 40.0, 7500, 0)}, kEverywhere);
  ASSERT_EQ(again.size(), 1u);
  EXPECT_EQ(ids(again.front()), (std::vector<std::int64_t>{1, 2, 3, 4}));
  EXPECT_TRUE(again.front().held);
  EXPECT_EQ(again.front().existence, 0.01);
  EXPECT_EQ(again.front().scans, 4);
  EXPECT_EQ(again.front().last, 1);
  EXPECT_EQ(initiator.candidates(), 0u);
}

TEST(Initiator, AHeldChainLookedAtWithoutAPlotIsDropped) {
  // As its track would be: a look without a plot takes a weak track's existence under the
  // deletion threshold.
  Initiator initiator(config::InitiationSpec{}, 2);
  hold_a_chain(initiator);
  // A batch that does not cover it is no look: the chain waits.
  const Initiator::Coverage nowhere = [](const Eigen::Vector3d&) { return false; };
  EXPECT_TRUE(initiator.step(4, 40.0, {}, nowhere).empty());
  EXPECT_EQ(initiator.candidates(), 1u);
  // A look with no plot on its line drops it; the plot that comes a look later seeds anew.
  EXPECT_TRUE(initiator.step(5, 44.0, {plot(8, 44.0, 0, 30000)}, kEverywhere).empty());
  EXPECT_EQ(initiator.candidates(), 0u);
  EXPECT_TRUE(initiator.step(6, 50.0, {plot(5, 50.0, 10000, 0)}, kEverywhere).empty());
}

TEST(Initiator, ThirdPlotIsGatedAlongTheLineOfSightByTheRangeSigma) {
  // A target 100 km north flying east at 200 m/s, seen every 4 s: 200 m cross-range sigma,
  // 30 m in range. The third plot's gate: four sigma plus a 6 g manoeuvre (480 m), 2080 m
  // across the line of sight and 720 m along it.
  const auto third = [](double x, double y) {
    Initiator initiator(config::InitiationSpec{}, 2);
    initiator.step(1, 4.0, {polar_plot(1, 4.0, 0, 100000)}, kEverywhere);
    initiator.step(2, 8.0, {polar_plot(2, 8.0, 800, 100000)}, kEverywhere);
    return initiator.step(3, 12.0, {polar_plot(3, 12.0, x, y)}, kEverywhere).size();
  };
  // The prediction is (1600, 100000). 1200 m across the line of sight: a track.
  EXPECT_EQ(third(2800, 100000), 1u);
  // 1200 m along it (a range error of 40 sigma, inside the cross-range circle): none.
  EXPECT_EQ(third(1600, 101200), 0u);
  // 600 m along it (a manoeuvre): a track.
  EXPECT_EQ(third(1600, 100600), 1u);
}

TEST(ChainManoeuvre, ComesFromTheModelsAndIsBoundedBySixG) {
  // The default profile's models: CV 2, turns of 0.15 rad/s with 6 m/s^2: 18 m/s^2 and
  // 0.15 rad/s x speed, so a 100 m/s chain may turn at 33 m/s^2 and a 400 m/s one at 6 g.
  const std::vector<config::MotionModelSpec> models = config::TrackingProfile{}.motion_models;
  const ChainManoeuvre m = ChainManoeuvre::from_models(models, 2);
  EXPECT_DOUBLE_EQ(m.accel, 18.0);
  EXPECT_DOUBLE_EQ(m.turn_rate, 0.15);
  EXPECT_DOUBLE_EQ(m.at(100.0), 33.0);
  EXPECT_DOUBLE_EQ(m.at(400.0), ChainManoeuvre::kMaxAcceleration);
  // One CV model with q = 0.5 (the peer benchmark's): 3 sigma, at any speed.
  const ChainManoeuvre cv =
      ChainManoeuvre::from_models({{.name = "cv",
                                    .type = config::MotionModelType::kConstantVelocity,
                                    .accel_sigma = std::sqrt(0.5)}},
                                  2);
  EXPECT_NEAR(cv.at(5.0), 3.0 * std::sqrt(0.5), 1e-12);
  // An acceleration in the state has no bound: 6 g, as without models.
  const ChainManoeuvre ca = ChainManoeuvre::from_models(
      {{.name = "ca", .type = config::MotionModelType::kConstantAcceleration}}, 2);
  EXPECT_DOUBLE_EQ(ca.at(5.0), ChainManoeuvre::kMaxAcceleration);
  EXPECT_DOUBLE_EQ(ChainManoeuvre::from_models({}, 2).at(5.0), ChainManoeuvre::kMaxAcceleration);
}

TEST(ChainManoeuvre, ASlowChainTakesNoPlotItsModelsCannotReach) {
  // A boat at 5 m/s seen every 2.5 s with 5 m plots; its third plot is missed and a clutter
  // plot lies 60 m off the chain's prediction. With 6 g the gate is 4 x 10 m + 187 m: the
  // chain takes the clutter plot and starts a track on it. With the models' 2.25 m/s^2
  // (3 x 0.5, and a 0.15 rad/s turn at 5 m/s) it is 4 x 10 m + 7 m: no track.
  const auto cartesian = [](std::int64_t id, double time, double x, double y) {
    PlotMeasurement p = plot(id, time, x, y);
    p.model = MeasurementModel::cartesian(2, 2, MeasVec::Constant(2, 5.0));
    return p;
  };
  const auto started = [&](ChainManoeuvre manoeuvre) {
    Initiator initiator(config::InitiationSpec{}, 2, manoeuvre);
    initiator.step(1, 2.5, {cartesian(1, 2.5, 0, 0)}, kEverywhere);
    initiator.step(2, 5.0, {cartesian(2, 5.0, 12.5, 0)}, kEverywhere);
    return initiator.step(3, 7.5, {cartesian(3, 7.5, 25, 60)}, kEverywhere).size();
  };
  EXPECT_EQ(started(ChainManoeuvre{}), 1u);
  const ChainManoeuvre boat = ChainManoeuvre::from_models(
      {{.name = "cv", .type = config::MotionModelType::kConstantVelocity, .accel_sigma = 0.5},
       {.name = "ct",
        .type = config::MotionModelType::kCoordinatedTurn,
        .accel_sigma = 0.5,
        .turn_rate = 0.15}},
      2);
  EXPECT_EQ(started(boat), 0u);
}

}  // namespace
}  // namespace skytrack
