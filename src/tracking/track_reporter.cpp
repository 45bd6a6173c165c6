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
                           const BranchHooks& hooks, double time, ScanReport& report,
                           TrackFrame& frame) {
  const int dims = filter.layout().dims;
  const int n = 2 * dims;
  std::size_t reported = 0;
  ImmEstimate scratch;
  for (const PointTrack& track : tracks) {
    if (track.branch != BranchType::kFather) {  // sons and grandsons are internal
      if (track.life.status != TrackStatus::kDeleted) ++report.point.branches;
      continue;
    }
    if (track.replaced) continue;  // its number lives on in the branch that replaced it
    // The estimate at the frame's time: the track's own, or its prediction kept in scratch.
    const auto at = [&](const ImmEstimate& e) -> const ImmEstimate& {
      if (e.time >= time) return e;
      filter.predict(e, time, scratch);
      return scratch;
    };
    const ImmEstimate* at_time = &at(track.estimate);
    Gaussian g = filter.combine(*at_time);
    TrackStatus status = track.life.status;
    // A father that took no plot while a branch of its did (its sons decide) is reported,
    // coasting, at that branch's estimate, with a covariance that still covers its own
    // prediction (one sigma along the gap). A father whose life gave it up (suspended) is
    // reported only in a look it took a plot or a branch stands in: otherwise it waits,
    // unreported, for a branch or a plot chain of its target.
    const PointTrack* branch = hooks.stand_in(track);
    if (branch == nullptr && track.doomed() && !track.undecided() &&
        status != TrackStatus::kDeleted && track.life.consecutive_misses > 0) {
      continue;
    }
    if (branch != nullptr) {
      const Eigen::VectorXd father_mean = g.mean;
      at_time = &at(branch->estimate);
      g = filter.combine(*at_time);
      const Eigen::VectorXd gap = father_mean - g.mean;
      g.covariance += gap * gap.transpose();
      status = TrackStatus::kCoasting;
    }
    // Written over the frame's earlier report in this place: its vectors keep their storage.
    TrackReport& out =
        reported < frame.tracks.size() ? frame.tracks[reported] : frame.tracks.emplace_back();
    ++reported;
    out.kind = ObjectKind::kPoint;
    out.extent.reset();
    out.members.reset();
    out.modes.clear();
    out.id = track.id;
    out.status = status;
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
      out.modes.emplace_back(names[m], at_time->probabilities[static_cast<Eigen::Index>(m)]);
    }
    out.quality = track.quality;
    switch (status) {
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
