// The branch layer's changes to the branch tree (paper 003 §1 rules 5-10): branches updated,
// created under the caps, aged and retired, and the doomed fathers deleted.
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

void BranchLayer::update_branch(const BranchPair& pair, ScanReport& report) {
  const int t = pair.track;
  const bool non_manoeuvre = pair.kind == PairKind::kSonNonManoeuvre;
  SoftUpdate& u = branch_updates_[static_cast<std::size_t>(t)];
  PointTrack& branch = store()[t];
  const std::int64_t number = branch.id;
  const BranchType type = branch.branch;
  std::vector<Candidate>& pool = non_manoeuvre ? gater().candidates() : manoeuvre_candidates_;
  double pair_likelihood = 0.0;  // of its own plot: which son wins (promote_confirmed_sons)
  for (const int c : u.candidates) {
    if (pool[c].plot == pair.plot && pool[c].hypothesis.usable) {
      pair_likelihood = pool[c].hypothesis.likelihood;
    }
  }
  const PlotRatios ratios =
      look_->updater.update(*look_, t, pool, u.candidates, u.beta, u.miss, number);
  // It found its target: its last motion (coast_on_last_motion), a father's once it replaces
  // its father.
  updated(branch, valid_association(u.beta, u.miss));
  const double likelihood_ratio = ratios.sum;
  add_support(branch.life, ratios, t);
  branch.quality = 0.8 * branch.quality + 0.2 * (1.0 - u.miss);
  branch.last_plot = pre().plots()[pair.plot];
  branch.last_plot_batch = look_->batch;
  branch.score += log_of(pair.probability);
  branch.pair_probability = pair.probability;
  touched_[static_cast<std::size_t>(t)] = 1;
  look_->used_by_branch[pair.plot] = 1;
  const std::string plot = std::to_string(pre().plots()[pair.plot].plot_id);
  if (branch.branch == BranchType::kFather) {  // made independent earlier in this batch
    update_existence(branch.life, likelihood_ratio, profile_.association.detection_probability,
                     profile_.association.gate_probability, profile_.point.track_life);
    const LifeChange change =
        advance_life(branch.life, true, mode_spread(branch.estimate, kLifeSpreadDims),
                     profile_.point.track_life);
    if (change.confirmed) add_event(events(), TrackEventType::kConfirmed, number, "");
    return;
  }
  if (non_manoeuvre) {  // rule 8
    tree_.mark_non_manoeuvre_update(number);
    changes_.clear();
    tree_.prune_children(number, changes_);
    apply(changes_, name(type, number) + " took plot " + plot + " (rule 8)", report);
  }
  // Rule 10: every branch update is followed by the confirmation test. A branch that took
  // its pair is not deleted for its spread: the PDA posterior of a wide prior (a son started
  // after misses) stays wide for a scan; misses end it (age_branches).
  if (weighs_existence(branch)) {
    update_existence(branch.life, likelihood_ratio, profile_.association.detection_probability,
                     profile_.association.gate_probability, profile_.point.track_life);
  }
  const bool confirmed = advance_life(branch.life, true, 0.0, life_of(branch)).confirmed;
  if (branch.coast_son()) {
    // Two hypotheses of one target since the split, the father's plots or misses and now
    // this plot: the better supported one stands, as in track-oriented MHT. Inherited in
    // this look's promotion, it waits for the next look: one decision per look.
    const std::int64_t father = tree_.father_of(number);
    const int f = store().slot(father);
    const bool stands = f >= 0 && branch.life.support > family_support(father);
    if (!stands ||
        std::find(replaced_now_.begin(), replaced_now_.end(), father) != replaced_now_.end()) {
      return;
    }
    // Firm as the father was: its support says it is the target.
    branch.life.status = TrackStatus::kConfirmed;
    branch.life.existence = std::max(branch.life.existence, store()[f].life.existence);
    changes_.clear();
    tree_.promote(number, changes_);
    apply(changes_, "confirmed with plot " + plot + " (rule 10)", report);
    return;
  }
  if (confirmed && non_manoeuvre && of_undecided_father(number)) {  // see promote_confirmed_sons
    confirmed_sons_.push_back({t, pair_likelihood, pre().plots()[pair.plot].plot_id});
    return;
  }
  // Confirmed, it replaces the father once its support passes the father's: a son from
  // clutter plots, confirmed while its father's target is missed, waits for the next look.
  const int f = store().slot(tree_.father_of(number));
  if (is_reported_as_firm(branch.life.status) && f >= 0 &&
      branch.life.support > store()[f].life.support) {
    changes_.clear();
    tree_.promote(number, changes_);
    apply(changes_, "confirmed with plot " + plot + " (rule 10)", report);
  }
}

