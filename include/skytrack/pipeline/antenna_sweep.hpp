#pragma once
// The sweep of a rotating antenna, followed from the plots themselves: each plot's azimuth and
// own time (plots[].time) place the beam, and consecutive plots give the rotation rate. The
// sweep is the cumulative angle the beam has turned through [rad], increasing whatever the
// sense of rotation, so "a revolution later" is "2 pi further" and a batch's coverage is the
// sweep between two values. Pure core: no I/O, deterministic.
#include <cstddef>
#include <optional>
#include <vector>

#include "skytrack/config/profile.hpp"
#include "skytrack/core/plot.hpp"

namespace skytrack {

/// The body-frame azimuth a plot was seen at (polar plots as measured; Cartesian plots from
/// the platform's position and heading).
double body_azimuth(const Plot& plot, const PlatformState& platform);

class AntennaSweep {
 public:
  enum class Kind { kUndecided, kSnapshot, kRotating };

  explicit AntennaSweep(const config::AntennaSpec& spec);

  /// Reads one batch (plots in any order): learns the rotation from consecutive plots while
  /// it is unknown (and refines the rate afterwards). A batch whose plots carry no time of
  /// their own makes the sensor a snapshot sensor; so do pairs of plots that never agree on
  /// a rate.
  Kind read(const PlotScan& scan);
  Kind kind() const { return kind_; }

  /// Each plot's sweep (batch order), for a rotating antenna's batches in arrival order. The
  /// first plot placed starts a revolution after `base` (the sweep the sensor's looks had
  /// reached before it was known to rotate).
  void place(const PlotScan& scan, double base, std::vector<double>& sweeps);
  /// Consecutive-plot rate samples read so far (learning progresses while it grows).
  std::size_t samples() const { return samples_; }

  bool rotating() const { return kind_ == Kind::kRotating; }
  double rate() const { return rate_; }  // [rad/s], > 0 once rotating
  double period() const;                 // [s]
  int sense() const { return sense_; }   // +1 clockwise, -1 counterclockwise, 0 unknown

  /// The sweep of the latest plot, and extrapolated from it to `time` (not before it).
  double latest() const { return latest_sweep_; }
  double sweep_at(double time) const;
  /// The sweep value of body azimuth `azimuth` in (after, after + 2 pi].
  double sweep_of(double azimuth, double after) const;
  /// The body azimuth at a sweep value.
  double azimuth_of(double sweep) const;
  /// The clockwise body-frame sector swept from `from` to `to` (to - from < 2 pi).
  AzimuthSector sector(double from, double to) const;

 private:
  struct Sample {  // one consecutive pair of plots
    double time = 0.0, azimuth = 0.0;
  };
  void learn(const std::vector<Sample>& ordered);
  double unwrap(double azimuth, double time) const;

  void order(const PlotScan& scan);

  config::AntennaSpec spec_;
  Kind kind_ = Kind::kUndecided;
  double rate_ = 0.0;  // [rad/s]
  int sense_ = 0;
  std::vector<double> rates_;   // signed rate samples [rad/s] while learning
  std::size_t samples_ = 0;     // rate samples read in all
  std::optional<Sample> last_;  // the latest plot seen (time order)
  double latest_time_ = 0.0, latest_sweep_ = 0.0;
  bool anchored_ = false;
  std::vector<Sample> ordered_;  // workspace
  std::vector<std::size_t> order_;
};

}  // namespace skytrack
