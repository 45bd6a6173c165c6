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
namespace {

using namespace tracking_detail;

/// The manoeuvre gate's filter: the profile's manoeuvre models with their white acceleration
/// raised to branching.manoeuvre_accel_sigma, in the main filter's state layout. Each gate
/// starts the models from the track's combined estimate, so no mode switching is needed.
/// Vertically too: a pull-up or a level change is a manoeuvre, and with flight levels the
/// height is measured to tens of metres (canalA's military traffic climbs at 50 m/s).
Expected<std::optional<ImmFilter>> manoeuvre_filter(const config::TrackingProfile& profile,
                                                    const ImmFilter& main) {
  const config::BranchingSpec& spec = profile.point.branching;
  if (!spec.enabled) return std::optional<ImmFilter>();
  std::vector<AnyMotionModel> models;
  std::vector<std::string> names;
  for (const std::string& name : spec.manoeuvre_models) {
    const auto it = std::find_if(profile.motion_models.begin(), profile.motion_models.end(),
                                 [&](const config::MotionModelSpec& m) { return m.name == name; });
    if (it == profile.motion_models.end()) {
      return make_error("branching.manoeuvre_models: no motion model named '" + name + "'");
    }
    config::MotionModelSpec model = *it;
    model.accel_sigma = std::max(model.accel_sigma, spec.manoeuvre_accel_sigma);
    model.vertical_accel_sigma = std::max(model.vertical_accel_sigma, spec.manoeuvre_accel_sigma);
    models.push_back(make_motion_model(model));
    names.push_back(name);
  }
  if (models.empty()) return make_error("branching.manoeuvre_models: no model given");
  const auto n = static_cast<Eigen::Index>(models.size());
  auto filter =
      ImmFilter::create(std::move(models), std::move(names), Eigen::MatrixXd::Identity(n, n),
                        main.layout(), main.measurement_spec());
  if (!filter) {
    return make_error("branching.manoeuvre_models: " + filter.error().message);
  }
  return std::optional<ImmFilter>(std::move(*filter));
}

/// The life rules of sons and grandsons started from manoeuvre pairs: the profile's, with
/// branching.confirmation (m_of_n: rule 10 of paper 003 §1 as in its examples, a branch
/// confirmed by its own run of associations).
config::TrackLifeSpec branch_life(const config::TrackingProfile& profile) {
  config::TrackLifeSpec spec = profile.point.track_life;
  spec.confirmation = profile.point.branching.confirmation;
  return spec;
}

}  // namespace

Expected<PointTracker> PointTracker::create(const config::TrackingProfile& profile, int dims) {
  if (profile.mode != config::TrackingMode::kPoint) {
    return make_error("profile '" + profile.identity.name + "': mode " +
                      std::string(config::to_string(profile.mode)) +
                      " is not implemented by the point tracker");
  }
  if (dims != 2 && dims != 3) return make_error("tracker dimension must be 2 or 3");
  auto filter = ImmFilter::from_profile(profile, dims);
  if (!filter) return unexpected(filter.error());
  auto manoeuvre = manoeuvre_filter(profile, *filter);
  if (!manoeuvre) return unexpected(manoeuvre.error());
  // A held last motion's models: the IMM's, with at most last_motion_accel_sigma of noise.
  std::optional<ImmFilter> hold;
  if (const double sigma = profile.point.branching.last_motion_accel_sigma;
      profile.point.branching.enabled && profile.point.branching.coast_on_last_motion &&
      sigma > 0.0) {
    config::TrackingProfile held = profile;
    for (config::MotionModelSpec& m : held.motion_models) {
      m.accel_sigma = std::min(m.accel_sigma, sigma);
    }
    auto made = ImmFilter::from_profile(held, dims);
    if (!made) return unexpected(made.error());
    hold = std::move(*made);
  }
  const StateLayout layout = filter->layout();
  return PointTracker(profile, layout, std::move(*filter), std::move(*manoeuvre), std::move(hold));
}

PointTracker::PointTracker(const config::TrackingProfile& profile, StateLayout layout,
                           ImmFilter filter, std::optional<ImmFilter> manoeuvre,
                           std::optional<ImmFilter> hold)
    : profile_(profile),
      branch_life_(branch_life(profile)),
      layout_(layout),
      filter_(std::move(filter)),
      manoeuvre_(std::move(manoeuvre)),
      hold_(std::move(hold)),
      initiator_(profile.point.initiation, layout.dims),
      jpda_(JpdaOptions{.max_exact_tracks = profile.association.max_exact_cluster_size,
                        .k_best = profile.association.k_best}),
      jpda_manoeuvre_(JpdaOptions{.max_exact_tracks = profile.association.max_exact_cluster_size,
                                  .k_best = std::min(profile.association.k_best, kManoeuvreKBest),
                                  .max_exact_states = kManoeuvreExactStates}) {
  for (int d = 1; d <= kMaxMeasurementDim; ++d) {
    gate_threshold_[d] = chi_square_quantile(profile.association.gate_probability, d);
    const double half = 0.5 * d;
    gate_volume_per_peak_[d] = std::pow(0.5 * gate_threshold_[d], half) / std::tgamma(half + 1.0);
    manoeuvre_threshold_[d] =
        chi_square_quantile(profile.point.branching.manoeuvre_gate_probability, d);
  }
  // What a track may do between looks, for its search region (search_regions): three sigma
  // of its models' white acceleration, or its fastest turn.
  for (const config::MotionModelSpec& m : profile.motion_models) {
    region_accel_ = std::max(region_accel_, 3.0 * m.accel_sigma);
    max_turn_rate_ = std::max(max_turn_rate_, std::abs(m.turn_rate));
  }
  if (manoeuvre_) {
    const int n = manoeuvre_->mode_count();
    manoeuvre_start_ = Eigen::VectorXd::Constant(n, 1.0 / n);
  }
}

