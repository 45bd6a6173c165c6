#pragma once
// M-of-N track initiation by plot-to-plot association with a speed gate. Plots the tracks
// leave unexplained (in no gate, or no track's most likely plot: the tracker decides) become
// seeds; a later plot whose distance to a seed implies a speed within
// [min_speed, max_speed] forms a candidate chain, which grows by the nearest plot to its
// constant-velocity prediction, the nearest chain-plot pairs first. A chain with M plots
// within N scans becomes a tentative track; chains that cannot reach M in time are dropped.
// Chains are cheap (no filter), so dense clutter costs seeds, not IMM tracks; a completed
// chain the tracker finds too weak for a track waits for its next plot as a chain (hold).
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "skytrack/association/grid_index.hpp"
#include "skytrack/config/profile.hpp"
#include "skytrack/core/look.hpp"
#include "skytrack/measurement/plot_measurement.hpp"

namespace skytrack {

/// Largest position standard deviation of a plot [m] (cross-range for polar plots).
double position_sigma(const PlotMeasurement& plot) noexcept;

/// How far a chain's target may stray from the constant-velocity line through its plots: the
/// acceleration its motion models allow, 3 sigma of their white (or Singer) acceleration
/// plus the centripetal acceleration of their fastest turn at the chain's own speed, and
/// never more than about 6 g (the default, also for a model whose acceleration is a state).
struct ChainManoeuvre {
  static constexpr double kMaxAcceleration = 60.0;  // [m/s^2]
  double accel = kMaxAcceleration;                  // [m/s^2]
  double turn_rate = 0.0;                           // [rad/s]

  static ChainManoeuvre from_models(const std::vector<config::MotionModelSpec>& models, int dims);
  /// [m/s^2] at `speed` [m/s].
  double at(double speed) const noexcept;
};

/// A chain of plots, oldest first, ready to start a track.
struct Initiation {
  std::vector<PlotMeasurement> plots;
  int scans = 0;           // scans spanned, first to last plot inclusive
  int last = -1;           // plots.back()'s index in the plots of the step that completed it
  bool held = false;       // completed once before and held back for this plot (Initiator::hold)
  double existence = 0.0;  // held: the existence its plots but the last gave it (hold)
};

class Initiator {
 public:
  explicit Initiator(const config::InitiationSpec& spec, int dims, ChainManoeuvre manoeuvre = {});

  /// Tells whether a batch looked at a position (a sector batch covers part of the sky).
  using Coverage = std::function<bool(const Eigen::Vector3d&)>;

  /// One batch of plots of `sensor` that no track explains, taken at `time`, its sweep ending
  /// at `sweep` (the antenna's, PlotMeasurement::sweep). Seeds and chains age by the batches
  /// that cover them ("looks"), at most once per half revolution of their sensor's sweep, so
  /// a revolution reported in sectors counts once. Returns the chains completed by this batch.
  /// `positions`: the plots' approximate_position, when the caller has them (else computed).
  const std::vector<Initiation>& step(std::uint64_t batch, double time, std::uint32_t sensor,
                                      double sweep, const std::vector<PlotMeasurement>& plots,
                                      const Coverage& covered,
                                      std::span<const Eigen::Vector3d> positions = {});
  /// The same for a snapshot sensor, whose batches are a look at everything (the plots'
  /// sweeps are set to one revolution per batch).
  const std::vector<Initiation>& step(std::uint64_t batch, double time,
                                      const std::vector<PlotMeasurement>& plots,
                                      const Coverage& covered,
                                      std::span<const Eigen::Vector3d> positions = {});

  /// Keeps a chain `step` just completed (its last M plots) as a chain that must take a plot
  /// in its next look: it completes again with that plot (Initiation::held, carrying
  /// `existence`, the tracker's weighing of its plots so far), or is dropped by a look
  /// without one. For a chain too weak to outlive a missed look as a track: as a chain it
  /// costs no filter. Call before the next step.
  void hold(const Initiation& initiation, double existence);

  /// Appends each candidate chain's search region at `time`: where its next plot may lie.
  void search_regions(double time, std::vector<SearchRegion>& out) const;

  std::size_t seeds() const { return seeds_.size(); }
  std::size_t candidates() const { return chains_.size(); }

 private:
  struct Seed {
    PlotMeasurement plot;
    Eigen::Vector3d position;
    std::uint64_t batch = 0;
    int looks = 0;        // batches that covered it since it was made
    double looked = 0.0;  // the sweep when it was last seen or looked at
  };
  struct Chain {
    std::vector<PlotMeasurement> plots;
    Eigen::Vector3d position;  // of the last plot
    Eigen::Vector3d velocity;
    double time = 0.0;  // of the last plot
    std::uint64_t last_batch = 0;
    int looks = 0;        // looks spanned, from the first plot's on, inclusive
    double looked = 0.0;  // the sweep when it last took a plot or was looked at
    int last = -1;        // its last plot's index in the batch that gave it
    int held_plots = 0;   // plots and looks when it was held (hold); 0 plots: not held
    int held_looks = 0;
    double held_existence = 0.0;
  };
  struct Extension {  // a plot in a chain's gate, at `distance` from its prediction
    double distance = 0.0;
    int chain = 0;
    int plot = 0;
  };

  void extend_chains(std::uint64_t batch, const std::vector<PlotMeasurement>& plots);
  void pair_with_seeds(std::uint64_t batch, const std::vector<PlotMeasurement>& plots);
  void retire();

  config::InitiationSpec spec_;
  int dims_;
  ChainManoeuvre manoeuvre_;
  std::vector<Seed> seeds_;
  std::vector<Chain> chains_;
  std::vector<Initiation> completed_;
  std::uint64_t batch_ = 0;  // the last step's batch and sweep
  double sweep_ = 0.0;
  std::vector<PlotMeasurement> snapshot_plots_;
  struct SeedGroup {  // the seeds of one batch: seeds_[begin, end)
    std::size_t begin = 0, end = 0;
    double oldest = 0.0;     // earliest plot time among them
    double max_sigma = 0.0;  // largest position_sigma among them
  };

  // Workspaces reused every scan.
  std::vector<SeedGroup> seed_groups_;
  std::vector<GridIndex> seed_indices_;  // one per seed group
  std::vector<Eigen::Vector3d> seed_positions_;
  std::vector<Eigen::Vector3d> positions_;
  std::vector<std::uint8_t> used_;
  std::vector<Extension> extensions_;
  std::vector<int> neighbours_;
  std::vector<double> radii_, cell_radii_;  // each chain's search radius (-1: none this batch)
  GridIndex index_;                         // this batch's plots
};

}  // namespace skytrack
