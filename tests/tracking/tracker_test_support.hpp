#pragma once
// Runs a simulated scenario through the Pipeline and scores it, for tracker tests.
#include <vector>

#include <gtest/gtest.h>

#include "skytrack/metrics/scenario_evaluation.hpp"
#include "skytrack/pipeline/pipeline.hpp"
#include "skytrack/sim/simulator.hpp"

namespace skytrack::testing {

struct TrackedRun {
  std::vector<TrackFrame> frames;
  metrics::EvaluationSummary summary;
};

/// A Cartesian plot at (x, y) [m].
inline Plot cartesian(std::int64_t id, double x, double y) {
  Plot p;
  p.id = id;
  p.form = PlotForm::kCartesian;
  p.x = x;
  p.y = y;
  return p;
}

inline config::TrackingProfile test_profile() {
  config::TrackingProfile profile;
  profile.identity = {"test", "1", ""};
  return profile;
}

/// A 2-D radar to 60 km (range sigma 20 m, azimuth 1 mrad, 2 s scans, P_D 0.9), with
/// `clutter` plots per scan over its coverage, for 200 s.
inline sim::Scenario radar_scenario(double clutter, sim::SensorSpec::Antenna antenna) {
  sim::Scenario s;
  s.name = "radar";
  s.dimensions = 2;
  s.duration = 200.0;
  s.sensor.scan_period = 2.0;
  s.sensor.antenna = antenna;
  s.sensor.detection_probability = 0.9;
  s.sensor.sigma.range = 20.0;
  s.sensor.sigma.azimuth = 0.001;
  s.sensor.max_range = 60000.0;
  s.clutter.mean = clutter;
  s.clutter.range = {1000.0, 60000.0};
  return s;
}

inline TrackedRun track_scenario(const sim::Scenario& scenario, std::uint64_t seed,
                                 const config::TrackingProfile& profile, double cutoff) {
  TrackedRun run;
  auto simulator = sim::Simulator::create(scenario, seed);
  EXPECT_TRUE(simulator) << (simulator ? "" : simulator.error().message);
  auto pipeline = Pipeline::create(profile);
  EXPECT_TRUE(pipeline) << (pipeline ? "" : pipeline.error().message);
  metrics::ScenarioEvaluation evaluation({cutoff, 2.0});
  while (auto batch = simulator->next()) {
    const ScanResult& result = pipeline->process(batch->plots);
    EXPECT_TRUE(result.accepted) << result.rejection;
    run.frames.push_back(result.frame);
    evaluation.add(batch->truth, &result.frame);
  }
  run.summary = evaluation.summary();
  return run;
}

inline sim::TargetSpec target(std::int64_t id, Eigen::Vector3d position, Eigen::Vector3d velocity) {
  sim::TargetSpec t;
  t.id = id;
  t.trajectory.position = position;
  t.trajectory.velocity = velocity;
  return t;
}

}  // namespace skytrack::testing
