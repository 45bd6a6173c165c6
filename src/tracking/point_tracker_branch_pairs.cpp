// The branch layer's pairs (paper 003 §2.2-2.3): manoeuvre gates, the ordered confirmation of
// the valid pairs, undecided fathers, coast sons and the promotion of confirmed sons.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include "point_tracker_branch_support.hpp"
#include "point_tracker_support.hpp"
#include "skytrack/tracking/point_tracker.hpp"

namespace skytrack {

using namespace tracking_detail;

PointTracker::Sphere PointTracker::manoeuvre_reach(const ImmEstimate& prior, const PlotScan& scan,
                                                   std::vector<Sphere>* modes,
                                                   ImmEstimate* mid_out) const {
  ImmEstimate mid = manoeuvre_prediction(prior, std::max(batch_mid_, prior.time));
  const Eigen::Vector3d centre = position_of(manoeuvre_->combine(mid).mean, layout_.dims);
  // The manoeuvre gate is the union of its models' gates: cover every model's region.
  if (modes != nullptr) modes->clear();
  double radius = 0.0;
  for (const Gaussian& mode : mid.modes) {
    const Eigen::Vector3d at = position_of(mode.mean, layout_.dims);
    const double reach =
        search_radius(mode, centre, manoeuvre_threshold_[kMaxMeasurementDim], scan);
    radius = std::max(radius, (at - centre).norm() + reach);
    if (modes != nullptr) modes->push_back({at, reach});
  }
  if (mid_out != nullptr) *mid_out = std::move(mid);
  return {centre, radius};
}

void PointTracker::gate_manoeuvre(const PlotScan& scan, int t, bool for_update) {
  const PointTrack& track = tracks_[t];
  // The manoeuvre models run from the track's estimate before this batch (a father is
  // updated by now), over the whole interval to the plot.
  const ImmEstimate& prior = previous_[static_cast<std::size_t>(t)];
  if (covered_[t] == 0 && scan.coverage && !starts_from_coast(track)) {
    // A sector look far from the track: a bound on its manoeuvre gate says so cheaply.
    SearchRegion bound = region_bound(
        t, scan, std::max(batch_mid_, prior.time), manoeuvre_threshold_[kMaxMeasurementDim],
        std::max(region_accel_, 3.0 * profile_.point.branching.manoeuvre_accel_sigma));
    bound.radius += seed_speed(t) * half_span_;
    if (!covers_region(scan, bound.centre, bound.radius)) return;
  }
  const auto [centre, radius] = manoeuvre_reach(prior, scan, &mode_reach_);
  if (covered_[t] == 0 && !covers_region(scan, centre, radius)) return;
  pre_->index().within(centre, radius, neighbours_);
  // The models' regions can lie far apart (turns either way): only plots inside one of them
  // are worth an innovation.
  std::erase_if(neighbours_, [&](int j) {
    return std::none_of(mode_reach_.begin(), mode_reach_.end(), [&](const Sphere& m) {
      return (pre_->positions()[j] - m.centre).squaredNorm() <= m.radius * m.radius;
    });
  });
  if (neighbours_.empty()) return;
  const double time = std::max(nearest_time(centre), prior.time);
  const ImmEstimate predicted = manoeuvre_prediction(prior, time);
  if (for_update) predicted_[t] = filter_.predict(track.estimate, time);
  for (const int j : neighbours_) {
    const PlotHypothesis m = manoeuvre_->hypothesise(predicted, pre_->plots()[j]);
    if (!m.usable || m.min_nis > manoeuvre_threshold_[pre_->plots()[j].model.size()]) continue;
    // Only an updating pair needs the plot against the track's own IMM prediction.
    PlotHypothesis hypothesis;
    if (for_update) {
      hypothesis = filter_.hypothesise(predicted_[t], pre_->plots()[j]);
      if (!hypothesis.usable) continue;
    }
    manoeuvre_candidates_.push_back({t, j, std::move(hypothesis), m.likelihood});
  }
}

void PointTracker::claim_best_plot(int t, const std::vector<Candidate>& pool,
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

void PointTracker::split_undecided_fathers() {
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
    PointTrack& track = tracks_[p.track];
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
    add_event(events_, TrackEventType::kUndecided, track.id,
              "two plots above ambiguity_beta: the sons from its plots decide");
    for (std::size_t k = 0; k < p.plots.size(); ++k) {
      if (free(k)) {
        branch_pairs_.push_back({PairKind::kFatherManoeuvre, p.track, p.plots[k], p.beta[k], -1});
      }
    }
  }
}

void PointTracker::update_father(int t, std::span<const int> candidates,
                                 std::span<const double> beta_plots, double beta_miss,
                                 TrackFrame& frame) {
  PointTrack& father = tracks_[t];
  const bool firm = is_reported_as_firm(father.life.status);
  // A firm father its life deletes is suspended, not deleted: no "deleted" event.
  update_track(t, candidates, beta_plots, beta_miss, frame, /*reports_deletion=*/!firm);
  if (!firm || father.life.status != TrackStatus::kDeleted) return;
  // Deleted by its life: it lives on, coasting, while branches may replace it.
  father.life.status = TrackStatus::kCoasting;
  if (!father.doomed()) {
    father.state = FatherState::kSuspended;
    add_event(events_, TrackEventType::kSuspended, father.id,
              "deleted by its track life; kept unreported while a branch may replace it");
  }
}

void PointTracker::confirm_branch_pairs(ScanReport& report, TrackFrame& frame) {
  const std::vector<BranchPair> confirmed = confirm_pairs(
      branch_pairs_, static_cast<int>(tracks_.size()), static_cast<int>(pre_->plots().size()));
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
        const std::int64_t son = tracks_[p.track].id;
        if (of_undecided_father(son)) tree_.mark_non_manoeuvre_update(son);
      }
      sons_marked = true;
    }
    if (pair.kind > PairKind::kSonNonManoeuvre && !sons_promoted) {
      promote_confirmed_sons(report);
      sons_promoted = true;
    }
    // An earlier decision of this batch may have removed the track.
    if (tracks_[pair.track].life.status == TrackStatus::kDeleted) continue;
    switch (pair.kind) {
      case PairKind::kFatherNonManoeuvre: {  // §2.3 (1), rule 5
        PointTrack& father = tracks_[pair.track];
        father.last_plot = pre_->plots()[pair.plot];
        father.last_plot_batch = batches_;
        used_by_branch_[pair.plot] = 1;
        changes_.clear();
        tree_.release_branches(father.id, changes_);
        apply(changes_,
              name(BranchType::kFather, father.id) + " took plot " +
                  std::to_string(pre_->plots()[pair.plot].plot_id) + " (rule 5)",
              report);
        note_doubtful_update(pair);
        break;
      }
      case PairKind::kSonNonManoeuvre:    // §2.3 (2), rules 8 and 10
      case PairKind::kGrandsonManoeuvre:  // §2.3 (3), rules 9 and 10
        update_branch(pair, report, frame);
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

void PointTracker::note_doubtful_update(const BranchPair& pair) {
  if (profile_.point.branching.coast_sons == 0 || pair.candidate < 0) return;
  const PointTrack& father = tracks_[pair.track];
  if (father.doomed() || !is_reported_as_firm(father.life.status)) return;
  // The plot's density as clutter against its density as the father's target (detected):
  // about 0.2 for a target's plot inside paper003_exp2's clutter area, 1e-4 outside it.
  const double clutter = pre_->density(pre_->plots()[pair.plot], pair.plot);
  const double target = profile_.association.detection_probability *
                        candidates_[static_cast<std::size_t>(pair.candidate)].likelihood;
  const double doubt = clutter / (clutter + target);
  if (!(doubt >= profile_.point.branching.coast_son_doubt)) return;
  doubtful_.push_back({pair.track, doubt, pre_->plots()[pair.plot].plot_id});
}

void PointTracker::start_coast_sons(ScanReport& report, TrackFrame& frame) {
  const int most = profile_.point.branching.coast_sons;
  for (const DoubtfulUpdate& d : doubtful_) {
    const PointTrack& father = tracks_[d.track];
    const BeforeUpdate& before = before_update_[static_cast<std::size_t>(d.track)];
    if (father.branch != BranchType::kFather || father.replaced || father.doomed() ||
        father.life.status == TrackStatus::kDeleted || !before.motion) {
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
        const int i = slot(id);
        return i >= 0 && touched_[static_cast<std::size_t>(i)] == 0;
      });
      if (oldest == sons.end()) continue;
      changes_.clear();
      tree_.remove(*oldest, changes_);
      apply(changes_, "the oldest of coast_sons " + std::to_string(most), report);
    }
    if (!make_room(father_id, father_id, score, d.plot_id, report)) continue;
    PointTrack son;
    son.id = next_provisional_++;
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
    add_event(events_, TrackEventType::kBranchCreated, father_id,
              name(BranchType::kSon, son.id) + " of " + name(BranchType::kFather, father_id) +
                  ": its last motion before plot " + plot + " (coast son, doubt " +
                  std::to_string(d.doubt).substr(0, 4) + ")");
    ++report.point.branches_created;
    slots_[son.id] = static_cast<int>(tracks_.size());
    tracks_.push_back(std::move(son));
    touched_.push_back(1);
  }
  doubtful_.clear();
}

