#include <cmath>

#include <gtest/gtest.h>

#include "skytrack/sim/random_targets.hpp"

namespace skytrack::sim {
namespace {

RandomTargetsSpec benchmark_population(int count) {
  RandomTargetsSpec spec;
  spec.count = count;
  spec.x = {-400.0, 400.0};
  spec.y = {-400.0, 400.0};
  spec.velocity_sigma = 5.0;
  spec.acceleration_noise = 0.5;
  spec.step = 1.0;
  return spec;
}

TEST(RandomTargets, SameSeedSamePopulationAnotherSeedAnother) {
  const auto spec = benchmark_population(20);
  const auto a = draw_random_targets(spec, 2, 49.0, 7);
  const auto b = draw_random_targets(spec, 2, 49.0, 7);
  const auto c = draw_random_targets(spec, 2, 49.0, 8);
  ASSERT_EQ(a.size(), 20u);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].id, static_cast<std::int64_t>(i) + 1);
    EXPECT_EQ(a[i].trajectory.position, b[i].trajectory.position);
    EXPECT_EQ(a[i].trajectory.segments.size(), 49u);  // one acceleration per 1 s step
  }
  EXPECT_NE(a[0].trajectory.position, c[0].trajectory.position);
}

TEST(RandomTargets, StatesFollowTheStatedDistributions) {
  // 4000 targets: the sample moments within about 4 standard errors of the stated ones.
  const auto targets = draw_random_targets(benchmark_population(4000), 2, 10.0, 1);
  double vx = 0.0, vx2 = 0.0, ax2 = 0.0;
  for (const auto& t : targets) {
    const auto& p = t.trajectory.position;
    EXPECT_TRUE(p.x() >= -400.0 && p.x() <= 400.0 && p.y() >= -400.0 && p.y() <= 400.0);
    EXPECT_EQ(p.z(), 0.0);
    vx += t.trajectory.velocity.x();
    vx2 += t.trajectory.velocity.x() * t.trajectory.velocity.x();
    ax2 += t.trajectory.segments[0].acceleration.squaredNorm() / 2.0;
  }
  const double n = static_cast<double>(targets.size());
  EXPECT_NEAR(vx / n, 0.0, 4.0 * 5.0 / std::sqrt(n));
  EXPECT_NEAR(std::sqrt(vx2 / n), 5.0, 0.25);
  // q / step per axis: the velocity diffuses by q per second, as white-noise acceleration.
  EXPECT_NEAR(ax2 / n, 0.5, 0.05);
}

TEST(RandomTargets, AnIdClashWithAListedTargetIsRefused) {
  Scenario scenario;
  scenario.duration = 10.0;
  scenario.targets.push_back(TargetSpec{});
  scenario.targets.back().id = 3;
  scenario.random_targets = benchmark_population(5);
  const auto added = add_random_targets(scenario, 1);
  ASSERT_FALSE(added);
  EXPECT_NE(added.error().message.find("first_id"), std::string::npos);
  scenario.random_targets->first_id = 100;
  ASSERT_TRUE(add_random_targets(scenario, 1));
  EXPECT_EQ(scenario.targets.size(), 6u);
}

}  // namespace
}  // namespace skytrack::sim
