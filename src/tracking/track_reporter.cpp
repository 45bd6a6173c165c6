#include "skytrack/tracking/track_reporter.hpp"

#include "point_tracker_support.hpp"

namespace skytrack {

using namespace tracking_detail;

void TrackReporter::start_frame(const PlotScan& scan, TrackFrame& frame) {
  frame.sensor = scan.sensor;
  frame.scan = scan.scan;
  frame.time = scan.time;
  // frame.tracks keeps its elements (and their storage) for report to overwrite.
  frame.associations.clear();
  frame.events.clear();
}

void TrackReporter::report(const std::vector<PointTrack>& tracks, const ImmFilter& filter,
                           double time, ScanReport& report, TrackFrame& frame) {
  const int dims = filter.layout().dims;
  const int n = 2 * dims;
  std::size_t reported = 0;
  for (const PointTrack& track : tracks) {
    if (track.branch != BranchType::kFather) {  // sons and grandsons are internal
      if (track.life.status != TrackStatus::kDeleted) ++report.point.branches;
      continue;
    }
    if (track.replaced) continue;  // its number lives on in the branch that replaced it
    // A doomed father is not reported while it waits for a branch to replace it (an
    // undecided one is).
    if (track.doomed() && !track.undecided() && track.life.status != TrackStatus::kDeleted)
      continue;
    const ImmEstimate at_time =
        track.estimate.time < time ? filter.predict(track.estimate, time) : track.estimate;
    const Gaussian g = filter.combine(at_time);
    // Written over the frame's earlier report in this place: its vectors keep their storage.
    TrackReport& out =
        reported < frame.tracks.size() ? frame.tracks[reported] : frame.tracks.emplace_back();
    ++reported;
    out.kind = ObjectKind::kPoint;
    out.extent.reset();
    out.members.reset();
    out.modes.clear();
    out.id = track.id;
    out.status = track.life.status;
    out.dims = dims;
    out.position = position_of(g.mean, dims);
    out.velocity = velocity_of(g.mean, dims);
    out.covariance.resize(static_cast<std::size_t>(n * n));
    for (int r = 0; r < n; ++r) {
      for (int c = 0; c < n; ++c)
        out.covariance[static_cast<std::size_t>(r * n + c)] = g.covariance(r, c);
    }
    const auto& names = filter.names();
    for (std::size_t m = 0; m < names.size(); ++m) {
      out.modes.emplace_back(names[m], at_time.probabilities[static_cast<Eigen::Index>(m)]);
    }
    out.quality = track.quality;
    switch (track.life.status) {
      case TrackStatus::kTentative:
        ++report.tentative;
        break;
      case TrackStatus::kConfirmed:
        ++report.confirmed;
        break;
      case TrackStatus::kCoasting:
        ++report.coasting;
        break;
      case TrackStatus::kDeleted:
        ++report.deleted;
        break;
    }
  }
  frame.tracks.resize(reported);
}

}  // namespace skytrack
