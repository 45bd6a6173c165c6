#pragma once
// The estimator of `mode: group` (estimator.hpp): the labeled box-particle PHD filter of paper
// 000 on the preprocessing stage's partitions. Per look: the stage's kernel-density clutter
// rejection and mean-shift cells (the profile's clutter_rejection, nothing protected), the
// group's edge plots the rejection took readmitted to their cell, each cell's measurement box,
// then the filter. Each label is one group track (kind group) with its centroid, velocity,
// extent and member count: confirmed while detected, coasting while its label survives
// missed scans, deleted when the label dies. One filter per sensor; 2-D.
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "skytrack/clutter/mean_shift_partition.hpp"
#include "skytrack/config/profile.hpp"
#include "skytrack/core/expected.hpp"
#include "skytrack/group/group_tracker.hpp"
#include "skytrack/tracking/estimator.hpp"

namespace skytrack::group {

class GroupEstimator final : public Estimator {
 public:
  /// Checks the profile's group section.
  static Expected<GroupEstimator> create(const config::TrackingProfile& profile);

  void process(const PlotScan& look, Preprocessing& pre, TrackFrame& frame,
               ScanReport& report) override;
  void report_only(const PlotScan& batch, TrackFrame& frame, ScanReport& report) override;
  /// None: a group may be born anywhere, so a rotating antenna's looks close on the sweep.
  void search_regions(const PlotScan&, double, std::vector<SearchRegion>&) const override {}

 private:
  explicit GroupEstimator(const GroupSpec& spec) : spec_(spec) {}

  struct Watch {  // one sensor's filter, and its labels' track numbers
    GroupTracker tracker;
    std::map<std::uint32_t, std::int64_t> numbers;  // label -> track number
  };
  Watch& watch_of(std::uint32_t sensor);
  /// The frame's tracks from the filter's estimates; labels gone since are reported deleted.
  void report(Watch& watch, const std::vector<GroupEstimate>& estimates, TrackFrame& frame,
              ScanReport& report, bool decided);

  GroupSpec spec_;
  std::map<std::uint32_t, Watch> watches_;
  std::int64_t next_number_ = 1;
  // Workspaces (reused).
  std::vector<clutter::PlotPartition> partitions_;
  std::vector<GroupCell> cells_;
  std::vector<std::uint32_t> seen_;
};

}  // namespace skytrack::group