void BranchLayer::create_branch(const BranchPair& pair, ScanReport& report, TrackFrame& frame) {
  const config::BranchingSpec& spec = profile_.point.branching;
  const PointTrack& parent = store()[pair.track];
  const bool of_father = parent.branch == BranchType::kFather;
  if (of_father && !may_start_sons(parent)) return;
  if (!tree_.can_branch(parent.id, spec.max_children)) return;  // rules 6-7: room left
  // A son starts at its father's latest update (rule 6), a grandson at its son's first plot
  // (rule 7): plot-to-plot manoeuvre starts (§3.3).
  const std::optional<PlotMeasurement>& start = of_father ? parent.last_plot : parent.first_plot;
  const PlotMeasurement& plot = pre().plots()[pair.plot];
  if (!start || !(plot.time > start->time)) return;
  const std::int64_t parent_id = parent.id;
  const BranchType parent_type = parent.branch;
  const double parent_quality = parent.quality;
  const double parent_support = parent.life.support;
  const double score = parent.score + log_of(pair.probability);
  const std::int64_t father = tree_.father_of(parent_id);
  if (!make_room(father, parent_id, score, plot.plot_id, report)) return;

  Initiation initiation;
  initiation.plots = {*start, plot};
  initiation.scans = tracking_detail::looks_between(start->sweep, plot.sweep) + 1;
  PointTrack branch;
  branch.id = store().provisional();
  branch.branch = of_father ? BranchType::kSon : BranchType::kGrandson;
  branch.life = initiated_life(2, initiation.scans);
  // Its existence starts at its pair's association probability (the chance that the plot
  // is its parent's target; at least a new track's): its later plots decide.
  if (weighs_existence(branch)) {
    branch.life.existence =
        std::clamp(pair.probability, profile_.point.track_life.initial_existence,
                   profile_.point.track_life.confirm_existence);
  }
  branch.estimate =
      of_father ? son_start(pair.track, plot) : *start_estimate(*look_, initiation, branch.life);
  branch.quality = parent_quality;
  branch.first_plot = *start;
  branch.last_plot = plot;
  branch.last_plot_batch = look_->batch;
  branch.score = score;
  branch.pair_probability = pair.probability;
  // A manoeuvre hypothesis: its parent's support and the prior of a manoeuvre begun since.
  branch.life.support = parent_support + std::log(kManoeuvreOnset);
  tree_.add_branch(branch.id, parent_id);
  look_->used_by_branch[pair.plot] = 1;
  add_association(frame, branch.id, plot.plot_id, plot.scan, pair.probability);
  add_event(events(), TrackEventType::kBranchCreated, father,
            name(branch.branch, branch.id) + " of " + name(parent_type, parent_id) + " from plot " +
                std::to_string(plot.plot_id));
  ++report.point.branches_created;
  store().add(std::move(branch));
  touched_.push_back(1);
}

ImmEstimate BranchLayer::son_start(int father, const PlotMeasurement& plot) const {
  // The father's state from its latest update, predicted to the plot by the manoeuvre
  // models (their wider process noise lets the plot turn the velocity), then updated with
  // the plot: a start at the father's latest update that keeps what it knew of the speed.
  const ImmEstimate m =
      manoeuvre_prediction(previous_[static_cast<std::size_t>(father)], plot.time);
  const Gaussian g = manoeuvre_.combine(m);
  const auto& probabilities = profile_.initial_mode_probabilities;
  const ImmEstimate start =
      filter().initial(g,
                       Eigen::Map<const Eigen::VectorXd>(
                           probabilities.data(), static_cast<Eigen::Index>(probabilities.size())),
                       m.time);
  const PlotHypothesis h = filter().hypothesise(start, plot);
  if (!h.usable) return start;
  const double one = 1.0;
  return look_->counted(filter().update(
      start, std::span(&h, 1), std::span(&one, 1), 0.0, profile_.association.detection_probability,
      profile_.association.gate_probability, pre().density(plot, -1)));
}

bool BranchLayer::make_room(std::int64_t father, std::int64_t parent, double score,
                            std::int64_t plot_id, ScanReport& report) {
  const config::BranchingSpec& spec = profile_.point.branching;
  for (const bool per_father : {true, false}) {
    const int count = per_father ? tree_.branch_count(father) : tree_.total_branches();
    const int cap = per_father ? spec.max_branches_per_father : spec.max_total_branches;
    if (count < cap) continue;
    const std::string where = per_father ? "the cap of " + std::to_string(cap) + " per father"
                                         : "the cap of " + std::to_string(cap) + " in total";
    // The least likely branch (lowest score; the newest on a tie), never the new one's parent.
    int least = -1;
    for (std::size_t i = 0; i < store().size(); ++i) {
      const PointTrack& b = store()[i];
      if (b.branch == BranchType::kFather || b.life.status == TrackStatus::kDeleted ||
          b.id == parent || (per_father && tree_.father_of(b.id) != father)) {
        continue;
      }
      if (least < 0 || b.score < store()[least].score ||
          (b.score == store()[least].score && b.id > store()[least].id)) {
        least = static_cast<int>(i);
      }
    }
    if (least < 0 || store()[least].score >= score) {
      add_event(
          events(), TrackEventType::kBranchPruned, father,
          "branch from plot " + std::to_string(plot_id) + " not created: least likely at " + where);
      ++report.point.branches_pruned;
      return false;
    }
    changes_.clear();
    tree_.remove(store()[least].id, changes_);
    apply(changes_, "least likely at " + where, report);
  }
  return true;
}