double PointTracker::miss_score(int t) const {
  return log_of(1.0 - support_detection_probability(tracks_[t].life,
                                                    profile_.association.detection_probability,
                                                    detectability_at(t)));
}

bool PointTracker::age_coast_son(int t, double time) {
  PointTrack& son = tracks_[t];
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

bool PointTracker::of_undecided_father(std::int64_t son) const {
  const int f = slot(tree_.father_of(son));
  return f >= 0 && tracks_[f].undecided();
}

double PointTracker::family_support(std::int64_t father) const {
  // The father and its paper 003 branches: a turn its sons follow is the target too.
  double best = tracks_[slot(father)].life.support;
  const BranchNode* node = tree_.find(father);
  if (node == nullptr) return best;
  for (const std::int64_t son : node->children) {
    const BranchNode* s = tree_.find(son);
    if (s == nullptr || s->coast) continue;
    for (const std::int64_t id : s->children) {
      const int g = slot(id);
      if (g >= 0) best = std::max(best, tracks_[g].life.support);
    }
    const int i = slot(son);
    if (i >= 0) best = std::max(best, tracks_[i].life.support);
  }
  return best;
}

void PointTracker::promote_confirmed_sons(ScanReport& report) {
  // The sons of an undecided father confirmed in the same scan: the one whose plot fits its
  // prediction best takes the number; the others, updated too, become independent
  // (§2.3 (2)). In pair order (JPDA weights, about 1 for a son alone in its cluster) the
  // first would win by chance.
  std::stable_sort(
      confirmed_sons_.begin(), confirmed_sons_.end(),
      [](const ConfirmedSon& a, const ConfirmedSon& b) { return a.likelihood > b.likelihood; });
  for (const ConfirmedSon& son : confirmed_sons_) {
    const PointTrack& track = tracks_[son.track];
    if (track.life.status == TrackStatus::kDeleted || track.branch != BranchType::kSon) continue;
    changes_.clear();
    tree_.promote(track.id, changes_);
    apply(changes_, "confirmed with plot " + std::to_string(son.plot_id) + " (rule 10)", report);
  }
  confirmed_sons_.clear();
}

}  // namespace skytrack
