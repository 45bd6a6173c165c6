#pragma once
// The seam every estimator mode sits behind (the profile's `mode`): the Pipeline prepares
// each look's plots once (preprocessing.hpp) and hands them to the one estimator the profile
// selects. docs/estimators.md says how a new mode is added.
#include <vector>

#include "skytrack/core/look.hpp"
#include "skytrack/core/plot.hpp"
#include "skytrack/core/scan_report.hpp"
#include "skytrack/core/track_report.hpp"
#include "skytrack/preprocess/preprocessing.hpp"

namespace skytrack {

/// An empty frame at a look's (or batch's) sensor, scan and time, for an estimator to fill.
inline void begin_frame(const PlotScan& look, TrackFrame& frame) {
  frame.sensor = look.sensor;
  frame.scan = look.scan;
  frame.time = look.time;
  frame.tracks.clear();
  frame.associations.clear();
  frame.events.clear();
}

class Estimator {
 public:
  virtual ~Estimator() = default;

  /// Processes one look, whose plots `pre` has prepared: fills `frame` (the tracks at
  /// look.time, the plots' associations, the events) and the report's common part and the
  /// mode's own. Never throws on bad input: bad values are counted and skipped.
  virtual void process(const PlotScan& look, Preprocessing& pre, TrackFrame& frame,
                       ScanReport& report) = 0;

  /// Reports the tracks at batch.time without a look (a batch whose plots all wait for a
  /// later look); nothing is updated or aged.
  virtual void report_only(const PlotScan& batch, TrackFrame& frame, ScanReport& report) = 0;

  /// Where the estimator may take a plot at `time` (for plots with the sigmas of batch
  /// `header`): a rotating antenna's look ends once its sweep has passed all of them.
  virtual void search_regions(const PlotScan& header, double time,
                              std::vector<SearchRegion>& out) const = 0;
};

}  // namespace skytrack