void BranchLayer::age_branches(ScanReport& report, TrackFrame& frame) {
  const int window = profile_.point.branching.coast_son_looks;
  for (std::size_t i = 0; i < store().size(); ++i) {
    PointTrack& branch = store()[i];
    if (branch.branch == BranchType::kFather || branch.life.status == TrackStatus::kDeleted ||
        !gater().covered(i)) {
      continue;
    }
    const bool touched = touched_[i] != 0;
    const double miss = miss_score(static_cast<int>(i));
    if (branch.coast_son()) {
      std::string reason;
      if (!touched) {
        branch.score += miss;
        if (!age_coast_son(static_cast<int>(i), frame.time)) {
          reason = "no plot in delete_confirmed_misses (" +
                   std::to_string(profile_.point.track_life.delete_confirmed_misses) + ") looks";
        }
      }
      // Undecided at the end of its window: the father's plots since the split stand.
      if (reason.empty() && window > 0 && branch.life.scans > window) {
        reason = "not confirmed within coast_son_looks (" + std::to_string(window) + ")";
      }
      if (!reason.empty()) {
        changes_.clear();
        tree_.remove(branch.id, changes_);
        apply(changes_, reason, report);
      }
      continue;
    }
    if (touched) continue;
    branch.score += miss;
    branch.estimate = filter().predict(branch.estimate, std::max(frame.time, branch.estimate.time));
    const double spread = mode_spread(branch.estimate, kLifeSpreadDims);
    if (weighs_existence(branch)) {
      update_existence(branch.life, 0.0, profile_.association.detection_probability,
                       profile_.association.gate_probability, profile_.point.track_life);
    }
    update_detectability(branch.life, 0.0, profile_.association.detection_probability,
                         profile_.association.gate_probability,
                         detectability_at(profile_, gater().in_clutter_area(i)));
    if (advance_life(branch.life, false, spread, life_of(branch)).deleted) {
      changes_.clear();
      tree_.remove(branch.id, changes_);
      apply(changes_, "no plot", report);
    }
  }
}

void BranchLayer::after_initiation() {
  // A held chain confirmed as it started (point_tracker_initiation.cpp) may continue a lost
  // father, as a track confirmed by the look's association does.
  if (!confirmed_now_.empty()) continue_lost_fathers(look_->report);
  // A doomed father that may start no more sons goes with its last branch.
  for (PointTrack& father : store().all()) {
    if (father.branch != BranchType::kFather || father.replaced || !father.doomed() ||
        father.life.status == TrackStatus::kDeleted || tree_.branch_count(father.id) > 0 ||
        may_start_sons(father) || father.life.consecutive_misses < recovery_misses()) {
      continue;
    }
    father.life.status = TrackStatus::kDeleted;
    add_event(events(), TrackEventType::kDeleted, father.id, "no branch left to replace it");
    changes_.clear();
    tree_.remove(father.id, changes_);
  }
}

bool BranchLayer::room_for_chain(std::int64_t father, double existence, std::int64_t plot_id,
                                 ScanReport& report) {
  const int max_children = profile_.point.branching.max_children;
  if (tree_.can_branch(father, max_children)) return true;
  // No room: the chain displaces the father's least likely chain son (lowest existence),
  // if less likely than itself. Sons from manoeuvre pairs stay.
  const BranchNode* node = tree_.find(father);
  int least = -1;
  for (const std::int64_t son : node->children) {
    const int i = store().slot(son);
    if (i < 0 || !store()[i].from_chain() || is_reported_as_firm(store()[i].life.status)) continue;
    if (least < 0 || store()[i].life.existence < store()[least].life.existence) least = i;
  }
  if (least < 0 || store()[least].life.existence >= existence) return false;
  changes_.clear();
  tree_.remove(store()[least].id, changes_);
  apply(changes_,
        "a likelier plot chain (plot " + std::to_string(plot_id) + ") at max_children " +
            std::to_string(max_children),
        report);
  return true;
}

}  // namespace skytrack