void PointTracker::start_frame(const PlotScan& scan, TrackFrame& frame) const {
  frame.sensor = scan.sensor;
  frame.scan = scan.scan;
  frame.time = scan.time;
  // frame.tracks keeps its elements (and their storage) for report_tracks to overwrite.
  frame.associations.clear();
  frame.events.clear();
}

void PointTracker::process(const PlotScan& scan, Preprocessing& pre, TrackFrame& frame,
                           ScanReport& report) {
  start_frame(scan, frame);
  events_.clear();
  ++batches_;
  pre_ = &pre;

  auto start = Clock::now();
  const std::size_t n = pre.plots().size();
  gated_.assign(n, 0);
  used_by_branch_.assign(n, 0);
  held_.assign(n, 0);
  double t_min = scan.time, t_max = scan.time;
  for (const PlotMeasurement& p : pre.plots()) {
    t_min = std::min(t_min, p.time);
    t_max = std::max(t_max, p.time);
  }
  gate(scan, 0.5 * (t_min + t_max), 0.5 * (t_max - t_min));
  report.predict += since(start);

  start = Clock::now();
  reject_clutter(report);
  if (branching()) {
    associate_branches(scan, report, frame);
  } else {
    associate_and_update(report, frame);
  }
  report.associate = since(start);

  start = Clock::now();
  initiate(scan, report, frame);
  if (branching()) retire_doomed_fathers();
  // Every event of the batch is decided: emitted, in the order they were made.
  frame.events.insert(frame.events.end(), std::make_move_iterator(events_.begin()),
                      std::make_move_iterator(events_.end()));
  events_.clear();
  number_confirmed(frame);
  // The tracks this look saw (aged or updated, or started or branched in it).
  for (std::size_t t = 0; t < tracks_.size(); ++t) {
    if (t >= covered_.size() || covered_[t] != 0 || took_candidates_[t] != 0) {
      tracks_[t].set_looked(pre.sensor(), pre.sweep());
    }
  }
  report_tracks(scan.time, report, frame);
  report.numeric_failures += std::exchange(numeric_failures_, 0);
  pre_ = nullptr;
  report.manage = since(start);
}

void PointTracker::report_only(const PlotScan& scan, TrackFrame& frame, ScanReport& report) {
  start_frame(scan, frame);
  report.plots = static_cast<int>(scan.plots.size());
  report_tracks(scan.time, report, frame);
}

double PointTracker::plot_spread_at(const Eigen::Vector3d& position, const PlotScan& scan) const {
  // Plot position spread near a track from the batch's sigmas (plot overrides are rare); in
  // 3-D the height error counts too (elevation is often measured worse than azimuth).
  const config::MeasurementSigmas& d = profile_.measurement.default_sigma;
  const MeasurementSigma& s = scan.sigma;
  const bool height = layout_.dims == 3;
  const double range = (position - scan.platform.position).norm();
  const double angle =
      std::max(s.azimuth.value_or(d.azimuth), height ? s.elevation.value_or(d.elevation) : 0.0);
  const double polar = std::max(s.range.value_or(d.range), range * angle);
  const double cartesian =
      std::max({s.x.value_or(d.x), s.y.value_or(d.y), height ? s.z.value_or(d.z) : 0.0});
  return std::max(polar, cartesian);
}

bool PointTracker::covers(const PlotScan& scan, const Eigen::Vector3d& position) const {
  return !scan.coverage || scan.coverage->contains(enu_to_polar(position, scan.platform).azimuth);
}

bool PointTracker::covers_region(const PlotScan& scan, const Eigen::Vector3d& centre,
                                 double radius) const {
  if (!scan.coverage) return true;
  const PolarPoint polar = enu_to_polar(centre, scan.platform);
  const double margin = std::atan2(radius, std::max(polar.range, radius));
  return scan.coverage->contains(polar.azimuth - margin) ||
         scan.coverage->contains(polar.azimuth + margin) || scan.coverage->contains(polar.azimuth);
}

}  // namespace skytrack
