// The point tracker's creation and a look's steps: gate, associate and update (plain, or the
// branch layer's pair kinds), initiate, number, report.
#include "skytrack/tracking/point_tracker.hpp"

#include <algorithm>
#include <iterator>
#include <string>
#include <utility>

#include "point_look.hpp"
#include "point_tracker_support.hpp"

namespace skytrack {

using namespace tracking_detail;

Expected<PointTracker> PointTracker::create(const config::TrackingProfile& profile, int dims) {
  if (profile.mode != config::TrackingMode::kPoint) {
    return make_error("profile '" + profile.identity.name + "': mode " +
                      std::string(config::to_string(profile.mode)) +
                      " is not implemented by the point tracker");
  }
  if (dims != 2 && dims != 3) return make_error("tracker dimension must be 2 or 3");
  auto filter = ImmFilter::from_profile(profile, dims);
  if (!filter) return unexpected(filter.error());
  auto branches = BranchLayer::create(profile, *filter, dims);
  if (!branches) return unexpected(branches.error());
  return PointTracker(profile, std::move(*filter), std::move(*branches));
}

PointTracker::PointTracker(const config::TrackingProfile& profile, ImmFilter filter,
                           std::optional<BranchLayer> branches)
    : profile_(profile),
      filter_(std::move(filter)),
      gater_(profile, filter_.layout().dims),
      associator_(profile),
      initiator_(profile.point.initiation, filter_.layout().dims,
                 ChainManoeuvre::from_models(profile.motion_models, filter_.layout().dims)),
      branches_(std::move(branches)),
      outlive_miss_existence_(existence_to_outlive_a_miss(
          profile.association.detection_probability, profile.association.gate_probability,
          profile.point.track_life, profile.point.branching.detectability)) {}

const BranchTree& PointTracker::branch_tree() const {
  static const BranchTree kNone;  // branching off: no branches
  return branches_ ? branches_->tree() : kNone;
}

void PointTracker::process(const PlotScan& scan, Preprocessing& pre, TrackFrame& frame,
                           ScanReport& report) {
  TrackReporter::start_frame(scan, frame);
  events_.clear();
  ++batches_;
  PointLook look{.profile = profile_,
                 .filter = filter_,
                 .store = store_,
                 .gater = gater_,
                 .associator = associator_,
                 .updater = updater_,
                 .scan = scan,
                 .pre = pre,
                 .frame = frame,
                 .report = report,
                 .batch = batches_,
                 .events = events_,
                 .used_by_branch = used_by_branch_,
                 .held = held_,
                 .initiation_plots = initiation_plots_,
                 .start_predicted = start_predicted_,
                 .start_shapes = start_shapes_,
                 .start_neighbours = start_neighbours_,
                 .start_hypotheses = start_hypotheses_,
                 .start_beta = start_beta_};
  BranchHooks& hooks = this->hooks();
  hooks.begin(look);

  auto start = Clock::now();
  const std::size_t n = pre.plots().size();
  used_by_branch_.assign(n, 0);
  held_.assign(n, 0);
  double t_min = scan.time, t_max = scan.time;
  for (const PlotMeasurement& p : pre.plots()) {
    t_min = std::min(t_min, p.time);
    t_max = std::max(t_max, p.time);
  }
  hooks.before_gating();
  gater_.gate(scan, pre, store_.all(), filter_, 0.5 * (t_min + t_max), 0.5 * (t_max - t_min),
              hooks);
  report.predict += since(start);

  start = Clock::now();
  reject_clutter(look);
  if (branches_) {
    branches_->associate(scan, report, frame);
  } else {
    associate_and_update(look);
  }
  report.associate = since(start);

  start = Clock::now();
  initiate(look);
  hooks.after_initiation();
  // Every event of the look is decided: emitted, in the order they were made.
  frame.events.insert(frame.events.end(), std::make_move_iterator(events_.begin()),
                      std::make_move_iterator(events_.end()));
  events_.clear();
  store_.number_confirmed(frame, renamed_);
  hooks.renamed(renamed_);
  // The tracks this look saw (aged or updated, or started or branched in it).
  for (std::size_t t = 0; t < store_.size(); ++t) {
    if (gater_.covered(t) || gater_.took_candidates(t)) {
      store_[t].set_looked(pre.sensor(), pre.sweep());
    }
  }
  TrackReporter::report(store_.all(), filter_, hooks, scan.time, report, frame);
  store_.erase_deleted();
  report.numeric_failures += look.numeric_failures;
  hooks.end();
  report.manage = since(start);
}

void PointTracker::report_only(const PlotScan& scan, TrackFrame& frame, ScanReport& report) {
  TrackReporter::start_frame(scan, frame);
  report.plots = static_cast<int>(scan.plots.size());
  TrackReporter::report(store_.all(), filter_, hooks(), scan.time, report, frame);
  store_.erase_deleted();
}

void PointTracker::search_regions(const PlotScan& header, double time,
                                  std::vector<SearchRegion>& out) const {
  out.clear();
  gater_.search_regions(store_.all(), filter_, header, time, out);
  initiator_.search_regions(time, out);
}

}  // namespace skytrack
