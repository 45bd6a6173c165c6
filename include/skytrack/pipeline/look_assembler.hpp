#pragma once
// Regroups a rotating antenna's plots into looks, whatever batches the feed delivers them in
// (a revolution, a sector, a few plots). A look ends at a cut: a sweep the beam is known to
// have passed and that no search region straddles, so each track's and candidate chain's
// plots of one revolution reach the tracker together and a track is looked at once per
// revolution. Plots beyond the latest cut wait for a later batch; once a revolution's worth
// waits, the cut is forced. Pure core, deterministic.
#include <cstdint>
#include <span>
#include <vector>

#include "skytrack/core/look.hpp"
#include "skytrack/core/plot.hpp"
#include "skytrack/pipeline/antenna_sweep.hpp"

namespace skytrack {

/// A search region as the beam sees it: the body-frame azimuths it spans.
struct AzimuthSpan {
  double centre = 0.0;  // [rad]
  double half = 0.0;    // [rad] pi: every azimuth (the region holds the radar)
};

/// One look, ready for the tracker: `scan` has the header of the latest batch (its number,
/// time, platform and sigmas), the look's plots and its coverage.
struct Look {
  PlotScan scan;
  std::vector<PlotScan> batches;  // headers of the earlier batches plots were held over from
  std::vector<int> batch_of;      // per plot: index into batches, -1 for the latest batch's
  std::vector<double> sweep;      // per plot [rad]
  double sweep_to = 0.0;          // the cut that ends it [rad]
  bool whole = false;             // a batch that swept a revolution by itself
  LookSources sources() const { return {batches, batch_of, sweep, sweep_to, whole}; }
};

class LookAssembler {
 public:
  /// Holds a batch's plots with their sweeps. `reached`: the sweep the beam is known to have
  /// passed by the end of this batch (the latest plot's, or further by the batch's time or
  /// coverage).
  void add(const PlotScan& batch, std::span<const double> sweeps, double reached);

  /// The held plots up to the latest cut, at most one revolution after the previous cut and
  /// at or before `reached`, that no span straddles (in any revolution; spans of half a
  /// revolution or more are left out: no cut keeps them whole). When the spans leave none and
  /// a revolution has been swept since the previous cut, up to one revolution on from it;
  /// after a gap of three revolutions, all. False when no cut is possible yet: call again
  /// until false, a batch may complete several looks.
  bool take(std::span<const AzimuthSpan> spans, const AntennaSweep& antenna, Look& look);

  /// Every held plot as one look at all directions, up to `reached`: for a batch that swept
  /// three quarters of a revolution or more by itself (a feed that delivers revolutions).
  void take_all(Look& look);

  /// The previous cut: spans are placed after it.
  double from() const { return from_; }
  double reached() const { return reached_; }
  bool started() const { return started_; }
  std::size_t held() const { return held_.size(); }

 private:
  struct Held {
    Plot plot;
    double sweep = 0.0;
    std::size_t batch = 0;  // index into headers_
  };
  double cut(std::span<const AzimuthSpan> spans, const AntennaSweep& antenna);
  /// Moves the held plots up to sweep c into `look` (its header the latest batch's).
  void release(double c, Look& look);

  std::vector<Held> held_;
  std::vector<PlotScan> headers_;  // batches with held plots, oldest first; plots empty
  bool started_ = false;
  double from_ = 0.0, reached_ = 0.0;
  struct Interval {
    double low = 0.0, high = 0.0;
  };
  std::vector<Interval> merged_;  // workspace
  std::vector<Held> kept_;
};

}  // namespace skytrack
