#pragma once
// Generates plot batches and ground truth from a Scenario, one batch at a time, so a long
// simulation never holds its output. Deterministic: same scenario and seed, same output.
//
// Snapshot antenna: every plot of scan k is measured at start + k T. Rotating antenna: the
// beam sweeps clockwise from the platform's nose, one revolution per scan period; each plot
// is timed by the azimuth it is seen at (plots[].time) and a revolution is reported in
// `sectors` batches, each stamped with the time its sector ends.
#include <cstdint>
#include <deque>
#include <optional>
#include <random>
#include <vector>

#include "skytrack/core/expected.hpp"
#include "skytrack/core/plot.hpp"
#include "skytrack/core/truth.hpp"
#include "skytrack/sim/scenario.hpp"
#include "skytrack/sim/trajectory.hpp"

namespace skytrack::sim {

/// One output batch: the plots and the truth at the batch's reference time.
struct SimulatedBatch {
  PlotScan plots;
  TruthFrame truth;
};

class Simulator {
 public:
  /// Checks the scenario (sigmas for every measured component, parents, periods).
  static Expected<Simulator> create(Scenario scenario, std::uint64_t seed);

  /// The next batch, or nullopt when the scenario's duration is over.
  std::optional<SimulatedBatch> next();

  /// The sigma written into scan lines: standard deviations (for bounded noise, those of the
  /// uniform distribution in the bounding ellipsoid).
  const MeasurementSigma& reported_sigma() const { return reported_sigma_; }

 private:
  struct Target {
    TargetSpec spec;
    Trajectory trajectory;
    std::vector<Eigen::Vector2d> member_offsets;  // groups
  };
  struct TimedPlot {
    Plot plot;
    double time = 0.0;
  };

  explicit Simulator(Scenario scenario, std::uint64_t seed);
  Expected<void> build_targets();
  PlatformState platform_at(double time) const;
  /// The reference time of the batch a plot measured at `time` belongs to.
  double batch_time_of(double time) const;
  bool alive(const Target& target, double time) const;
  Eigen::Matrix2d shape_at(const Target& target, const KinematicState& state) const;
  template <class PositionAt>
  double illumination_time(PositionAt position_at, double begin) const;

  void generate(double begin, double end, std::vector<TimedPlot>& out);
  void add_target_plots(const Target& target, double begin, std::vector<TimedPlot>& out);
  void add_clutter(const ClutterSpec& clutter, double begin, double end,
                   std::vector<TimedPlot>& out);
  std::optional<Plot> measure(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity,
                              double time);
  Eigen::VectorXd bounded_noise(int dims);
  SimulatedBatch make_batch(std::uint64_t number, double time, std::vector<TimedPlot> plots);
  TruthFrame truth_at(double time) const;

  Scenario scenario_;
  std::mt19937_64 rng_;
  std::vector<Target> targets_;
  std::optional<Trajectory> platform_;
  MeasurementSigma reported_sigma_;
  std::uint64_t next_scan_ = 0;  // batch number
  std::uint64_t period_ = 0;     // snapshot or revolution index
  std::deque<SimulatedBatch> pending_;
};

}  // namespace skytrack::sim
