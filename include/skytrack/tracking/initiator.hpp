#pragma once
// M-of-N track initiation by plot-to-plot association with a speed gate. Plots nobody else
// used become seeds; a later plot whose distance to a seed implies a speed within
// [min_speed, max_speed] forms a candidate chain, which grows by the nearest plot to its
// constant-velocity prediction. A chain with M plots within N scans becomes a tentative
// track; chains that cannot reach M in time are dropped. Chains are cheap (no filter), so
// dense clutter costs seeds, not IMM tracks.
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "skytrack/association/plot_index.hpp"
#include "skytrack/config/profile.hpp"
#include "skytrack/measurement/plot_measurement.hpp"

namespace skytrack {

/// Largest position standard deviation of a plot [m] (cross-range for polar plots).
double position_sigma(const PlotMeasurement& plot) noexcept;

/// A chain of plots, oldest first, ready to start a track.
struct Initiation {
  std::vector<PlotMeasurement> plots;
  int scans = 0;  // scans spanned, first to last plot inclusive
};

class Initiator {
 public:
  explicit Initiator(const config::InitiationSpec& spec, int dims);

  /// One scan of plots that no track used. Returns the chains completed this scan.
  const std::vector<Initiation>& step(std::uint64_t scan_index,
                                      const std::vector<PlotMeasurement>& plots);

  std::size_t seeds() const { return seeds_.size(); }
  std::size_t candidates() const { return chains_.size(); }

 private:
  struct Seed {
    PlotMeasurement plot;
    Eigen::Vector3d position;
    std::uint64_t scan = 0;
  };
  struct Chain {
    std::vector<PlotMeasurement> plots;
    Eigen::Vector3d position;  // of the last plot
    Eigen::Vector3d velocity;
    double time = 0.0;  // of the last plot
    std::uint64_t first_scan = 0, last_scan = 0;
  };

  void extend_chains(std::uint64_t scan, const std::vector<PlotMeasurement>& plots);
  void pair_with_seeds(std::uint64_t scan, const std::vector<PlotMeasurement>& plots);
  void retire(std::uint64_t scan);

  config::InitiationSpec spec_;
  int dims_;
  std::vector<Seed> seeds_;
  std::vector<Chain> chains_;
  std::vector<Initiation> completed_;
  // Workspaces reused every scan.
  std::vector<Eigen::Vector3d> positions_;
  std::vector<std::uint8_t> used_;
  std::vector<int> neighbours_;
  PlotIndex index_;
};

}  // namespace skytrack
