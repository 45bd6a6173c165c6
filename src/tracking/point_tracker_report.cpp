// The point tracker's report: every reported track at the batch's time, into the frame.
#include "skytrack/tracking/point_tracker.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <numbers>
#include <utility>

#include <Eigen/Eigenvalues>

#include "point_tracker_support.hpp"
#include "skytrack/core/chi_square.hpp"
#include "skytrack/geometry/frames.hpp"

namespace skytrack {

using namespace tracking_detail;

void PointTracker::report_tracks(double time, ScanReport& report, TrackFrame& frame) {
  const int dims = layout_.dims;
  const int n = 2 * dims;
  std::size_t reported = 0;
  for (const PointTrack& track : tracks_) {
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
        track.estimate.time < time ? filter_.predict(track.estimate, time) : track.estimate;
    const Gaussian g = filter_.combine(at_time);
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
    const auto& names = filter_.names();
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
  // Deleted tracks are reported once, in the batch that deletes them.
  std::erase_if(tracks_,
                [](const PointTrack& t) { return t.life.status == TrackStatus::kDeleted; });
  if (branching()) {
    slots_.clear();
    for (std::size_t i = 0; i < tracks_.size(); ++i) slots_[tracks_[i].id] = static_cast<int>(i);
  }
}

}  // namespace skytrack
