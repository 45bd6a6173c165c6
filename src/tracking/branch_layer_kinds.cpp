// Branch ("filiation") tracking on the IMM-JPDA point tracker, paper 003 §1 rules (5)-(10),
// §2.1-2.3 and §3.3 (Ma, Xu, Zhang 2020).
//
// Per batch, after the non-manoeuvre gates of fathers and sons (gater.cpp, with the hooks of
// branch_layer.cpp), and with manoeuvre gates (the manoeuvre models, started from the
// track's estimate before the batch) made only for the tracks that can still use a
// manoeuvre pair once the non-manoeuvre kinds are confirmed:
//   §2.1  JPDA marginals per pair kind (branch type x gate), each over that kind's pairs. The
//         fathers' non-manoeuvre kind is exactly the plain tracker's IMM-JPDA: it updates the
//         fathers, which are reported. A pair is a valid association when its probability
//         exceeds the track's miss probability in the same kind.
//   §2.2  ordered confirmation of the valid pairs (branch_association.hpp).
//   §2.3  in that order: (1) father non-manoeuvre pair: the father's branches are released
//         (rule 5); (2) son non-manoeuvre pair: the son is updated with its IMM-JPDA weights,
//         its grandsons go (rule 8), and once confirmed it replaces the father (rule 10);
//         (3) grandson manoeuvre pair: likewise (rules 9, 10); (4) son manoeuvre pair: a
//         grandson from the son's first plot and this plot (rule 7); (5) father manoeuvre
//         pair: a son from the father's latest update plot and this plot (rule 6). Both
//         are plot-to-plot manoeuvre starts (§3.3), as is a plot chain of the initiator that
//         ends in a suspended father's manoeuvre gate: it becomes that father's son.
// Branches without a confirmed pair coast and miss; their track life deletes them. Only
// fathers branch once confirmed ("stably tracked", §0); a tentative father is plain IMM-JPDA.
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

const config::TrackLifeSpec& BranchLayer::life_of(const PointTrack& branch) const {
  return branch.from_chain() ? profile_.point.track_life : branch_life_;
}

bool BranchLayer::weighs_existence(const PointTrack& branch) const {
  return branch.from_chain() || branch.coast_son() ||
         branch_life_.confirmation == config::ConfirmationMethod::kExistence;
}

int BranchLayer::recovery_misses() const {
  // A suspended father waits, unreported, for initiation.n more scans after it may no longer
  // branch: the time a plot chain of its target needs to form and confirm (§3.3).
  return profile_.point.track_life.delete_confirmed_misses + profile_.point.initiation.n;
}

bool BranchLayer::may_start_sons(const PointTrack& father) const {
  return is_reported_as_firm(father.life.status) &&
         (!father.doomed() ||
          father.life.consecutive_misses < profile_.point.track_life.delete_confirmed_misses);
}

bool BranchLayer::suspends_before_gating(const PointTrack& track, const Gaussian& mid,
                                         double time) const {
  if (track.branch != BranchType::kFather || track.doomed() ||
      !is_reported_as_firm(track.life.status) || tree_.branch_count(track.id) == 0) {
    return false;
  }
  const std::optional<ImmEstimate> last = last_motion(track, time);
  return position_spread(last ? last->modes.front() : mid, kLifeSpreadDims) >
         kSuspendBeforeGating * profile_.point.track_life.delete_position_sigma;
}

ImmEstimate BranchLayer::manoeuvre_prediction(const ImmEstimate& estimate, double time) const {
  const ImmEstimate start =
      manoeuvre_.initial(filter().combine(estimate), manoeuvre_start_, estimate.time);
  return manoeuvre_.predict(start, std::max(time, estimate.time));
}

void BranchLayer::associate(const PlotScan& scan, ScanReport& report, TrackFrame& frame) {
  look_->associator.estimate_clutter_density(pre(), store().all(), gater().candidates());
  branch_updates_.assign(store().size(), SoftUpdate{});
  branch_pairs_.clear();
  touched_.assign(store().size(), 0);
  for (const int t : suspended_at_gate_) {
    add_event(events(), TrackEventType::kSuspended, store()[t].id,
              "predicted position spread above delete_position_sigma; kept unreported while a "
              "branch may replace it");
  }
  // §2.1 (1), (3): the non-manoeuvre kinds; the fathers' kind also updates the fathers.
  claimed_by_.assign(pre().plots().size(), -1);
  pending_splits_.clear();
  doubtful_.clear();
  replaced_now_.clear();
  if (profile_.point.branching.coast_sons > 0) {
    for (BeforeUpdate& before : before_update_) before.valid = false;
    before_update_.resize(store().size());
  }
  solve_kind(PairKind::kFatherNonManoeuvre);
  split_undecided_fathers();
  solve_kind(PairKind::kSonNonManoeuvre);
  // Their confirmation comes first in §2.2 and does not depend on the later kinds, so it
  // tells which tracks can still use a manoeuvre pair: fathers and sons without a confirmed
  // non-manoeuvre pair (rules 6-7) and every grandson. Only those get a manoeuvre gate.
  const std::size_t n = store().size();
  std::vector<std::uint8_t> taken(n, 0);
  for (const BranchPair& pair :
       confirm_pairs(branch_pairs_, static_cast<int>(n), static_cast<int>(pre().plots().size()))) {
    taken[static_cast<std::size_t>(pair.track)] = 1;
  }
  for (std::size_t t = 0; t < n; ++t) {
    const PointTrack& track = store()[t];
    if (taken[t] != 0 || track.life.status == TrackStatus::kDeleted || has_previous_[t] == 0) {
      continue;
    }
    if (track.branch == BranchType::kFather && !may_start_sons(track)) continue;
    if (track.coast_son()) continue;  // the father's last motion only: it does not branch
    gate_manoeuvre(scan, static_cast<int>(t), track.branch == BranchType::kGrandson);
  }
  // §2.1 (2), (3): the manoeuvre kinds.
  solve_kind(PairKind::kGrandsonManoeuvre);
  solve_kind(PairKind::kSonManoeuvre);
  solve_kind(PairKind::kFatherManoeuvre);
  confirm_branch_pairs(report, frame);
  age_branches(report, frame);
}

