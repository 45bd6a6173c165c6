// The per-track hot path (Gaussian predict, innovate, Kalman and PDA updates) must not touch
// the heap: StateVec/StateMat/MeasVec... are bounded-size Eigen types that live on the stack.
//
// Two checks:
//  1. Eigen's own: EIGEN_RUNTIME_NO_MALLOC + set_is_malloc_allowed(false) asserts on any Eigen
//     heap allocation. It only works in assert builds (skipped under NDEBUG) and only sees
//     Eigen code compiled with the macro, i.e. instantiated in this file.
//  2. A counting malloc (glibc only, not under ASan/TSan, which own malloc): every malloc in
//     the process, library code included, is counted while the window is open. Works in
//     release builds too.
#define EIGEN_RUNTIME_NO_MALLOC  // before any Eigen include
#include <Eigen/Core>

#include <atomic>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include <gtest/gtest.h>

#include "filter_test_support.hpp"
#include "skytrack/filter/innovation.hpp"
#include "skytrack/filter/pda.hpp"
#include "skytrack/motion/motion_model.hpp"

#include "../counting_malloc.hpp"

namespace skytrack {
namespace {

struct HotPathInputs {
  StateLayout layout{3, true, true};
  AnyMotionModel cv = ConstantVelocity{1.5, 0.5};
  AnyMotionModel ct = CoordinatedTurnEstimated{2.0, 0.01, 0.5, 0.05};
  AnyMotionModel singer = Singer{5.0, 10.0, 0.5};
  Gaussian prior;
  PlotMeasurement plot;
  config::MeasurementSpec ekf;
  config::MeasurementSpec unscented;

  HotPathInputs() {
    prior.mean = StateVec::Zero(layout.size());
    prior.mean << 20000, -150, 30000, 40, 5000, 2, 1, -1, 0, 0.02;
    prior.covariance = StateMat::Identity(layout.size(), layout.size()) * 400.0;
    PlatformState platform;
    platform.velocity = {200.0, 0.0, 0.0};
    platform.attitude = {0.3, 0.02, -0.05};
    MeasVec z(4), s(4);
    z << 36400.0, 0.8, 0.13, -60.0;
    s << 30.0, 0.003, 0.006, 2.0;
    plot = {MeasurementModel::polar(platform, true, true, 3, s), z, 2.0, 1};
    unscented.update = config::MeasurementUpdate::kUnscented;
  }
};

#if SKYTRACK_COUNTING_MALLOC
/// One pass over the hot path; returns something derived from every result.
double hot_path(const HotPathInputs& in) {
  const Gaussian a = predict(in.cv, in.layout, in.prior, 2.0);
  const Gaussian b = predict(in.ct, in.layout, in.prior, 2.0);
  const Gaussian c = predict(in.singer, in.layout, in.prior, 2.0);
  const Innovation ekf = innovate(a, in.layout, in.plot, in.ekf);
  const Innovation ukf = innovate(b, in.layout, in.plot, in.unscented);
  const Gaussian updated = kalman_update(c, innovate(c, in.layout, in.plot, in.ekf));
  const double beta[2] = {0.6, 0.3};
  const Innovation both[2] = {ekf, ekf};
  const Gaussian mixed = pda_update(a, std::span(both), std::span(beta), 0.1);
  return ekf.nis + ukf.nis + updated.mean[0] + mixed.covariance(0, 0);
}
#endif

TEST(HotPathAllocation, EigenRuntimeNoMallocAroundPredictAndInnovate) {
#ifdef NDEBUG
  GTEST_SKIP() << "EIGEN_RUNTIME_NO_MALLOC only checks in assert builds";
#else
  // GIVEN the inputs prepared outside the window
  const HotPathInputs in;
  const AnyMotionModel model = ConstantVelocity{1.5, 0.5};
  // WHEN one predict and one innovate run with Eigen heap allocation forbidden
  Eigen::internal::set_is_malloc_allowed(false);
  const Gaussian predicted = predict(model, in.layout, in.prior, 2.0);
  const Innovation innovation = innovate(predicted, in.layout, in.plot, in.ekf);
  Eigen::internal::set_is_malloc_allowed(true);
  // THEN nothing asserted and the results are usable
  EXPECT_TRUE(innovation.ok);
#endif
}

TEST(HotPathAllocation, NoMallocAnywhereInTheHotPath) {
#if !SKYTRACK_COUNTING_MALLOC
  GTEST_SKIP() << "the counting malloc needs glibc and no sanitizer";
#else
  const HotPathInputs in;
  volatile double sink = hot_path(in);  // warm-up outside the window
  // WHEN the hot path runs with every malloc in the process counted
  g_allocations = 0;
  g_counting = true;
  sink = sink + hot_path(in);
  g_counting = false;
  // THEN it allocated nothing
  EXPECT_EQ(g_allocations.load(), 0);
  EXPECT_TRUE(std::isfinite(sink));
  // AND the counter does count (a heap vector is seen)
  g_counting = true;
  const std::vector<double>* probe = new std::vector<double>(100);
  g_counting = false;
  EXPECT_GE(g_allocations.load(), 1);
  delete probe;
#endif
}

}  // namespace
}  // namespace skytrack
