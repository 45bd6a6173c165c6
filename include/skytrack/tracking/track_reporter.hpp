#pragma once
// The point tracker's reporter: every reported track (the fathers; one waiting for its
// branches as coasting) predicted to the look's time, into the frame, and the report's counts.
#include <vector>

#include "skytrack/core/look.hpp"
#include "skytrack/core/scan_report.hpp"
#include "skytrack/core/track_report.hpp"
#include "skytrack/filter/imm_filter.hpp"
#include "skytrack/tracking/branch_hooks.hpp"
#include "skytrack/tracking/point_track.hpp"

namespace skytrack {

class TrackReporter {
 public:
  /// An empty frame at the look's sensor, scan and time; its track reports keep their
  /// storage for report to overwrite.
  static void start_frame(const PlotScan& scan, TrackFrame& frame);
  /// Writes the reported tracks at `time` into the frame and counts them (the branches too);
  /// `hooks` names the branch that stands in for a father that took no plot.
  static void report(const std::vector<PointTrack>& tracks, const ImmFilter& filter,
                     const BranchHooks& hooks, double time, ScanReport& report, TrackFrame& frame);
};

}  // namespace skytrack