void BranchLayer::solve_kind(PairKind kind) {
  const bool manoeuvre = is_manoeuvre(kind);
  std::vector<Candidate>& pool = manoeuvre ? manoeuvre_candidates_ : gater().candidates();
  const BranchType type = type_of(kind);
  kind_list_.clear();
  for (std::size_t k = 0; k < pool.size(); ++k) {
    if (store()[pool[k].track].branch == type) kind_list_.push_back(static_cast<int>(k));
  }
  // The fathers' kind runs even without pairs: it coasts and ages the fathers.
  if (kind_list_.empty() && kind != PairKind::kFatherNonManoeuvre) return;
  const double gate_probability = manoeuvre ? profile_.point.branching.manoeuvre_gate_probability
                                            : profile_.association.gate_probability;
  look_->associator.solve(
      look_->association(), pool, kind_list_, gate_probability,
      [&](int t, std::span<const int> mine, std::span<const double> beta, double miss) {
        // The non-manoeuvre gates decide which plots the tracks explain (initiation).
        if (!manoeuvre) note_explained(*look_, pool, mine, beta);
        if (store()[t].branch != type) return;
        const bool was_doomed = store()[t].doomed();
        // Two plots each likely enough: one frame cannot decide (§0), the sons will.
        const bool split = kind == PairKind::kFatherNonManoeuvre && !was_doomed &&
                           may_start_sons(store()[t]) &&
                           ambiguous(beta, miss, profile_.point.branching.ambiguity_beta);
        std::optional<ImmEstimate> last_detected;
        if (split && holds_last_motion()) last_detected = store()[t].last_detected;
        if (kind == PairKind::kFatherNonManoeuvre && profile_.point.branching.coast_sons > 0) {
          BeforeUpdate& before = before_update_[static_cast<std::size_t>(t)];
          before.motion = store()[t].last_detected;  // assigned in place: storage reused
          before.support = store()[t].life.support;
          before.detectable = store()[t].life.detectable;
          before.valid = true;
        }
        if (kind == PairKind::kFatherNonManoeuvre) update_father(t, mine, beta, miss);
        // A doomed father takes no non-manoeuvre pair but may start sons, so that a
        // branch can still keep its number.
        const PointTrack& track = store()[t];
        if (track.life.status == TrackStatus::kDeleted) return;
        // Only an ambiguity test needs to know whose likeliest plot each plot is.
        if (kind == PairKind::kFatherNonManoeuvre && !track.doomed() &&
            profile_.point.branching.ambiguity_beta < 1.0) {
          claim_best_plot(t, pool, mine, beta, miss);
          // Decided once every father's likeliest plot is known (split_undecided_fathers).
          if (split && may_start_sons(track)) {
            PendingSplit& p = pending_splits_.emplace_back();
            p.track = t;
            p.miss = miss;
            p.last_detected = std::move(last_detected);
            for (std::size_t k = 0; k < mine.size(); ++k) {
              p.plots.push_back(pool[mine[k]].plot);
              p.beta.push_back(beta[k]);
            }
          }
        }
        if (kind == PairKind::kFatherNonManoeuvre && !was_doomed && track.doomed() &&
            may_start_sons(track)) {
          // Suspended (or undecided) by this very update: the plots its IMM-JPDA found
          // likely (its turn modes included) start its sons, as its manoeuvre pairs do.
          for (std::size_t k = 0; k < mine.size(); ++k) {
            if (beta[k] <= miss) continue;
            branch_pairs_.push_back(
                {PairKind::kFatherManoeuvre, t, pool[mine[k]].plot, beta[k], -1});
          }
          return;
        }
        if (track.doomed() && (!manoeuvre || !may_start_sons(track))) return;
        if (kind != PairKind::kFatherNonManoeuvre && updates_track(kind)) {
          SoftUpdate& u = branch_updates_[static_cast<std::size_t>(t)];
          u.candidates.assign(mine.begin(), mine.end());
          u.beta.assign(beta.begin(), beta.end());
          u.miss = miss;
        }
        for (std::size_t k = 0; k < mine.size(); ++k) {
          if (beta[k] <= miss) continue;  // not a valid association
          branch_pairs_.push_back({kind, t, pool[mine[k]].plot, beta[k], mine[k]});
        }
      },
      manoeuvre);
}

}  // namespace skytrack
