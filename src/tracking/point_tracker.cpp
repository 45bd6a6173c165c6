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

using tracking_detail::add_association;
using tracking_detail::add_event;
using tracking_detail::kLifeSpreadDims;
using tracking_detail::mode_spread;
using tracking_detail::position_of;
using tracking_detail::position_spread;
using tracking_detail::valid_association;
using tracking_detail::velocity_of;

using Clock = std::chrono::steady_clock;

std::chrono::microseconds since(Clock::time_point start) {
  return std::chrono::duration_cast<std::chrono::microseconds>(Clock::now() - start);
}

// Association weights below this are not worth a Kalman update; below the second they are not
// reported in the output's associations.
constexpr double kNegligibleBeta = 1e-4;
constexpr double kAssociationReportThreshold = 1e-3;
// The manoeuvre kinds' probabilities only choose which branches to start, so their clusters
// (wide gates, chained in dense clutter) get a cheaper exact attempt and fewer joint events.
constexpr int kManoeuvreKBest = 10;
constexpr std::int64_t kManoeuvreExactStates = std::int64_t{1} << 12;
// Murty's k-best costs about k x tracks^2 x (tracks + plots): seconds for the clusters of
// hundreds of tracks a flood of random plots chains together, where k joint events are a
// vanishing share of the whole anyway. Clusters of more than this many times the exact limit
// take per-track PDA, the bound on a batch's association work.
constexpr int kKBestClusterFactor = 2;
// A plot cloud: more than this many other plots within this many of a plot's position
// sigmas in one look (a formation of a few aircraft is not one).
constexpr int kCloudPlots = 16;
constexpr double kCloudSigmas = 5.0;
// Height spread of a track started from plots without height [m].
constexpr double kUnknownHeightSigma = 3000.0;
// Acceleration spread of a new track, where the layout has acceleration states [m/s^2].
constexpr double kInitialAccelerationSigma = 10.0;
// Sparse clutter when nothing better is known: one false plot per (10 km)^k.
double sparse_clutter_density(int position_dims) {
  return std::pow(1e-4, position_dims);
}

std::optional<clutter::ClutterMapCells> clutter_map_cells(const config::ClutterMapSpec& map) {
  if (!map.enabled) return std::nullopt;
  return clutter::ClutterMapCells{
      .range = map.range_cell, .azimuth = map.azimuth_cell, .cartesian = map.cartesian_cell};
}

/// True when the plot measures height (elevation, z or altitude).
bool measures_height(const PlotMeasurement& plot) {
  return plot.model.position_components == 3;
}

