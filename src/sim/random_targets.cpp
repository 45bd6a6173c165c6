#include "skytrack/sim/random_targets.hpp"

#include <cmath>
#include <random>
#include <string>

namespace skytrack::sim {

std::vector<TargetSpec> draw_random_targets(const RandomTargetsSpec& spec, int dimensions,
                                            double duration, std::uint64_t seed) {
  // A stream of its own (seed mixed with a constant), so adding a population to a scenario
  // does not shift the measurement noise the other draws see.
  std::mt19937_64 rng(seed ^ 0x9e3779b97f4a7c15ULL);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> normal;
  const auto uniform_in = [&](const Eigen::Vector2d& interval) {
    return interval[0] + (interval[1] - interval[0]) * unit(rng);
  };
  const int steps = spec.acceleration_noise > 0.0 && spec.step > 0.0
                        ? static_cast<int>(std::ceil(duration / spec.step))
                        : 0;
  const double acceleration_sigma =
      steps > 0 ? std::sqrt(spec.acceleration_noise / spec.step) : 0.0;
  std::vector<TargetSpec> targets;
  targets.reserve(static_cast<std::size_t>(spec.count));
  for (int i = 0; i < spec.count; ++i) {
    TargetSpec target;
    target.id = spec.first_id + i;
    TrajectorySpec& trajectory = target.trajectory;
    trajectory.position = {uniform_in(spec.x), uniform_in(spec.y),
                           dimensions == 3 ? uniform_in(spec.z) : 0.0};
    trajectory.velocity = {spec.velocity_sigma * normal(rng), spec.velocity_sigma * normal(rng),
                           dimensions == 3 ? spec.velocity_sigma * normal(rng) : 0.0};
    trajectory.segments.reserve(static_cast<std::size_t>(steps));
    for (int k = 0; k < steps; ++k) {
      SegmentSpec segment;
      segment.type = SegmentSpec::Type::kConstantAcceleration;
      segment.duration = spec.step;
      segment.acceleration = {acceleration_sigma * normal(rng), acceleration_sigma * normal(rng),
                              dimensions == 3 ? acceleration_sigma * normal(rng) : 0.0};
      trajectory.segments.push_back(segment);
    }
    targets.push_back(std::move(target));
  }
  return targets;
}

Expected<void> add_random_targets(Scenario& scenario, std::uint64_t seed) {
  if (!scenario.random_targets) return {};
  const auto drawn =
      draw_random_targets(*scenario.random_targets, scenario.dimensions, scenario.duration, seed);
  for (const TargetSpec& target : drawn) {
    for (const TargetSpec& given : scenario.targets) {
      if (given.id == target.id) {
        return make_error("random_targets: id " + std::to_string(target.id) +
                          " is also a listed target's; set random_targets.first_id");
      }
    }
  }
  scenario.targets.insert(scenario.targets.end(), drawn.begin(), drawn.end());
  return {};
}

}  // namespace skytrack::sim
