#pragma once
// The stage between a look's plots and every estimator mode: each plot becomes a measurement
// in the tracking frame (plot_measurement.hpp), with its position, a grid index over them and
// the plot clouds; on the estimator's call, kernel-density clutter rejection with mean-shift
// partitions and measurement boxes (paper 000 §3.1, clutter_rejector.hpp), and the clutter
// density each plot is weighed against (the batch's or its antenna revolution's, raised by the
// clutter map; clutter_density.hpp).
//
// Rejection and density wait for the estimator because they may depend on its tracks: the
// point tracker protects the plots in its confirmed tracks' gates from rejection, and the
// clutter map counts only the plots no firm track gates. A mode without tracks to protect
// calls them right away.
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "skytrack/association/grid_index.hpp"
#include "skytrack/clutter/clutter_density.hpp"
#include "skytrack/clutter/clutter_rejector.hpp"
#include "skytrack/config/profile.hpp"
#include "skytrack/core/look.hpp"
#include "skytrack/core/plot.hpp"
#include "skytrack/core/scan_report.hpp"
#include "skytrack/measurement/plot_measurement.hpp"

namespace skytrack {

// A plot cloud: more than this many other plots within this many of a plot's position sigmas
// in one look (a formation of a few aircraft is not one).
inline constexpr int kCloudPlots = 16;
inline constexpr double kCloudSigmas = 5.0;

/// Sparse clutter when nothing better is known: one false plot per (10 km)^k.
double sparse_clutter_density(int position_dims);

class Preprocessing {
 public:
  /// `dims`: the tracking frame's dimension (2 or 3), the estimator's.
  Preprocessing(const config::TrackingProfile& profile, int dims);

  /// Prepares one look. Without `sources` the look is the batch `look` as it arrived (a
  /// snapshot: a revolution of sweep after the sensor's last look). Plots that make no
  /// measurement are counted in report.plots_invalid.
  void prepare(const PlotScan& look, const LookSources* sources, ScanReport& report);

  // The look's measurements, their approximate positions in the tracking frame and a grid
  // index over them, its cells the look's median plot-cloud radius, which is about a gate's
  // (2-D when a 3-D look holds a polar plot without height: such a plot lies at elevation 0,
  // kilometres under its target, so the look is searched on the plane).
  const std::vector<PlotMeasurement>& plots() const { return plots_; }
  const std::vector<Eigen::Vector3d>& positions() const { return positions_; }
  const GridIndex& index() const { return index_; }
  std::uint32_t sensor() const { return sensor_; }
  /// The antenna's sweep at the look's end [rad].
  double sweep() const { return sweep_; }
  /// Plot j lies in a plot cloud: chaff, a jammer's false plots, a swarm too dense to resolve.
  /// No chain can tell a target there from the rest, and it is no measure of the sky's clutter.
  bool in_cloud(std::size_t j) const { return crowd_[j] != 0; }
  /// Plot j was removed by clutter rejection.
  bool rejected(std::size_t j) const { return rejected_[j] != 0; }

  /// Kernel-density clutter rejection of the look's plots, those flagged in `protect` kept
  /// whatever their density; its result (with the mean-shift cells and their measurement
  /// boxes) stays valid until the next look. Nothing is rejected when the profile disables it.
  const clutter::ClutterRejectionResult& reject_clutter(std::span<const std::uint8_t> protect);
  bool rejects_clutter() const { return rejector_.spec().enabled; }

  /// Estimates each plot's clutter density (unless the profile fixes it). `false_plots`: per
  /// plot, 1 where the clutter map may count it as a false plot (no firm track gates it).
  void estimate_density(std::span<const std::uint8_t> false_plots);
  /// The plots of one gate (indices in plots()) share its clutter density: a gate is smaller
  /// than the clutter map resolves, so a plot with no counted plot round it (no estimate of
  /// its own, only the profile's sparse value) takes the largest estimate of the others.
  /// Estimates shared from one gate are not passed on to another.
  void share_density(std::span<const int> gate);
  /// The clutter density of plot `index` of this look in its measurement space (-1: a plot of
  /// an earlier look): the estimate, or the profile's value times the polar volume element.
  double density(const PlotMeasurement& plot, int index) const;

  /// Ends the look: a rotating antenna's density window keeps its plots.
  void finish();

 private:
  config::TrackingProfile profile_;
  int dims_;
  clutter::ClutterRejector rejector_;
  clutter::ClutterDensity density_;
  std::uint64_t looks_ = 0;
  std::uint32_t sensor_ = 0;
  bool windowed_ = false;  // its density is estimated over the sensor's last revolution
  double sweep_ = 0.0;
  std::vector<PlotMeasurement> plots_;
  std::vector<Eigen::Vector3d> positions_;
  GridIndex index_;
  std::vector<double> cloud_radii_, cloud_median_;  // per plot; workspace
  std::vector<std::uint8_t> crowd_;
  std::vector<std::uint8_t> rejected_;
  std::vector<std::uint8_t> boxed_;    // per plot: counted by the batch-wide density
  std::vector<std::uint8_t> counted_;  // per plot: counted by the clutter map
  std::vector<double> estimate_;       // per plot, measurement space; 0: none
  std::vector<std::uint8_t> own_;      // per plot: estimate_ is its own (not shared)
};

}  // namespace skytrack