/// The manoeuvre gate's filter: the profile's manoeuvre models with their white acceleration
/// raised to branching.manoeuvre_accel_sigma, in the main filter's state layout. Each gate
/// starts the models from the track's combined estimate, so no mode switching is needed.
/// Vertically too: a pull-up or a level change is a manoeuvre, and with flight levels the
/// height is measured to tens of metres (canalA's military traffic climbs at 50 m/s).
Expected<std::optional<ImmFilter>> manoeuvre_filter(const config::TrackingProfile& profile,
                                                    const ImmFilter& main) {
  const config::BranchingSpec& spec = profile.branching;
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
  config::TrackLifeSpec spec = profile.track_life;
  spec.confirmation = profile.branching.confirmation;
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
  if (const double sigma = profile.branching.last_motion_accel_sigma;
      profile.branching.enabled && profile.branching.coast_on_last_motion && sigma > 0.0) {
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
      initiator_(profile.initiation, layout.dims),
      clutter_(profile.clutter_rejection),
      density_(clutter_map_cells(profile.association.clutter_map)),
      jpda_(JpdaOptions{.max_exact_tracks = profile.association.max_exact_cluster_size,
                        .k_best = profile.association.k_best}),
      jpda_manoeuvre_(JpdaOptions{.max_exact_tracks = profile.association.max_exact_cluster_size,
                                  .k_best = std::min(profile.association.k_best, kManoeuvreKBest),
                                  .max_exact_states = kManoeuvreExactStates}) {
  for (int d = 1; d <= kMaxMeasurementDim; ++d) {
    gate_threshold_[d] = chi_square_quantile(profile.association.gate_probability, d);
    const double half = 0.5 * d;
    gate_volume_per_peak_[d] = std::pow(0.5 * gate_threshold_[d], half) / std::tgamma(half + 1.0);
    manoeuvre_threshold_[d] = chi_square_quantile(profile.branching.manoeuvre_gate_probability, d);
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

void PointTracker::process(const PlotScan& scan, TrackFrame& frame, ScanReport& report,
                           const LookSources* sources) {
  start_frame(scan, frame);
  events_.clear();
  ++batches_;

  auto start = Clock::now();
  make_measurements(scan, sources, report);
  double t_min = scan.time, t_max = scan.time;
  for (const PlotMeasurement& p : plots_) {
    t_min = std::min(t_min, p.time);
    t_max = std::max(t_max, p.time);
  }
  gate(scan, 0.5 * (t_min + t_max), 0.5 * (t_max - t_min));
  report.predict = since(start);

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
      tracks_[t].set_looked(sensor_, look_sweep_);
    }
  }
  report_tracks(scan.time, report, frame);
  report.numeric_failures += std::exchange(numeric_failures_, 0);
  if (windowed_) {
    boxed_.resize(plots_.size());
    for (std::size_t j = 0; j < plots_.size(); ++j) boxed_[j] = rejected_[j] || crowd_[j] ? 0 : 1;
    density_.remember(sensor_, plots_, rejected_, boxed_, clutter_counted_);
  }
  report.manage = since(start);
}

void PointTracker::report_only(const PlotScan& scan, TrackFrame& frame, ScanReport& report) {
  start_frame(scan, frame);
  report.plots = static_cast<int>(scan.plots.size());
  report_tracks(scan.time, report, frame);
}

void PointTracker::make_measurements(const PlotScan& scan, const LookSources* sources,
                                     ScanReport& report) {
  plots_.clear();
  positions_.clear();
  report.plots = static_cast<int>(scan.plots.size());
  sensor_ = scan.sensor;
  windowed_ = sources != nullptr && !profile_.association.clutter_density;
  clutter_counted_.assign(scan.plots.size(), 0);
  // A snapshot look is one revolution's worth of sweep after the last.
  const double snapshot_sweep = 2.0 * std::numbers::pi * static_cast<double>(batches_);
  look_sweep_ = sources != nullptr ? sources->sweep_to : snapshot_sweep;
  for (std::size_t i = 0; i < scan.plots.size(); ++i) {
    const int from = sources != nullptr ? sources->batch_of[i] : -1;
    const PlotScan& header = from >= 0 ? sources->batches[static_cast<std::size_t>(from)] : scan;
    auto measurement = measurement_from_plot(scan.plots[i], header,
                                             profile_.measurement.default_sigma, layout_.dims);
    if (!measurement) {
      ++report.plots_invalid;
      continue;
    }
    measurement->sensor = scan.sensor;
    measurement->scan = header.scan;
    measurement->sweep = sources != nullptr ? sources->sweep[i] : snapshot_sweep;
    positions_.push_back(approximate_position(*measurement));
    plots_.push_back(std::move(*measurement));
  }
  rejected_.assign(plots_.size(), 0);
  gated_.assign(plots_.size(), 0);
  used_by_branch_.assign(plots_.size(), 0);
  held_.assign(plots_.size(), 0);
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

void PointTracker::gate(const PlotScan& scan, double batch_mid, double half_span) {
  // A 3-D tracker's polar plot without height lies at el = 0, kilometres under its target's
  // track: a batch holding one is searched on the horizontal plane (the exact gate is in
  // measurement space), so a secondary radar's reply without Mode C still finds its track.
  const bool heightless =
      layout_.dims == 3 && std::any_of(plots_.begin(), plots_.end(), [](const PlotMeasurement& p) {
        return is_polar(p.model.kind) && !measures_height(p);
      });
  index_.build(positions_, heightless ? 2 : layout_.dims);
  find_plot_clouds();
  candidates_.clear();
  manoeuvre_candidates_.clear();
  // branching.last_motion_false_plots weighs the clutter round each plot while gating: from
  // all of this batch's plots (associate_branches re-estimates it from the ungated ones).
  if (holds_last_motion() && profile_.branching.last_motion_false_plots > 0.0) {
    estimate_clutter_density();
  }
  batch_mid_ = batch_mid;
  half_span_ = half_span;
  predicted_.resize(tracks_.size());
  if (branching()) {  // the manoeuvre gates start from the estimates before this batch
    // Assigned in place: the slots keep their storage from batch to batch.
    previous_.resize(tracks_.size());
    has_previous_.assign(tracks_.size(), 0);
    // Only tracks that may get a manoeuvre gate or start sons need it: firm fathers and
    // branches (most tracks in heavy clutter are tentative fathers).
    for (std::size_t t = 0; t < tracks_.size(); ++t) {
      const PointTrack& track = tracks_[t];
      if (track.branch != BranchType::kFather || is_reported_as_firm(track.life.status)) {
        // A father holding its last motion since a miss: its manoeuvre gate and sons start
        // from its last update (rule 6), coasted by its IMM, whose turn modes reach where a
        // turn since then has gone.
        previous_[t] = starts_from_coast(track) ? *track.coasted : track.estimate;
        has_previous_[t] = 1;
      }
    }
  }
  covered_.assign(tracks_.size(), 1);
  took_candidates_.assign(tracks_.size(), 0);
  dense_.assign(tracks_.size(), profile_.branching.last_motion_false_plots > 0.0 ? 0 : 1);
  suspended_at_gate_.clear();
  const double widest = gate_threshold_[kMaxMeasurementDim];
  for (std::size_t t = 0; t < tracks_.size(); ++t) {
    PointTrack& track = tracks_[t];
    // Undecided until its sons are gone; for one look only when it holds its last motion,
    // which stays its hypothesis beside its sons' (rule 5 then decides between them).
    if (track.undecided && (tree_.branch_count(track.id) == 0 || holds_last_motion())) {
      track.doomed.reset();
      track.undecided = false;
    }
    const ImmEstimate& estimate = track.estimate;
    if (scan.coverage) {
      // A sector look: most tracks lie far from it; a bound on the search region says which
      // need no prediction.
      SearchRegion bound = region_bound(static_cast<int>(t), scan,
                                        std::max(batch_mid, estimate.time), widest, region_accel_);
      bound.radius += seed_speed(static_cast<int>(t)) * half_span;
      if (!covers_region(scan, bound.centre, bound.radius)) {
        covered_[t] = 0;
        predicted_[t] = estimate;
        continue;
      }
    }
    const Gaussian mid =
        filter_.combine(filter_.predict(estimate, std::max(batch_mid, estimate.time)));
    const Eigen::Vector3d centre = position_of(mid.mean, layout_.dims);
    // A sector batch looks at a track whose predicted position lies in the sector; one whose
    // search region only reaches into it may take a plot from it but is not aged by it.
    covered_[t] =
        covers(scan, centre) && look_sweep_ - track.looked_by(sensor_) > std::numbers::pi ? 1 : 0;
    if (covered_[t] != 0 &&
        suspends_before_gating(tracks_[t], mid, std::max(batch_mid, estimate.time))) {
      tracks_[t].doomed = batches_;
      suspended_at_gate_.push_back(static_cast<int>(t));
    }
    // Grandsons and doomed fathers take manoeuvre pairs only; manoeuvre gates are made
    // later, for the tracks that can use them (point_tracker_branches.cpp).
    const bool non_manoeuvre = tracks_[t].branch != BranchType::kGrandson && !tracks_[t].doomed;
    // Search radius: the widest gate in the most uncertain direction, plus the motion over
    // half the batch's time span. The exact gate test is per plot, in measurement space.
    const double radius = search_radius(mid, centre, widest, scan);
    if (!covered_[t] && !covers_region(scan, centre, radius)) {
      predicted_[t] = estimate;
      continue;
    }
    index_.within(centre, radius, neighbours_);
    if (neighbours_.empty()) {
      predicted_[t] = estimate;
      continue;
    }
    // The track is updated at the time of its nearest candidate plot.
    predicted_[t] = filter_.predict(estimate, std::max(nearest_time(centre), estimate.time));
    if (!non_manoeuvre) continue;
    const std::optional<ImmEstimate> narrowed = last_motion(track, predicted_[t].time);
    // branching.last_motion_false_plots: the clutter is weighed in the last motion's gate,
    // whether or not the father gates on it in this look.
    const bool weighs_clutter =
        holds_last_motion() && profile_.branching.last_motion_false_plots > 0.0;
    const std::optional<ImmEstimate> held =
        narrowed || !weighs_clutter ? narrowed : last_motion(track, predicted_[t].time, true);
    // In a clutter area: a plot round it in dense clutter (without last_motion_false_plots
    // every track is, from the start of the batch).
    for (std::size_t k = 0; held && dense_[t] == 0 && k < neighbours_.size(); ++k) {
      const int j = neighbours_[k];
      const Innovation in = innovate(held->modes.front(), layout_, plots_[j], profile_.measurement);
      if (in.ok && in_dense_clutter(in, j)) dense_[t] = 1;
    }
    if (narrowed && dense_[t] != 0) {
      // In a clutter area its non-manoeuvre association is the motion unchanged (§2.1): it
      // gates, weighs and is updated on its last motion alone. The IMM's turn modes spread the
      // likelihood over the false plots (exp. 2, seeds 1-100: the number survives 52 -> 70 %)
      // and turn the father onto them; a turn is its sons' to follow (rule 6).
      predicted_[t] = *narrowed;
    }
    for (const int j : neighbours_) {
      PlotHypothesis hypothesis = filter_.hypothesise(predicted_[t], plots_[j]);
      if (!hypothesis.usable) continue;
      // A plot inside any mode's gate (the union of the modes' gates), or a coasting father's
      // last motion's gate (branching.coast_on_last_motion), is a candidate.
      if (hypothesis.min_nis > gate_threshold_[plots_[j].model.size()]) continue;
      gated_[j] = 1;
      took_candidates_[t] = 1;
      const double likelihood = hypothesis.likelihood;
      candidates_.push_back({static_cast<int>(t), j, std::move(hypothesis), likelihood});
    }
  }
}

bool PointTracker::starts_from_coast(const PointTrack& track) const {
  return holds_last_motion() && track.branch == BranchType::kFather &&
         track.life.consecutive_misses >= 1 && track.last_detected && track.coasted;
}

void PointTracker::hold_last_motion(PointTrack& track) const {
  const std::optional<ImmEstimate> coast = last_motion(track, track.estimate.time, true);
  if (!coast) return;
  track.coasted = track.life.consecutive_misses >= 1 && track.coasted
                      ? filter_.predict(*track.coasted, track.estimate.time)
                      : track.estimate;
  track.estimate = *coast;
}

bool PointTracker::holds_last_motion() const {
  return branching() && profile_.branching.coast_on_last_motion;
}

bool PointTracker::in_dense_clutter(const Innovation& last_motion, int plot) const {
  // Gate volume c_d g^(d/2) sqrt|S| = gate_volume_per_peak_ / N(0; 0, S), the peak density
  // from log N(nu; 0, S) and the NIS (c_d = pi^(d/2) / Gamma(d/2 + 1)).
  const double volume = gate_volume_per_peak_[plots_[plot].model.size()] *
                        std::exp(-last_motion.log_likelihood - 0.5 * last_motion.nis);
  return clutter_density(plots_[plot], plot) * volume >= profile_.branching.last_motion_false_plots;
}

std::optional<ImmEstimate> PointTracker::last_motion(const PointTrack& track, double time,
                                                     bool missing_now) const {
  // A coast son always holds its father's last motion (branching.coast_sons).
  const bool firm_father =
      track.branch == BranchType::kFather && is_reported_as_firm(track.life.status);
  if (!holds_last_motion() || !track.last_detected || !(firm_father || track.coast_son) ||
      (!track.coast_son && track.life.consecutive_misses < 1 && !missing_now &&
       profile_.branching.non_manoeuvre_gate != config::NonManoeuvreGate::kLastMotion)) {
    return std::nullopt;
  }
  // The likeliest mode at the last detection, predicted alone: IMM mixing would blend in the
  // other modes' diverging predictions.
  ImmEstimate one = *track.last_detected;
  Eigen::Index kept = 0;
  one.probabilities.maxCoeff(&kept);
  for (Gaussian& m : one.modes) m = one.modes[static_cast<std::size_t>(kept)];
  one.probabilities.setZero();
  one.probabilities[kept] = 1.0;
  ImmEstimate predicted = (hold_ ? *hold_ : filter_).predict(one, std::max(time, one.time));
  for (Gaussian& m : predicted.modes) m = predicted.modes[static_cast<std::size_t>(kept)];
  return predicted;
}

double PointTracker::search_radius(const Gaussian& g, const Eigen::Vector3d& centre,
                                   double threshold, const PlotScan& scan) const {
  const double track_sigma = position_spread(g, layout_.dims);
  const double plot_sigma = plot_spread_at(centre, scan);
  return std::sqrt(threshold * (track_sigma * track_sigma + plot_sigma * plot_sigma)) +
         velocity_of(g.mean, layout_.dims).norm() * half_span_;
}

double PointTracker::nearest_time(const Eigen::Vector3d& centre) const {
  int nearest = neighbours_.front();
  double best = std::numeric_limits<double>::infinity();
  for (const int j : neighbours_) {
    const double d = (positions_[j] - centre).squaredNorm();
    if (d < best) {
      best = d;
      nearest = j;
    }
  }
  return plots_[nearest].time;
}

void PointTracker::reject_clutter(ScanReport& report) {
  if (!profile_.clutter_rejection.enabled || plots_.empty()) return;
  // Plots in the gate of a confirmed track are kept whatever their density.
  std::vector<std::uint8_t> protect(plots_.size(), 0);
  for (const Candidate& c : candidates_) {
    const TrackStatus status = tracks_[c.track].life.status;
    if (status == TrackStatus::kConfirmed || status == TrackStatus::kCoasting) {
      protect[c.plot] = 1;
    }
  }
  const clutter::ClutterRejectionResult& result = clutter_.apply(positions_, layout_.dims, protect);
  for (std::size_t j = 0; j < plots_.size(); ++j) rejected_[j] = result.keep[j] ? 0 : 1;
  std::erase_if(candidates_, [&](const Candidate& c) { return rejected_[c.plot] != 0; });
  std::erase_if(manoeuvre_candidates_, [&](const Candidate& c) { return rejected_[c.plot] != 0; });
  report.plots_rejected_clutter = result.rejected;
  add_event(events_, TrackEventType::kClutterRejected, 0,
            std::to_string(result.rejected) + " of " + std::to_string(plots_.size()) + " plots");
}

void PointTracker::associate_and_update(ScanReport& report, TrackFrame& frame) {
  estimate_clutter_density();
  kind_list_.resize(candidates_.size());
  for (std::size_t k = 0; k < candidates_.size(); ++k) kind_list_[k] = static_cast<int>(k);
  solve_clusters(candidates_, kind_list_, profile_.association.gate_probability, report,
                 [&](int t, std::span<const int> mine, std::span<const double> beta, double miss) {
                   update_track(t, mine, beta, miss, frame);
                 });
}

const JpdaResult& PointTracker::pda_marginals(const JpdaProblem& problem) {
  // Each track on its own (PDA): beta_j ~ likelihood ratio_j, beta_0 ~ miss weight.
  pda_result_ = JpdaResult{};
  const Eigen::Index n = problem.likelihood.rows(), m = problem.likelihood.cols();
  pda_result_.beta = Eigen::MatrixXd::Zero(n, m + 1);
  for (Eigen::Index t = 0; t < n; ++t) {
    const double total =
        problem.miss[t] + problem.likelihood.row(t).sum() / problem.clutter_density;
    if (!(total > 0.0)) {
      pda_result_.beta(t, 0) = 1.0;
      continue;
    }
    pda_result_.beta(t, 0) = problem.miss[t] / total;
    for (Eigen::Index j = 0; j < m; ++j) {
      pda_result_.beta(t, j + 1) = problem.likelihood(t, j) / problem.clutter_density / total;
    }
  }
  pda_result_.approximated = true;
  return pda_result_;
}

void PointTracker::solve_clusters(const std::vector<Candidate>& pool, std::span<const int> list,
                                  double gate_probability, ScanReport& report,
                                  const OnTrack& on_track, bool pda_above_exact) {
  const double pd = profile_.association.detection_probability;
  // Candidates are grouped by track (they were made track by track) and clustered.
  pairs_.clear();
  for (const int k : list) pairs_.push_back({pool[k].track, pool[k].plot});
  const std::span<const Cluster> clusters =
      clusters_.build(static_cast<int>(tracks_.size()), static_cast<int>(plots_.size()), pairs_);
  std::vector<int> first(tracks_.size() + 1, 0);  // range of `list` per track
  for (const int k : list) ++first[pool[k].track + 1];
  for (std::size_t t = 0; t < tracks_.size(); ++t) first[t + 1] += first[t];

  std::vector<double> beta;
  std::vector<int> mine;
  for (const Cluster& cluster : clusters) {
    const auto n_tracks = static_cast<Eigen::Index>(cluster.tracks.size());
    const auto n_plots = static_cast<Eigen::Index>(cluster.plots.size());
    if (n_plots == 0) {
      for (const int t : cluster.tracks) on_track(t, {}, {}, 1.0);
      continue;
    }
    ++report.clusters;
    report.largest_cluster = std::max(report.largest_cluster, static_cast<int>(n_tracks));
    // Each plot's likelihood ratio against clutter in its own measurement space.
    JpdaProblem problem;
    problem.likelihood = Eigen::MatrixXd::Zero(n_tracks, n_plots);
    problem.miss = Eigen::VectorXd::Constant(n_tracks, 1.0 - pd * gate_probability);
    problem.clutter_density = 1.0;
    const auto column = [&](int plot) {
      return std::find(cluster.plots.begin(), cluster.plots.end(), plot) - cluster.plots.begin();
    };
    for (Eigen::Index ti = 0; ti < n_tracks; ++ti) {
      const int t = cluster.tracks[ti];
      for (int k = first[t]; k < first[t + 1]; ++k) {
        const Candidate& c = pool[list[k]];
        problem.likelihood(ti, column(c.plot)) =
            pd * c.likelihood / clutter_density(plots_[c.plot], c.plot);
      }
    }
    const bool gnn = profile_.association.method == config::AssociationMethod::kGnn;
    const auto exact = static_cast<Eigen::Index>(profile_.association.max_exact_cluster_size);
    const bool too_large = n_tracks > kKBestClusterFactor * exact;
    const bool pda = !gnn && n_tracks > exact && (pda_above_exact || too_large);
    const JpdaResult& result =
        pda ? pda_marginals(problem)
            : (gnn ? gnn_.associate(problem)
                   : (pda_above_exact ? jpda_manoeuvre_ : jpda_).solve(problem));
    numeric_failures_ += result.status != JpdaStatus::kOk;
    if (pda) {
      ++report.approximated_clusters;
      add_event(events_, TrackEventType::kJpdaApproximated, 0,
                std::to_string(n_tracks) + " tracks, " + std::to_string(n_plots) + " plots, " +
                    (pda_above_exact ? "manoeuvre gates" : "too many for k-best") +
                    ": PDA per track");
    } else if (result.approximated) {
      ++report.approximated_clusters;
      add_event(events_, TrackEventType::kJpdaApproximated, 0,
                std::to_string(n_tracks) + " tracks, " + std::to_string(n_plots) + " plots, " +
                    std::to_string(profile_.association.k_best) + " best joint events");
    }
    for (Eigen::Index ti = 0; ti < n_tracks; ++ti) {
      const int t = cluster.tracks[ti];
      beta.clear();
      mine.clear();
      for (int k = first[t]; k < first[t + 1]; ++k) {
        beta.push_back(result.beta(ti, column(pool[list[k]].plot) + 1));
        mine.push_back(list[k]);
      }
      // The non-manoeuvre gates decide which plots the tracks explain (initiation).
      if (&pool == &candidates_) note_explained(pool, mine, beta);
      on_track(t, mine, beta, result.beta(ti, 0));
    }
  }
}

void PointTracker::update_track(int t, std::span<const int> candidates,
                                std::span<const double> beta_plots, double beta_miss,
                                TrackFrame& frame, bool reports_deletion) {
  PointTrack& track = tracks_[t];
  if (!covered_[t] && candidates.empty()) return;  // not looked at: neither updated nor aged
  const double pd = profile_.association.detection_probability;
  const PlotRatios ratios =
      soft_update(t, candidates_, candidates, beta_plots, beta_miss, track.id, frame);
  const double detection = 1.0 - beta_miss;
  track.quality = 0.8 * track.quality + 0.2 * detection;
  // P_D on its detectability chain, as in its support: a target masked in a clutter area
  // is not evidence that there is none (IPDA with a detectability chain).
  update_existence(track.life, ratios.sum,
                   support_detection_probability(track.life, pd, detectability_at(t)),
                   profile_.association.gate_probability, profile_.track_life);
  add_support(track.life, ratios, t);
  bool detected = detection > 0.5;
  if (holds_last_motion() && is_reported_as_firm(track.life.status) &&
      static_cast<std::size_t>(t) < dense_.size() && dense_[t] != 0) {
    // branching.coast_on_last_motion: a father with no valid association (§2.2: no plot
    // likelier than its miss) coasts on the motion it was last seen in, however much its
    // plots weigh together; the turns it may have started are its sons' to find (§4.2).
    detected = valid_association(beta_plots, beta_miss);
    if (!detected) hold_last_motion(track);
  }
  const LifeChange change = advance_life(
      track.life, detected, mode_spread(track.estimate, kLifeSpreadDims), profile_.track_life);
  if (change.confirmed) {
    add_event(events_, TrackEventType::kConfirmed, track.id, "");
    if (branching()) confirmed_now_.push_back(t);
  }
  if (change.started_coasting) add_event(events_, TrackEventType::kCoasting, track.id, "");
  if (change.deleted && reports_deletion)
    add_event(events_, TrackEventType::kDeleted, track.id, "");
}

PointTracker::PlotRatios PointTracker::soft_update(int t, std::vector<Candidate>& pool,
                                                   std::span<const int> candidates,
                                                   std::span<const double> beta_plots,
                                                   double beta_miss, std::int64_t number,
                                                   TrackFrame& frame) {
  PointTrack& track = tracks_[t];
  const double pd = profile_.association.detection_probability;
  if (candidates.empty()) {
    track.estimate = filter_.predict(track.estimate, std::max(frame.time, track.estimate.time));
    return {};
  }
  PlotRatios ratios;
  // Plots with a negligible weight change nothing but cost a Kalman update per mode: they
  // are left out and the other weights renormalised.
  hypotheses_.clear();
  kept_beta_.clear();
  double density = 0.0, kept = beta_miss;
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    Candidate& c = pool[candidates[k]];
    const double plot_density = clutter_density(plots_[c.plot], c.plot);
    density += plot_density / static_cast<double>(candidates.size());
    if (c.hypothesis.usable) {
      const double ratio = c.hypothesis.likelihood / plot_density;
      ratios.sum += ratio;
      ratios.best = std::max(ratios.best, ratio);
    }
    if (beta_plots[k] >= kAssociationReportThreshold) {
      add_association(frame, number, plots_[c.plot].plot_id, plots_[c.plot].scan, beta_plots[k]);
    }
    if (beta_plots[k] < kNegligibleBeta) continue;
    hypotheses_.push_back(std::move(c.hypothesis));
    kept_beta_.push_back(beta_plots[k]);
    kept += beta_plots[k];
  }
  for (double& b : kept_beta_) b /= kept;
  track.estimate = counted(filter_.update(predicted_[t], hypotheses_, kept_beta_, beta_miss / kept,
                                          pd, profile_.association.gate_probability, density));
  if (holds_last_motion() && valid_association(beta_plots, beta_miss)) {
    track.last_detected = track.estimate;  // it found its target (a son, later a father)
  }
  return ratios;
}

ImmEstimate PointTracker::start_estimate(const Initiation& initiation, TrackLife& life) const {
  // Two-point start at the second plot, then IMM updates with any further plots.
  const PlotMeasurement& a = initiation.plots[0];
  const PlotMeasurement& b = initiation.plots[1];
  const int dims = layout_.dims;
  const double dt = std::max(b.time - a.time, 1e-3);
  const Eigen::Vector3d pa = approximate_position(a), pb = approximate_position(b);
  const double sa = position_sigma(a), sb = position_sigma(b);
  Gaussian g;
  g.mean = StateVec::Zero(layout_.size());
  g.covariance = StateMat::Zero(layout_.size(), layout_.size());
  for (int axis = 0; axis < dims; ++axis) {
    const int p = StateLayout::position(axis), v = StateLayout::velocity(axis);
    const bool unknown_height = axis == 2 && !(measures_height(a) && measures_height(b));
    g.mean[p] = pb[axis];
    g.mean[v] = unknown_height ? 0.0 : (pb[axis] - pa[axis]) / dt;
    g.covariance(p, p) = unknown_height ? kUnknownHeightSigma * kUnknownHeightSigma : sb * sb;
    g.covariance(v, v) = unknown_height ? 100.0 * 100.0 : (sa * sa + sb * sb) / (dt * dt);
    g.covariance(p, v) = g.covariance(v, p) = unknown_height ? 0.0 : sb * sb / dt;
  }
  if (layout_.acceleration) {
    for (int axis = 0; axis < dims; ++axis) {
      const int i = layout_.acceleration_index(axis);
      g.covariance(i, i) = kInitialAccelerationSigma * kInitialAccelerationSigma;
    }
  }
  if (layout_.turn_rate) {
    double sigma = 0.05;
    for (const auto& spec : profile_.motion_models) {
      if (spec.type == config::MotionModelType::kCoordinatedTurnEstimated) {
        sigma = spec.initial_turn_rate_sigma;
      }
    }
    g.covariance(layout_.turn_rate_index(), layout_.turn_rate_index()) = sigma * sigma;
  }
  const auto& probabilities = profile_.initial_mode_probabilities;
  ImmEstimate estimate =
      filter_.initial(g,
                      Eigen::Map<const Eigen::VectorXd>(
                          probabilities.data(), static_cast<Eigen::Index>(probabilities.size())),
                      b.time);
  const double one = 1.0;
  for (std::size_t k = 2; k < initiation.plots.size(); ++k) {
    const PlotMeasurement& plot = initiation.plots[k];
    const ImmEstimate predicted = filter_.predict(estimate, std::max(plot.time, estimate.time));
    const PlotHypothesis h = filter_.hypothesise(predicted, plot);
    if (!h.usable) continue;
    const double density = clutter_density(plot, -1);
    update_existence(life, h.likelihood / density, profile_.association.detection_probability,
                     profile_.association.gate_probability, profile_.track_life);
    estimate = counted(filter_.update(predicted, std::span(&h, 1), std::span(&one, 1), 0.0,
                                      profile_.association.detection_probability,
                                      profile_.association.gate_probability, density));
  }
  return estimate;
}

config::DetectabilitySpec PointTracker::detectability_at(int t) const {
  // Masking is a clutter area's (branching.last_motion_false_plots): elsewhere a miss is
  // independent of the last, as P_D says.
  config::DetectabilitySpec chain = profile_.branching.detectability;
  if (static_cast<std::size_t>(t) >= dense_.size() || dense_[t] == 0) chain.hide = 0.0;
  return chain;
}

void PointTracker::add_support(TrackLife& life, const PlotRatios& ratios, int where) const {
  const double pd = support_detection_probability(life, profile_.association.detection_probability,
                                                  detectability_at(where));
  life.support += scan_support(ratios.best, pd, profile_.association.gate_probability);
  update_detectability(life, ratios.sum, where);
}

void PointTracker::update_detectability(TrackLife& life, double likelihood_ratio, int where) const {
  skytrack::update_detectability(life, likelihood_ratio, profile_.association.detection_probability,
                                 profile_.association.gate_probability, detectability_at(where));
}

void PointTracker::note_explained(const std::vector<Candidate>& pool, std::span<const int> mine,
                                  std::span<const double> beta) {
  // A track whose most likely plot has more than gated_seed_beta of its weight explains that
  // plot alone: the others in its gate are more than it can explain (one plot per target)
  // and stay free for initiation. A track without such a plot (its own plot missed, or its
  // target manoeuvring away from its prediction) may be explained by any of them: it holds
  // its whole gate, so a chain cannot start on its target's plots while it lags.
  int best = -1;
  double best_beta = -1.0;
  for (std::size_t k = 0; k < mine.size(); ++k) {
    if (beta[k] > best_beta) {
      best_beta = beta[k];
      best = pool[mine[k]].plot;
    }
  }
  if (best < 0) return;
  if (best_beta > profile_.initiation.gated_seed_beta) {
    held_[best] = 1;
    return;
  }
  for (const int k : mine) held_[pool[k].plot] = 1;
}

bool PointTracker::free_for_initiation(std::size_t j) const {
  if (rejected_[j] || used_by_branch_[j]) return false;
  // In no gate, or in the gates of tracks that each explain another plot: a target of its
  // own, such as a formation member inside its neighbour's gate.
  return gated_[j] == 0 || held_[j] == 0;
}

void PointTracker::find_plot_clouds() {
  // Many plots within a few of a plot's position sigmas in one look: chaff, a jammer's false
  // plots, a swarm too dense to resolve. No chain can tell a target there from the rest, and
  // a chain per plot would cost the square of the crowd in tracks and gates.
  crowd_.assign(plots_.size(), 0);
  for (std::size_t j = 0; j < plots_.size(); ++j) {
    crowd_[j] =
        index_.more_than(positions_[j], kCloudSigmas * position_sigma(plots_[j]), kCloudPlots);
  }
}

void PointTracker::initiate(const PlotScan& scan, ScanReport& report, TrackFrame& frame) {
  std::vector<PlotMeasurement> unused;
  int clouded = 0;
  for (std::size_t j = 0; j < plots_.size(); ++j) {
    if (!free_for_initiation(j)) continue;
    if (crowd_[j]) {
      ++clouded;
      continue;
    }
    unused.push_back(plots_[j]);
  }
  if (clouded > 0) {
    report.plots_in_clouds += clouded;
    add_event(events_, TrackEventType::kPlotCloud, 0,
              std::to_string(clouded) + " plots in clouds start no track (more than " +
                  std::to_string(kCloudPlots) + " plots within " +
                  std::to_string(static_cast<int>(kCloudSigmas)) + " position sigmas)");
  }
  const auto covered = [&](const Eigen::Vector3d& p) { return covers(scan, p); };
  if (branching()) {
    find_lost_fathers(scan);
    continue_lost_fathers(report);
  }
  int tentative = static_cast<int>(std::count_if(tracks_.begin(), tracks_.end(), [](const auto& t) {
    return t.branch == BranchType::kFather && t.life.status == TrackStatus::kTentative;
  }));
  int refused = 0;
  for (const Initiation& initiation :
       initiator_.step(batches_, scan.time, sensor_, look_sweep_, unused, covered)) {
    if (branching()) {
      const int father = lost_father_of(initiation.plots.back());
      if (father >= 0 && start_chain_branch(father, initiation, report, frame)) continue;
    }
    if (tentative >= profile_.initiation.max_tentative) {
      ++refused;
      continue;
    }
    ++tentative;
    PointTrack track;
    track.id = next_provisional_++;
    track.life = initiated_life(static_cast<int>(initiation.plots.size()), initiation.scans);
    track.life.existence = profile_.track_life.initial_existence;
    track.estimate = start_estimate(initiation, track.life);
    track.quality = 1.0;
    if (branching()) {
      track.last_plot = initiation.plots.back();
      track.last_plot_batch = batches_;
      tree_.add_father(track.id);
      slots_[track.id] = static_cast<int>(tracks_.size());
    }
    std::string detail = "from plots";
    for (const PlotMeasurement& p : initiation.plots) {
      detail.append(" ").append(std::to_string(p.plot_id));
    }
    add_event(events_, TrackEventType::kInitiated, track.id, detail);
    const PlotMeasurement& last = initiation.plots.back();
    add_association(frame, track.id, last.plot_id, last.scan, 1.0);
    tracks_.push_back(std::move(track));
    ++report.initiated;
  }
  if (refused > 0) {
    report.initiations_refused += refused;
    add_event(events_, TrackEventType::kOverload, 0,
              std::to_string(refused) +
                  " chains start no track: " + std::to_string(profile_.initiation.max_tentative) +
                  " tentative tracks held (initiation.max_tentative)");
  }
}

void PointTracker::report_tracks(double time, ScanReport& report, TrackFrame& frame) {
  const int dims = layout_.dims;
  const int n = 2 * dims;
  std::size_t reported = 0;
  for (const PointTrack& track : tracks_) {
    if (track.branch != BranchType::kFather) {  // sons and grandsons are internal
      if (track.life.status != TrackStatus::kDeleted) ++report.branches;
      continue;
    }
    if (track.replaced) continue;  // its number lives on in the branch that replaced it
    // A doomed father is not reported while it waits for a branch to replace it (an
    // undecided one is).
    if (track.doomed && !track.undecided && track.life.status != TrackStatus::kDeleted) continue;
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

double PointTracker::clutter_density(const PlotMeasurement& plot, int index) const {
  // Clutter density in the plot's measurement space: this batch's estimate, or the profile's
  // value (per m^k in the tracking frame) times the polar volume element.
  if (index >= 0 && auto_density_[static_cast<std::size_t>(index)] > 0.0) {
    return auto_density_[static_cast<std::size_t>(index)];
  }
  const MeasurementModel& m = plot.model;
  double density =
      profile_.association.clutter_density.value_or(sparse_clutter_density(m.position_components));
  density *= m.volume_element(plot.z);
  if (m.has_range_rate) density /= 2.0 * profile_.initiation.max_speed;
  return density;
}

void PointTracker::estimate_clutter_density() {
  auto_density_.assign(plots_.size(), 0.0);
  if (profile_.association.clutter_density) return;
  // The clutter map counts the plots no firm track gates: those are the false plots.
  clutter_counted_.assign(plots_.size(), 0);
  if (profile_.association.clutter_map.enabled) {
    for (std::size_t j = 0; j < plots_.size(); ++j) clutter_counted_[j] = rejected_[j] ? 0 : 1;
    for (const Candidate& c : candidates_) {
      if (is_reported_as_firm(tracks_[c.track].life.status)) clutter_counted_[c.plot] = 0;
    }
  }
  boxed_.resize(plots_.size());
  for (std::size_t j = 0; j < plots_.size(); ++j) boxed_[j] = rejected_[j] || crowd_[j] ? 0 : 1;
  density_.estimate(sensor_, windowed_, plots_, boxed_, clutter_counted_, auto_density_);
}

}  // namespace skytrack
