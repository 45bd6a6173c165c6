#pragma once
// The estimator of `mode: extended` (estimator.hpp): the multi-object extended tracker
// (extended_tracker.hpp) with the profile's extent estimator (SMF-EOT, random matrix or
// MEM-EKF*), one per sensor, 2-D. Its tracks are `kind: extended` with the centre's position
// and velocity and the extent (the 2x2 shape matrix of the object's ellipse). A tentative
// track carries a provisional number; a track is numbered when it is confirmed, so clutter
// that never confirms takes no number; coasting while it misses; deleted when its existence
// probability falls below the profile's threshold (after its misses with existence off).
#include <cstdint>
#include <map>
#include <vector>

#include "skytrack/config/profile.hpp"
#include "skytrack/core/expected.hpp"
#include "skytrack/extended/extended_tracker.hpp"
#include "skytrack/tracking/estimator.hpp"

namespace skytrack::extended {

class ExtendedMode final : public Estimator {
 public:
  static Expected<ExtendedMode> create(const config::TrackingProfile& profile);

  void process(const PlotScan& look, Preprocessing& pre, TrackFrame& frame,
               ScanReport& report) override;
  void report_only(const PlotScan& batch, TrackFrame& frame, ScanReport& report) override;
  /// None: an object may appear anywhere, so a rotating antenna's looks close on the sweep.
  void search_regions(const PlotScan&, double, std::vector<SearchRegion>&) const override {}

 private:
  explicit ExtendedMode(const ExtendedSpec& spec) : spec_(spec) {}

  struct Watch {  // one sensor's tracker, and its tracks' numbers once confirmed
    ExtendedTracker tracker;
    std::map<std::uint64_t, std::int64_t> numbers;  // tracker id -> track number
  };
  Watch& watch_of(std::uint32_t sensor);
  void report(Watch& watch, TrackFrame& frame, ScanReport& report) const;

  ExtendedSpec spec_;
  std::map<std::uint32_t, Watch> watches_;
  std::int64_t next_number_ = 1;
};

}  // namespace skytrack::extended
