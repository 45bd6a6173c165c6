// The branch layer's pairs (paper 003 §2.2-2.3): manoeuvre gates, the ordered confirmation of
// the valid pairs, undecided fathers, coast sons and the promotion of confirmed sons.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include "branch_layer_support.hpp"
#include "point_life.hpp"
#include "point_look.hpp"
#include "point_tracker_support.hpp"
#include "skytrack/tracking/branch_layer.hpp"

namespace skytrack {

using namespace tracking_detail;

BranchLayer::Sphere BranchLayer::manoeuvre_reach(const ImmEstimate& prior, const PlotScan& scan,
                                                 std::vector<Sphere>* modes,
                                                 ImmEstimate* mid_out) const {
  ImmEstimate mid = manoeuvre_prediction(prior, std::max(gater().batch_mid(), prior.time));
  const Eigen::Vector3d centre = position_of(manoeuvre_.combine(mid).mean, filter().layout().dims);
  // The manoeuvre gate is the union of its models' gates: cover every model's region.
  if (modes != nullptr) modes->clear();
  double radius = 0.0;
  for (const Gaussian& mode : mid.modes) {
    const Eigen::Vector3d at = position_of(mode.mean, filter().layout().dims);
    const double reach =
        gater().search_radius(mode, centre, manoeuvre_threshold_[kMaxMeasurementDim], scan);
    radius = std::max(radius, (at - centre).norm() + reach);
    if (modes != nullptr) modes->push_back({at, reach});
  }
  if (mid_out != nullptr) *mid_out = std::move(mid);
  return {centre, radius};
}

void BranchLayer::gate_manoeuvre(const PlotScan& scan, int t, bool for_update) {
  const PointTrack& track = store()[t];
  // The manoeuvre models run from the track's estimate before this batch (a father is
  // updated by now), over the whole interval to the plot.
  const ImmEstimate& prior = previous_[static_cast<std::size_t>(t)];
  if (!gater().covered(static_cast<std::size_t>(t)) && scan.coverage && !starts_from_coast(track)) {
    // A sector look far from the track: a bound on its manoeuvre gate says so cheaply.
    SearchRegion bound = gater().region_bound(
        store().all(), t, filter(), scan, std::max(gater().batch_mid(), prior.time),
        manoeuvre_threshold_[kMaxMeasurementDim],
        std::max(gater().region_accel(), 3.0 * profile_.point.branching.manoeuvre_accel_sigma));
    bound.radius += gater().seed_speed(t) * gater().half_span();
    if (!Gater::covers_region(scan, bound.centre, bound.radius)) return;
  }
  const auto [centre, radius] = manoeuvre_reach(prior, scan, &mode_reach_);
  if (!gater().covered(static_cast<std::size_t>(t)) && !Gater::covers_region(scan, centre, radius))
    return;
  pre().index().within(centre, radius, neighbours_);
  // The models' regions can lie far apart (turns either way): only plots inside one of them
  // are worth an innovation.
  std::erase_if(neighbours_, [&](int j) {
    return std::none_of(mode_reach_.begin(), mode_reach_.end(), [&](const Sphere& m) {
      return (pre().positions()[j] - m.centre).squaredNorm() <= m.radius * m.radius;
    });
  });
  if (neighbours_.empty()) return;
  const double time = std::max(Gater::nearest_time(pre(), neighbours_, centre), prior.time);
  const ImmEstimate predicted = manoeuvre_prediction(prior, time);
  if (for_update) gater().predicted()[t] = filter().predict(track.estimate, time);
  manoeuvre_shapes_.clear();
  shapes_.clear();
  for (const int j : neighbours_) {
    if (manoeuvre_.min_nis(predicted, pre().plots()[j], manoeuvre_shapes_) >
        manoeuvre_threshold_[pre().plots()[j].model.size()]) {
      continue;
    }
    const PlotHypothesis m = manoeuvre_.hypothesise(predicted, pre().plots()[j], manoeuvre_shapes_);
    if (!m.usable || m.min_nis > manoeuvre_threshold_[pre().plots()[j].model.size()]) continue;
    // Only an updating pair needs the plot against the track's own IMM prediction.
    PlotHypothesis hypothesis;
    if (for_update) {
      hypothesis = filter().hypothesise(gater().predicted()[t], pre().plots()[j], shapes_);
      if (!hypothesis.usable) continue;
    }
    manoeuvre_candidates_.push_back({t, j, std::move(hypothesis), m.likelihood});
  }
}

void BranchLayer::claim_best_plot(int t, const std::vector<Candidate>& pool,
                                  std::span<const int> mine, std::span<const double> beta,
                                  double miss) {
  int best = -1;
  double best_beta = miss;
  for (std::size_t k = 0; k < mine.size(); ++k) {
    if (beta[k] > best_beta) {
      best_beta = beta[k];
      best = pool[mine[k]].plot;
    }
  }
  if (best < 0) return;
  int& owner = claimed_by_[static_cast<std::size_t>(best)];
  owner = owner == -1 ? t : -2;  // -2: the likeliest plot of several fathers
}

void BranchLayer::split_undecided_fathers() {
  const double tau = profile_.point.branching.ambiguity_beta;
  for (const PendingSplit& p : pending_splits_) {
    // A plot that is another father's likeliest is that father's target (a formation
    // member), not a second hypothesis of this one.
    const auto free = [&](std::size_t k) {
      const int owner = claimed_by_[static_cast<std::size_t>(p.plots[k])];
      return p.beta[k] > p.miss && (owner == -1 || owner == p.track);
    };
    int likely = 0;
    for (std::size_t k = 0; k < p.plots.size(); ++k) {
      if (free(k) && p.beta[k] >= tau) ++likely;
    }
    PointTrack& track = store()[p.track];
    if (likely < 2 || track.doomed() || track.life.status == TrackStatus::kDeleted) continue;
    // Undecided: no non-manoeuvre pair; the plots its IMM-JPDA found likely start its sons.
    std::erase_if(branch_pairs_, [&](const BranchPair& b) {
      return b.kind == PairKind::kFatherNonManoeuvre && b.track == p.track;
    });
    track.state = FatherState::kUndecided;
    if (holds_last_motion()) {  // its sons hold the plots; it coasts on its last motion
      track.last_detected = p.last_detected;
      hold_last_motion(track);
    }
    add_event(events(), TrackEventType::kUndecided, track.id,
              "two plots above ambiguity_beta: the sons from its plots decide");
    for (std::size_t k = 0; k < p.plots.size(); ++k) {
      if (free(k)) {
        branch_pairs_.push_back({PairKind::kFatherManoeuvre, p.track, p.plots[k], p.beta[k], -1});
      }
    }
  }
}

void BranchLayer::update_father(int t, std::span<const int> candidates,
                                std::span<const double> beta_plots, double beta_miss) {
  PointTrack& father = store()[t];
  const bool firm = is_reported_as_firm(father.life.status);
  // A firm father its life deletes is suspended, not deleted: no "deleted" event.
  look_->updater.update_track(*look_, t, candidates, beta_plots, beta_miss, *this,
                              /*reports_deletion=*/!firm);
  if (!firm || father.life.status != TrackStatus::kDeleted) return;
  // Deleted by its life: it lives on, coasting, while branches may replace it.
  father.life.status = TrackStatus::kCoasting;
  if (!father.doomed()) {
    father.state = FatherState::kSuspended;
    add_event(events(), TrackEventType::kSuspended, father.id,
              "deleted by its track life; kept unreported while a branch may replace it");
  }
}

void BranchLayer::confirm_branch_pairs(ScanReport& report, TrackFrame& frame) {
  const std::vector<BranchPair> confirmed = confirm_pairs(
      branch_pairs_, static_cast<int>(store().size()), static_cast<int>(pre().plots().size()));
  bool sons_marked = false, sons_promoted = false;
  confirmed_sons_.clear();
  for (const BranchPair& pair : confirmed) {
    if (pair.kind == PairKind::kSonNonManoeuvre && !sons_marked) {
      // The fathers' pairs (§2.3 (1)) are done. The son of an undecided father (two likely
      // plots: often two targets, a wingman joining) whose non-manoeuvre pair was confirmed
      // (§2.2) has its update in this scan: a sibling promoted in this scan makes it
      // independent (§2.3 (2)) instead of deleting it, so the wingman keeps its plots. The
      // sons of a lost father are one target's hypotheses: the paper's order stands.
      for (const BranchPair& p : confirmed) {
        if (p.kind != PairKind::kSonNonManoeuvre) continue;
        const std::int64_t son = store()[p.track].id;
        if (of_undecided_father(son)) tree_.mark_non_manoeuvre_update(son);
      }
      sons_marked = true;
    }
    if (pair.kind > PairKind::kSonNonManoeuvre && !sons_promoted) {
      promote_confirmed_sons(report);
      sons_promoted = true;
    }
    // An earlier decision of this batch may have removed the track.
    if (store()[pair.track].life.status == TrackStatus::kDeleted) continue;
    switch (pair.kind) {
      case PairKind::kFatherNonManoeuvre: {  // §2.3 (1), rule 5
        PointTrack& father = store()[pair.track];
        father.last_plot = pre().plots()[pair.plot];
        father.last_plot_batch = look_->batch;
        look_->used_by_branch[pair.plot] = 1;
        changes_.clear();
        tree_.release_branches(father.id, changes_);
        if (!changes_.empty()) {  // the common firm father has no branch: no reason to word
          apply(changes_,
                name(BranchType::kFather, father.id) + " took plot " +
                    std::to_string(pre().plots()[pair.plot].plot_id) + " (rule 5)",
                report);
        }
        note_doubtful_update(pair);
        break;
      }
      case PairKind::kSonNonManoeuvre:    // §2.3 (2), rules 8 and 10
      case PairKind::kGrandsonManoeuvre:  // §2.3 (3), rules 9 and 10
        update_branch(pair, report);
        break;
      case PairKind::kSonManoeuvre:     // §2.3 (4), rule 7
      case PairKind::kFatherManoeuvre:  // §2.3 (5), rule 6
        create_branch(pair, report, frame);
        break;
    }
  }
  if (!sons_promoted) promote_confirmed_sons(report);
  start_coast_sons(report, frame);
}

void BranchLayer::note_doubtful_update(const BranchPair& pair) {
  if (profile_.point.branching.coast_sons == 0 || pair.candidate < 0) return;
  const PointTrack& father = store()[pair.track];
  if (father.doomed() || !is_reported_as_firm(father.life.status)) return;
  // The plot's density as clutter against its density as the father's target (detected):
  // about 0.2 for a target's plot inside paper003_exp2's clutter area, 1e-4 outside it.
  const double clutter = pre().density(pre().plots()[pair.plot], pair.plot);
  const double target = profile_.association.detection_probability *
                        gater().candidates()[static_cast<std::size_t>(pair.candidate)].likelihood;
  const double doubt = clutter / (clutter + target);
  if (!(doubt >= profile_.point.branching.coast_son_doubt)) return;
  doubtful_.push_back({pair.track, doubt, pre().plots()[pair.plot].plot_id});
}

void BranchLayer::start_coast_sons(ScanReport& report, TrackFrame& frame) {
  const int most = profile_.point.branching.coast_sons;
  for (const DoubtfulUpdate& d : doubtful_) {
    const PointTrack& father = store()[d.track];
    const BeforeUpdate& before = before_update_[static_cast<std::size_t>(d.track)];
    if (father.branch != BranchType::kFather || father.replaced || father.doomed() ||
        father.life.status == TrackStatus::kDeleted || !before.valid || !before.motion) {
      continue;
    }
    const std::int64_t father_id = father.id;
    const double quality = father.quality;
    const double score = father.score + log_of(d.doubt);
    const std::string plot = std::to_string(d.plot_id);
    // Room: the oldest coast son that took no plot in this batch goes.
    const std::vector<std::int64_t> sons = tree_.coast_sons(father_id);
    if (static_cast<int>(sons.size()) >= most) {
      const auto oldest = std::find_if(sons.begin(), sons.end(), [&](std::int64_t id) {
        const int i = store().slot(id);
        return i >= 0 && touched_[static_cast<std::size_t>(i)] == 0;
      });
      if (oldest == sons.end()) continue;
      changes_.clear();
      tree_.remove(*oldest, changes_);
      apply(changes_, "the oldest of coast_sons " + std::to_string(most), report);
    }
    if (!make_room(father_id, father_id, score, d.plot_id, report)) continue;
    PointTrack son;
    son.id = store().provisional();
    son.branch = BranchType::kSon;
    son.origin = BranchOrigin::kCoast;
    son.life.scans = 1;
    son.life.consecutive_misses = 1;  // this look: the target missed, the plot a false alarm
    son.life.existence = std::clamp(d.doubt, profile_.point.track_life.initial_existence,
                                    profile_.point.track_life.confirm_existence);
    // The target missed in this look: the father's support before its plot, and a miss.
    son.life.support = before.support;
    son.life.detectable = before.detectable;
    add_support(son.life, {}, d.track);  // in its father's clutter
    son.last_detected = before.motion;
    son.estimate = *last_motion(son, frame.time, true);
    son.quality = quality;
    son.score = score;
    tree_.add_branch(son.id, father_id, true);
    add_event(events(), TrackEventType::kBranchCreated, father_id,
              name(BranchType::kSon, son.id) + " of " + name(BranchType::kFather, father_id) +
                  ": its last motion before plot " + plot + " (coast son, doubt " +
                  std::to_string(d.doubt).substr(0, 4) + ")");
    ++report.point.branches_created;
    store().add(std::move(son));
    touched_.push_back(1);
  }
  doubtful_.clear();
}

double BranchLayer::miss_score(int t) const {
  return log_of(
      1.0 - support_detection_probability(
                store()[t].life, profile_.association.detection_probability,
                detectability_at(profile_, gater().in_clutter_area(static_cast<std::size_t>(t)))));
}

bool BranchLayer::age_coast_son(int t, double time) {
  PointTrack& son = store()[t];
  add_support(son.life, {}, t);
  son.life.history <<= 1;
  ++son.life.scans;
  ++son.life.consecutive_misses;
  if (std::optional<ImmEstimate> held = last_motion(son, time, true)) {
    son.estimate = std::move(*held);
  }
  return son.life.consecutive_misses < profile_.point.track_life.delete_confirmed_misses &&
         position_spread(son.estimate.modes.front(), kLifeSpreadDims) <=
             profile_.point.track_life.delete_position_sigma;
}

bool BranchLayer::of_undecided_father(std::int64_t son) const {
  const int f = store().slot(tree_.father_of(son));
  return f >= 0 && store()[f].undecided();
}

double BranchLayer::family_support(std::int64_t father) const {
  // The father and its paper 003 branches: a turn its sons follow is the target too.
  double best = store()[store().slot(father)].life.support;
  const BranchNode* node = tree_.find(father);
  if (node == nullptr) return best;
  for (const std::int64_t son : node->children) {
    const BranchNode* s = tree_.find(son);
    if (s == nullptr || s->coast) continue;
    for (const std::int64_t id : s->children) {
      const int g = store().slot(id);
      if (g >= 0) best = std::max(best, store()[g].life.support);
    }
    const int i = store().slot(son);
    if (i >= 0) best = std::max(best, store()[i].life.support);
  }
  return best;
}

void BranchLayer::promote_confirmed_sons(ScanReport& report) {
  // The sons of an undecided father confirmed in the same scan: the one whose plot fits its
  // prediction best takes the number; the others, updated too, become independent
  // (§2.3 (2)). In pair order (JPDA weights, about 1 for a son alone in its cluster) the
  // first would win by chance.
  std::stable_sort(
      confirmed_sons_.begin(), confirmed_sons_.end(),
      [](const ConfirmedSon& a, const ConfirmedSon& b) { return a.likelihood > b.likelihood; });
  for (const ConfirmedSon& son : confirmed_sons_) {
    const PointTrack& track = store()[son.track];
    if (track.life.status == TrackStatus::kDeleted || track.branch != BranchType::kSon) continue;
    changes_.clear();
    tree_.promote(track.id, changes_);
    apply(changes_, "confirmed with plot " + std::to_string(son.plot_id) + " (rule 10)", report);
  }
  confirmed_sons_.clear();
}

}  // namespace skytrack
