// The branch layer's creation, the look's parts it works on, and its hooks into the plain
// tracker (branch_layer.hpp).
#include "skytrack/tracking/branch_layer.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <utility>

#include "branch_layer_support.hpp"
#include "point_life.hpp"
#include "point_look.hpp"
#include "point_tracker_support.hpp"
#include "skytrack/core/chi_square.hpp"

namespace skytrack {
namespace {

using namespace tracking_detail;

/// The manoeuvre gate's filter: the profile's manoeuvre models with their white acceleration
/// raised to branching.manoeuvre_accel_sigma, in the main filter's state layout. Each gate
/// starts the models from the track's combined estimate, so no mode switching is needed.
/// Vertically too: a pull-up or a level change is a manoeuvre, and with flight levels the
/// height is measured to tens of metres (canalA's military traffic climbs at 50 m/s).
Expected<ImmFilter> manoeuvre_filter(const config::TrackingProfile& profile,
                                     const ImmFilter& main) {
  const config::BranchingSpec& spec = profile.point.branching;
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
  return std::move(*filter);
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

Expected<std::optional<BranchLayer>> BranchLayer::create(const config::TrackingProfile& profile,
                                                         const ImmFilter& main, int dims) {
  if (!profile.point.branching.enabled) return std::optional<BranchLayer>();
  auto manoeuvre = manoeuvre_filter(profile, main);
  if (!manoeuvre) return unexpected(manoeuvre.error());
  // A held last motion's models: the IMM's, with at most last_motion_accel_sigma of noise.
  std::optional<ImmFilter> hold;
  if (const double sigma = profile.point.branching.last_motion_accel_sigma;
      profile.point.branching.coast_on_last_motion && sigma > 0.0) {
    config::TrackingProfile held = profile;
    for (config::MotionModelSpec& m : held.motion_models) {
      m.accel_sigma = std::min(m.accel_sigma, sigma);
    }
    auto made = ImmFilter::from_profile(held, dims);
    if (!made) return unexpected(made.error());
    hold = std::move(*made);
  }
  return std::optional<BranchLayer>(BranchLayer(profile, std::move(*manoeuvre), std::move(hold)));
}

BranchLayer::BranchLayer(const config::TrackingProfile& profile, ImmFilter manoeuvre,
                         std::optional<ImmFilter> hold)
    : profile_(profile),
      branch_life_(branch_life(profile)),
      manoeuvre_(std::move(manoeuvre)),
      hold_(std::move(hold)) {
  for (int d = 1; d <= kMaxMeasurementDim; ++d) {
    manoeuvre_threshold_[d] =
        chi_square_quantile(profile.point.branching.manoeuvre_gate_probability, d);
  }
  const int n = manoeuvre_.mode_count();
  manoeuvre_start_ = Eigen::VectorXd::Constant(n, 1.0 / n);
}

TrackStore& BranchLayer::store() {
  return look_->store;
}
const TrackStore& BranchLayer::store() const {
  return look_->store;
}
Gater& BranchLayer::gater() {
  return look_->gater;
}
const Gater& BranchLayer::gater() const {
  return look_->gater;
}
const ImmFilter& BranchLayer::filter() const {
  return look_->filter;
}
Preprocessing& BranchLayer::pre() const {
  return look_->pre;
}
std::vector<TrackEvent>& BranchLayer::events() {
  return look_->events;
}

const PointTrack* BranchLayer::stand_in(const PointTrack& father) const {
  if (look_ == nullptr || father.life.consecutive_misses == 0) return nullptr;
  const BranchNode* node = tree_.find(father.id);
  if (node == nullptr) return nullptr;
  // The prior that the target left the father's motion: the share of its IMM's other modes
  // (none with one motion model: the profile says the targets do not manoeuvre).
  const double onset = 1.0 - father.estimate.probabilities.maxCoeff();
  const PointTrack* best = nullptr;
  const auto consider = [&](std::int64_t id) {
    const int t = store().slot(id);
    if (t < 0) return;
    const PointTrack& branch = store()[static_cast<std::size_t>(t)];
    if (branch.coast_son() || branch.life.status == TrackStatus::kDeleted ||
        branch.last_plot_batch != look_->batch ||
        onset * branch.pair_probability <= (1.0 - onset) * (1.0 - branch.pair_probability)) {
      return;
    }
    if (best == nullptr || branch.score > best->score) best = &branch;
  };
  for (const std::int64_t son : node->children) {
    consider(son);
    if (const BranchNode* s = tree_.find(son)) {
      for (const std::int64_t grandson : s->children) consider(grandson);
    }
  }
  return best;
}

void BranchLayer::before_gating() {
  manoeuvre_candidates_.clear();
  const std::size_t n = store().size();
  // branching.last_motion_false_plots weighs the clutter round each plot while gating: from
  // all of this look's plots (associate re-estimates it from the ungated ones).
  if (holds_last_motion() && profile_.point.branching.last_motion_false_plots > 0.0) {
    look_->associator.estimate_clutter_density(pre(), store().all(), {});
  }
  // The manoeuvre gates start from the estimates before this look. Assigned in place: the
  // slots keep their storage from look to look.
  previous_.resize(n);
  has_previous_.assign(n, 0);
  suspended_at_gate_.clear();
  for (std::size_t t = 0; t < n; ++t) {
    PointTrack& track = store()[t];
    // Only tracks that may get a manoeuvre gate or start sons need it: firm fathers and
    // branches (most tracks in heavy clutter are tentative fathers).
    if (track.branch != BranchType::kFather || is_reported_as_firm(track.life.status)) {
      // A father holding its last motion since a miss: its manoeuvre gate and sons start
      // from its last update (rule 6), coasted by its IMM, whose turn modes reach where a
      // turn since then has gone.
      previous_[t] = starts_from_coast(track) ? *track.coasted : track.estimate;
      has_previous_[t] = 1;
    }
    // Undecided until its sons are gone; for one look only when it holds its last motion,
    // which stays its hypothesis beside its sons' (rule 5 then decides between them).
    if (track.undecided() && (tree_.branch_count(track.id) == 0 || holds_last_motion())) {
      track.state = FatherState::kActive;
    }
  }
}

bool BranchLayer::at_mid_batch(int t, bool covered, const Gaussian& mid, double time) {
  PointTrack& track = store()[static_cast<std::size_t>(t)];
  if (covered && suspends_before_gating(track, mid, time)) {
    track.state = FatherState::kSuspended;
    suspended_at_gate_.push_back(t);
  }
  // Grandsons and doomed fathers take manoeuvre pairs only; manoeuvre gates are made
  // later, for the tracks that can use them (branch_layer_pairs.cpp).
  return track.branch != BranchType::kGrandson && !track.doomed();
}

void BranchLayer::narrow(int t, ImmEstimate& predicted, std::span<const int> neighbours,
                         std::uint8_t& clutter_area) {
  const PointTrack& track = store()[static_cast<std::size_t>(t)];
  const bool narrowed = last_motion(track, predicted.time, false, narrowed_);
  // branching.last_motion_false_plots: the clutter is weighed in the last motion's gate,
  // whether or not the father gates on it in this look.
  const bool weighs_clutter =
      holds_last_motion() && profile_.point.branching.last_motion_false_plots > 0.0;
  const bool held =
      narrowed || (weighs_clutter && last_motion(track, predicted.time, true, narrowed_));
  // In a clutter area: a plot round it in dense clutter (without last_motion_false_plots
  // every track is, from the start of the look). The gate's size is the innovation
  // covariance's, which depends on a plot only through its measurement model: one
  // covariance serves the neighbours that share the model.
  const MeasurementModel* model = nullptr;
  double log_det = 0.0;
  for (std::size_t k = 0; held && clutter_area == 0 && k < neighbours.size(); ++k) {
    const int j = neighbours[k];
    const PlotMeasurement& plot = pre().plots()[j];
    if (model == nullptr || !same_innovation_shape(*model, plot.model)) {
      log_det = last_motion_log_det(plot);
      model = &plot.model;
    }
    if (std::isfinite(log_det) && in_dense_clutter(log_det, j)) clutter_area = 1;
  }
  if (narrowed && clutter_area != 0) {
    // In a clutter area its non-manoeuvre association is the motion unchanged (§2.1): it
    // gates, weighs and is updated on its last motion alone. The IMM's turn modes spread the
    // likelihood over the false plots (exp. 2, seeds 1-100: the number survives 52 -> 70 %)
    // and turn the father onto them; a turn is its sons' to follow (rule 6).
    predicted = narrowed_;
  }
}

void BranchLayer::updated(PointTrack& track, bool valid) {
  if (holds_last_motion() && valid) {
    track.last_detected = track.estimate;  // it found its target (a son, later a father)
  }
}

bool BranchLayer::detected(int t, bool valid, bool plain) {
  PointTrack& track = store()[static_cast<std::size_t>(t)];
  if (!holds_last_motion() || !is_reported_as_firm(track.life.status) ||
      !gater().in_clutter_area(static_cast<std::size_t>(t))) {
    return plain;
  }
  // branching.coast_on_last_motion: a father with no valid association (§2.2: no plot
  // likelier than its miss) coasts on the motion it was last seen in, however much its
  // plots weigh together; the turns it may have started are its sons' to find (§4.2).
  if (!valid) hold_last_motion(track);
  return valid;
}

void BranchLayer::father_started(int t, const Initiation& initiation) {
  PointTrack& track = store()[static_cast<std::size_t>(t)];
  track.last_plot = initiation.plots.back();
  track.last_plot_batch = look_->batch;
  tree_.add_father(track.id);
}

void BranchLayer::renamed(std::span<const std::pair<std::int64_t, std::int64_t>> renamed) {
  for (const auto& [provisional, number] : renamed) tree_.rename(provisional, number);
}

void BranchLayer::before_initiation(const PlotScan& scan, ScanReport& report) {
  find_lost_fathers(scan);
  continue_lost_fathers(report);
}

bool BranchLayer::take_chain(const Initiation& initiation, ScanReport& report, TrackFrame& frame) {
  const int father = lost_father_of(initiation.plots.back());
  return father >= 0 && start_chain_branch(father, initiation, report, frame);
}

void BranchLayer::add_support(TrackLife& life, const PlotRatios& ratios, int where) const {
  tracking_detail::add_support(profile_, life, ratios.best, ratios.sum,
                               gater().in_clutter_area(static_cast<std::size_t>(where)));
}

}  // namespace skytrack
