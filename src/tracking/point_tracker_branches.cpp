// Branch ("filiation") tracking on the IMM-JPDA point tracker, paper 003 §1 rules (5)-(10),
// §2.1-2.3 and §3.3 (Ma, Xu, Zhang 2020).
//
// Per batch, after the non-manoeuvre gates of fathers and sons (point_tracker.cpp), and with
// manoeuvre gates (the manoeuvre models, started from the track's estimate before the batch)
// made only for the tracks that can still use a manoeuvre pair once the non-manoeuvre kinds
// are confirmed:
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

#include "point_tracker_support.hpp"
#include "skytrack/tracking/point_tracker.hpp"

namespace skytrack {
namespace {

using tracking_detail::add_association;
using tracking_detail::add_event;
using tracking_detail::kLifeSpreadDims;
using tracking_detail::mode_spread;
using tracking_detail::position_of;
using tracking_detail::position_spread;
using tracking_detail::supersede;

constexpr PairKind kConfirmationOrder[kPairKinds] = {
    PairKind::kFatherNonManoeuvre, PairKind::kSonNonManoeuvre, PairKind::kGrandsonManoeuvre,
    PairKind::kSonManoeuvre, PairKind::kFatherManoeuvre};

bool is_manoeuvre(PairKind kind) {
  return kind == PairKind::kGrandsonManoeuvre || kind == PairKind::kSonManoeuvre ||
         kind == PairKind::kFatherManoeuvre;
}

BranchType type_of(PairKind kind) {
  switch (kind) {
    case PairKind::kFatherNonManoeuvre:
    case PairKind::kFatherManoeuvre:
      return BranchType::kFather;
    case PairKind::kSonNonManoeuvre:
    case PairKind::kSonManoeuvre:
      return BranchType::kSon;
    case PairKind::kGrandsonManoeuvre:
      return BranchType::kGrandson;
  }
  return BranchType::kFather;
}

std::string name(BranchType type, std::int64_t number) {
  std::string out(type == BranchType::kFather ? std::string_view("track") : to_string(type));
  out.append(" ").append(std::to_string(number));
  return out;
}

// A father with branches is suspended before gating once its prediction is this many times
// wider than delete_position_sigma. At 1.0 (the limit its own life applies to the posterior)
// it also suspended fathers whose update would suspend them anyway, and those now start
// their sons from the plots their update weighed (solve_kind); exp. 1, seeds 1-100: 0.6: 14
// number changes, 1.0: 12, 1.2 to 2.5: 10, never: 10 but exp. 2 and 3 worse.
constexpr double kSuspendBeforeGating = 1.2;

// The prior of a manoeuvre begun between two looks, in a branch's support: one look in ten
// (exp. 2 measured the same with 0.01, 51 %, and a little worse with 0.23, 50 %).
constexpr double kManoeuvreOnset = 0.1;

// A probability's log, floored so that a zero weight still orders branches.
double log_of(double p) {
  return std::log(std::max(p, 1e-300));
}

// True when the second likeliest plot above the miss weight has at least `tau`.
bool ambiguous(std::span<const double> beta, double miss, double tau) {
  double first = 0.0, second = 0.0;
  for (const double b : beta) {
    if (b <= miss) continue;
    if (b > first) {
      second = first;
      first = b;
    } else if (b > second) {
      second = b;
    }
  }
  return second >= tau;
}

}  // namespace

const config::TrackLifeSpec& PointTracker::life_of(const PointTrack& branch) const {
  return branch.from_chain ? profile_.track_life : branch_life_;
}

bool PointTracker::weighs_existence(const PointTrack& branch) const {
  return branch.from_chain || branch.coast_son ||
         branch_life_.confirmation == config::ConfirmationMethod::kExistence;
}

int PointTracker::recovery_misses() const {
  // A suspended father waits, unreported, for initiation.n more scans after it may no longer
  // branch: the time a plot chain of its target needs to form and confirm (§3.3).
  return profile_.track_life.delete_confirmed_misses + profile_.initiation.n;
}

bool PointTracker::may_start_sons(const PointTrack& father) const {
  return is_reported_as_firm(father.life.status) &&
         (!father.doomed ||
          father.life.consecutive_misses < profile_.track_life.delete_confirmed_misses);
}

bool PointTracker::suspends_before_gating(const PointTrack& track, const Gaussian& mid,
                                          double time) const {
  if (!branching() || track.branch != BranchType::kFather || track.doomed ||
      !is_reported_as_firm(track.life.status) || tree_.branch_count(track.id) == 0) {
    return false;
  }
  const std::optional<ImmEstimate> last = last_motion(track, time);
  return position_spread(last ? last->modes.front() : mid, kLifeSpreadDims) >
         kSuspendBeforeGating * profile_.track_life.delete_position_sigma;
}

ImmEstimate PointTracker::manoeuvre_prediction(const ImmEstimate& estimate, double time) const {
  const ImmEstimate start =
      manoeuvre_->initial(filter_.combine(estimate), manoeuvre_start_, estimate.time);
  return manoeuvre_->predict(start, std::max(time, estimate.time));
}

int PointTracker::slot(std::int64_t number) const {
  const auto it = slots_.find(number);
  return it == slots_.end() ? -1 : it->second;
}

void PointTracker::associate_branches(const PlotScan& scan, ScanReport& report, TrackFrame& frame) {
  estimate_clutter_density();
  branch_updates_.assign(tracks_.size(), SoftUpdate{});
  branch_pairs_.clear();
  touched_.assign(tracks_.size(), 0);
  for (const int t : suspended_at_gate_) {
    add_event(events_, TrackEventType::kSuspended, tracks_[t].id,
              "predicted position spread above delete_position_sigma; kept unreported while a "
              "branch may replace it");
  }
  // §2.1 (1), (3): the non-manoeuvre kinds; the fathers' kind also updates the fathers.
  claimed_by_.assign(plots_.size(), -1);
  pending_splits_.clear();
  doubtful_.clear();
  replaced_now_.clear();
  if (profile_.branching.coast_sons > 0) before_update_.assign(tracks_.size(), BeforeUpdate{});
  solve_kind(PairKind::kFatherNonManoeuvre, report, frame);
  split_undecided_fathers();
  solve_kind(PairKind::kSonNonManoeuvre, report, frame);
  // Their confirmation comes first in §2.2 and does not depend on the later kinds, so it
  // tells which tracks can still use a manoeuvre pair: fathers and sons without a confirmed
  // non-manoeuvre pair (rules 6-7) and every grandson. Only those get a manoeuvre gate.
  const std::size_t n = tracks_.size();
  std::vector<std::uint8_t> taken(n, 0);
  for (const BranchPair& pair :
       confirm_pairs(branch_pairs_, static_cast<int>(n), static_cast<int>(plots_.size()))) {
    taken[static_cast<std::size_t>(pair.track)] = 1;
  }
  for (std::size_t t = 0; t < n; ++t) {
    const PointTrack& track = tracks_[t];
    if (taken[t] != 0 || track.life.status == TrackStatus::kDeleted || has_previous_[t] == 0) {
      continue;
    }
    if (track.branch == BranchType::kFather && !may_start_sons(track)) continue;
    if (track.coast_son) continue;  // the father's last motion only: it does not branch
    gate_manoeuvre(scan, static_cast<int>(t), track.branch == BranchType::kGrandson);
  }
  // §2.1 (2), (3): the manoeuvre kinds.
  solve_kind(PairKind::kGrandsonManoeuvre, report, frame);
  solve_kind(PairKind::kSonManoeuvre, report, frame);
  solve_kind(PairKind::kFatherManoeuvre, report, frame);
  confirm_branch_pairs(report, frame);
  age_branches(report, frame);
}

void PointTracker::solve_kind(PairKind kind, ScanReport& report, TrackFrame& frame) {
  const bool manoeuvre = is_manoeuvre(kind);
  std::vector<Candidate>& pool = manoeuvre ? manoeuvre_candidates_ : candidates_;
  const BranchType type = type_of(kind);
  kind_list_.clear();
  for (std::size_t k = 0; k < pool.size(); ++k) {
    if (tracks_[pool[k].track].branch == type) kind_list_.push_back(static_cast<int>(k));
  }
  // The fathers' kind runs even without pairs: it coasts and ages the fathers.
  if (kind_list_.empty() && kind != PairKind::kFatherNonManoeuvre) return;
  const double gate_probability = manoeuvre ? profile_.branching.manoeuvre_gate_probability
                                            : profile_.association.gate_probability;
  solve_clusters(
      pool, kind_list_, gate_probability, report,
      [&](int t, std::span<const int> mine, std::span<const double> beta, double miss) {
        if (tracks_[t].branch != type) return;
        const bool was_doomed = tracks_[t].doomed.has_value();
        // Two plots each likely enough: one frame cannot decide (§0), the sons will.
        const bool split = kind == PairKind::kFatherNonManoeuvre && !was_doomed &&
                           may_start_sons(tracks_[t]) &&
                           ambiguous(beta, miss, profile_.branching.ambiguity_beta);
        std::optional<ImmEstimate> last_detected;
        if (split && holds_last_motion()) last_detected = tracks_[t].last_detected;
        if (kind == PairKind::kFatherNonManoeuvre && profile_.branching.coast_sons > 0) {
          before_update_[static_cast<std::size_t>(t)] = {
              tracks_[t].last_detected, tracks_[t].life.support, tracks_[t].life.detectable};
        }
        if (kind == PairKind::kFatherNonManoeuvre) update_father(t, mine, beta, miss, frame);
        // A doomed father takes no non-manoeuvre pair but may start sons, so that a
        // branch can still keep its number.
        const PointTrack& track = tracks_[t];
        if (track.life.status == TrackStatus::kDeleted) return;
        // Only an ambiguity test needs to know whose likeliest plot each plot is.
        if (kind == PairKind::kFatherNonManoeuvre && !track.doomed &&
            profile_.branching.ambiguity_beta < 1.0) {
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
        if (kind == PairKind::kFatherNonManoeuvre && !was_doomed && track.doomed &&
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
        if (track.doomed && (!manoeuvre || !may_start_sons(track))) return;
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
        std::max(region_accel_, 3.0 * profile_.branching.manoeuvre_accel_sigma));
    bound.radius += seed_speed(t) * half_span_;
    if (!covers_region(scan, bound.centre, bound.radius)) return;
  }
  const auto [centre, radius] = manoeuvre_reach(prior, scan, &mode_reach_);
  if (covered_[t] == 0 && !covers_region(scan, centre, radius)) return;
  index_.within(centre, radius, neighbours_);
  // The models' regions can lie far apart (turns either way): only plots inside one of them
  // are worth an innovation.
  std::erase_if(neighbours_, [&](int j) {
    return std::none_of(mode_reach_.begin(), mode_reach_.end(), [&](const Sphere& m) {
      return (positions_[j] - m.centre).squaredNorm() <= m.radius * m.radius;
    });
  });
  if (neighbours_.empty()) return;
  const double time = std::max(nearest_time(centre), prior.time);
  const ImmEstimate predicted = manoeuvre_prediction(prior, time);
  if (for_update) predicted_[t] = filter_.predict(track.estimate, time);
  for (const int j : neighbours_) {
    const PlotHypothesis m = manoeuvre_->hypothesise(predicted, plots_[j]);
    if (!m.usable || m.min_nis > manoeuvre_threshold_[plots_[j].model.size()]) continue;
    // Only an updating pair needs the plot against the track's own IMM prediction.
    PlotHypothesis hypothesis;
    if (for_update) {
      hypothesis = filter_.hypothesise(predicted_[t], plots_[j]);
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
  const double tau = profile_.branching.ambiguity_beta;
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
    if (likely < 2 || track.doomed || track.life.status == TrackStatus::kDeleted) continue;
    // Undecided: no non-manoeuvre pair; the plots its IMM-JPDA found likely start its sons.
    std::erase_if(branch_pairs_, [&](const BranchPair& b) {
      return b.kind == PairKind::kFatherNonManoeuvre && b.track == p.track;
    });
    track.doomed = batches_;
    track.undecided = true;
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
  if (!father.doomed) {
    father.doomed = batches_;
    add_event(events_, TrackEventType::kSuspended, father.id,
              "deleted by its track life; kept unreported while a branch may replace it");
  }
}

void PointTracker::confirm_branch_pairs(ScanReport& report, TrackFrame& frame) {
  const std::vector<BranchPair> confirmed = confirm_pairs(
      branch_pairs_, static_cast<int>(tracks_.size()), static_cast<int>(plots_.size()));
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
        father.last_plot = plots_[pair.plot];
        father.last_plot_batch = batches_;
        used_by_branch_[pair.plot] = 1;
        changes_.clear();
        tree_.release_branches(father.id, changes_);
        apply(changes_,
              name(BranchType::kFather, father.id) + " took plot " +
                  std::to_string(plots_[pair.plot].plot_id) + " (rule 5)",
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
  if (profile_.branching.coast_sons == 0 || pair.candidate < 0) return;
  const PointTrack& father = tracks_[pair.track];
  if (father.doomed || !is_reported_as_firm(father.life.status)) return;
  // The plot's density as clutter against its density as the father's target (detected):
  // about 0.2 for a target's plot inside paper003_exp2's clutter area, 1e-4 outside it.
  const double clutter = clutter_density(plots_[pair.plot], pair.plot);
  const double target = profile_.association.detection_probability *
                        candidates_[static_cast<std::size_t>(pair.candidate)].likelihood;
  const double doubt = clutter / (clutter + target);
  if (!(doubt >= profile_.branching.coast_son_doubt)) return;
  doubtful_.push_back({pair.track, doubt, plots_[pair.plot].plot_id});
}

void PointTracker::start_coast_sons(ScanReport& report, TrackFrame& frame) {
  const int most = profile_.branching.coast_sons;
  for (const DoubtfulUpdate& d : doubtful_) {
    const PointTrack& father = tracks_[d.track];
    const BeforeUpdate& before = before_update_[static_cast<std::size_t>(d.track)];
    if (father.branch != BranchType::kFather || father.replaced || father.doomed ||
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
    son.coast_son = true;
    son.life.scans = 1;
    son.life.consecutive_misses = 1;  // this look: the target missed, the plot a false alarm
    son.life.existence = std::clamp(d.doubt, profile_.track_life.initial_existence,
                                    profile_.track_life.confirm_existence);
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
    ++report.branches_created;
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
  return son.life.consecutive_misses < profile_.track_life.delete_confirmed_misses &&
         position_spread(son.estimate.modes.front(), kLifeSpreadDims) <=
             profile_.track_life.delete_position_sigma;
}

bool PointTracker::of_undecided_father(std::int64_t son) const {
  const int f = slot(tree_.father_of(son));
  return f >= 0 && tracks_[f].undecided;
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

void PointTracker::update_branch(const BranchPair& pair, ScanReport& report, TrackFrame& frame) {
  const int t = pair.track;
  const bool non_manoeuvre = pair.kind == PairKind::kSonNonManoeuvre;
  SoftUpdate& u = branch_updates_[static_cast<std::size_t>(t)];
  PointTrack& branch = tracks_[t];
  const std::int64_t number = branch.id;
  const BranchType type = branch.branch;
  std::vector<Candidate>& pool = non_manoeuvre ? candidates_ : manoeuvre_candidates_;
  double pair_likelihood = 0.0;  // of its own plot: which son wins (promote_confirmed_sons)
  for (const int c : u.candidates) {
    if (pool[c].plot == pair.plot && pool[c].hypothesis.usable) {
      pair_likelihood = pool[c].hypothesis.likelihood;
    }
  }
  const PlotRatios ratios = soft_update(t, pool, u.candidates, u.beta, u.miss, number, frame);
  const double likelihood_ratio = ratios.sum;
  add_support(branch.life, ratios, t);
  branch.quality = 0.8 * branch.quality + 0.2 * (1.0 - u.miss);
  branch.last_plot = plots_[pair.plot];
  branch.last_plot_batch = batches_;
  branch.score += log_of(pair.probability);
  touched_[static_cast<std::size_t>(t)] = 1;
  used_by_branch_[pair.plot] = 1;
  const std::string plot = std::to_string(plots_[pair.plot].plot_id);
  if (branch.branch == BranchType::kFather) {  // made independent earlier in this batch
    update_existence(branch.life, likelihood_ratio, profile_.association.detection_probability,
                     profile_.association.gate_probability, profile_.track_life);
    const LifeChange change = advance_life(
        branch.life, true, mode_spread(branch.estimate, kLifeSpreadDims), profile_.track_life);
    if (change.confirmed) add_event(events_, TrackEventType::kConfirmed, number, "");
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
                     profile_.association.gate_probability, profile_.track_life);
  }
  const bool confirmed = advance_life(branch.life, true, 0.0, life_of(branch)).confirmed;
  if (branch.coast_son) {
    // Two hypotheses of one target since the split, the father's plots or misses and now
    // this plot: the better supported one stands, as in track-oriented MHT. Inherited in
    // this look's promotion, it waits for the next look: one decision per look.
    const std::int64_t father = tree_.father_of(number);
    const int f = slot(father);
    const bool stands = f >= 0 && branch.life.support > family_support(father);
    if (!stands ||
        std::find(replaced_now_.begin(), replaced_now_.end(), father) != replaced_now_.end()) {
      return;
    }
    // Firm as the father was: its support says it is the target.
    branch.life.status = TrackStatus::kConfirmed;
    branch.life.existence = std::max(branch.life.existence, tracks_[f].life.existence);
    changes_.clear();
    tree_.promote(number, changes_);
    apply(changes_, "confirmed with plot " + plot + " (rule 10)", report);
    return;
  }
  if (confirmed && non_manoeuvre && of_undecided_father(number)) {  // see promote_confirmed_sons
    confirmed_sons_.push_back({t, pair_likelihood, plots_[pair.plot].plot_id});
    return;
  }
  // Confirmed, it replaces the father once its support passes the father's: a son from
  // clutter plots, confirmed while its father's target is missed, waits for the next look.
  const int f = slot(tree_.father_of(number));
  if (is_reported_as_firm(branch.life.status) && f >= 0 &&
      branch.life.support > tracks_[f].life.support) {
    changes_.clear();
    tree_.promote(number, changes_);
    apply(changes_, "confirmed with plot " + plot + " (rule 10)", report);
  }
}

void PointTracker::create_branch(const BranchPair& pair, ScanReport& report, TrackFrame& frame) {
  const config::BranchingSpec& spec = profile_.branching;
  const PointTrack& parent = tracks_[pair.track];
  const bool of_father = parent.branch == BranchType::kFather;
  if (of_father && !may_start_sons(parent)) return;
  if (!tree_.can_branch(parent.id, spec.max_children)) return;  // rules 6-7: room left
  // A son starts at its father's latest update (rule 6), a grandson at its son's first plot
  // (rule 7): plot-to-plot manoeuvre starts (§3.3).
  const std::optional<PlotMeasurement>& start = of_father ? parent.last_plot : parent.first_plot;
  const PlotMeasurement& plot = plots_[pair.plot];
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
  branch.id = next_provisional_++;
  branch.branch = of_father ? BranchType::kSon : BranchType::kGrandson;
  branch.life = initiated_life(2, initiation.scans);
  // Its existence starts at its pair's association probability (the chance that the plot
  // is its parent's target; at least a new track's): its later plots decide.
  if (weighs_existence(branch)) {
    branch.life.existence = std::clamp(pair.probability, profile_.track_life.initial_existence,
                                       profile_.track_life.confirm_existence);
  }
  branch.estimate =
      of_father ? son_start(pair.track, plot) : start_estimate(initiation, branch.life);
  branch.quality = parent_quality;
  branch.first_plot = *start;
  branch.last_plot = plot;
  branch.last_plot_batch = batches_;
  branch.score = score;
  // A manoeuvre hypothesis: its parent's support and the prior of a manoeuvre begun since.
  branch.life.support = parent_support + std::log(kManoeuvreOnset);
  tree_.add_branch(branch.id, parent_id);
  used_by_branch_[pair.plot] = 1;
  add_association(frame, branch.id, plot.plot_id, plot.scan, pair.probability);
  add_event(events_, TrackEventType::kBranchCreated, father,
            name(branch.branch, branch.id) + " of " + name(parent_type, parent_id) + " from plot " +
                std::to_string(plot.plot_id));
  ++report.branches_created;
  slots_[branch.id] = static_cast<int>(tracks_.size());
  tracks_.push_back(std::move(branch));
  touched_.push_back(1);
}

ImmEstimate PointTracker::son_start(int father, const PlotMeasurement& plot) const {
  // The father's state from its latest update, predicted to the plot by the manoeuvre
  // models (their wider process noise lets the plot turn the velocity), then updated with
  // the plot: a start at the father's latest update that keeps what it knew of the speed.
  const ImmEstimate m =
      manoeuvre_prediction(previous_[static_cast<std::size_t>(father)], plot.time);
  const Gaussian g = manoeuvre_->combine(m);
  const auto& probabilities = profile_.initial_mode_probabilities;
  const ImmEstimate start =
      filter_.initial(g,
                      Eigen::Map<const Eigen::VectorXd>(
                          probabilities.data(), static_cast<Eigen::Index>(probabilities.size())),
                      m.time);
  const PlotHypothesis h = filter_.hypothesise(start, plot);
  if (!h.usable) return start;
  const double one = 1.0;
  return counted(filter_.update(start, std::span(&h, 1), std::span(&one, 1), 0.0,
                                profile_.association.detection_probability,
                                profile_.association.gate_probability, clutter_density(plot, -1)));
}

bool PointTracker::make_room(std::int64_t father, std::int64_t parent, double score,
                             std::int64_t plot_id, ScanReport& report) {
  const config::BranchingSpec& spec = profile_.branching;
  for (const bool per_father : {true, false}) {
    const int count = per_father ? tree_.branch_count(father) : tree_.total_branches();
    const int cap = per_father ? spec.max_branches_per_father : spec.max_total_branches;
    if (count < cap) continue;
    const std::string where = per_father ? "the cap of " + std::to_string(cap) + " per father"
                                         : "the cap of " + std::to_string(cap) + " in total";
    // The least likely branch (lowest score; the newest on a tie), never the new one's parent.
    int least = -1;
    for (std::size_t i = 0; i < tracks_.size(); ++i) {
      const PointTrack& b = tracks_[i];
      if (b.branch == BranchType::kFather || b.life.status == TrackStatus::kDeleted ||
          b.id == parent || (per_father && tree_.father_of(b.id) != father)) {
        continue;
      }
      if (least < 0 || b.score < tracks_[least].score ||
          (b.score == tracks_[least].score && b.id > tracks_[least].id)) {
        least = static_cast<int>(i);
      }
    }
    if (least < 0 || tracks_[least].score >= score) {
      add_event(
          events_, TrackEventType::kBranchPruned, father,
          "branch from plot " + std::to_string(plot_id) + " not created: least likely at " + where);
      ++report.branches_pruned;
      return false;
    }
    changes_.clear();
    tree_.remove(tracks_[least].id, changes_);
    apply(changes_, "least likely at " + where, report);
  }
  return true;
}

void PointTracker::age_branches(ScanReport& report, TrackFrame& frame) {
  const int window = profile_.branching.coast_son_looks;
  for (std::size_t i = 0; i < tracks_.size(); ++i) {
    PointTrack& branch = tracks_[i];
    if (branch.branch == BranchType::kFather || branch.life.status == TrackStatus::kDeleted ||
        (i < covered_.size() && covered_[i] == 0)) {
      continue;
    }
    const bool touched = touched_[i] != 0;
    const double miss = miss_score(static_cast<int>(i));
    if (branch.coast_son) {
      std::string reason;
      if (!touched) {
        branch.score += miss;
        if (!age_coast_son(static_cast<int>(i), frame.time)) {
          reason = "no plot in delete_confirmed_misses (" +
                   std::to_string(profile_.track_life.delete_confirmed_misses) + ") looks";
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
    branch.estimate = filter_.predict(branch.estimate, std::max(frame.time, branch.estimate.time));
    const double spread = mode_spread(branch.estimate, kLifeSpreadDims);
    if (weighs_existence(branch)) {
      update_existence(branch.life, 0.0, profile_.association.detection_probability,
                       profile_.association.gate_probability, profile_.track_life);
    }
    update_detectability(branch.life, 0.0, static_cast<int>(i));
    if (advance_life(branch.life, false, spread, life_of(branch)).deleted) {
      changes_.clear();
      tree_.remove(branch.id, changes_);
      apply(changes_, "no plot", report);
    }
  }
}

void PointTracker::retire_doomed_fathers() {
  // A doomed father that may start no more sons goes with its last branch.
  for (PointTrack& father : tracks_) {
    if (father.branch != BranchType::kFather || father.replaced || !father.doomed ||
        father.life.status == TrackStatus::kDeleted || tree_.branch_count(father.id) > 0 ||
        may_start_sons(father) || father.life.consecutive_misses < recovery_misses()) {
      continue;
    }
    father.life.status = TrackStatus::kDeleted;
    add_event(events_, TrackEventType::kDeleted, father.id, "no branch left to replace it");
    changes_.clear();
    tree_.remove(father.id, changes_);
  }
}

bool PointTracker::room_for_chain(std::int64_t father, double existence, std::int64_t plot_id,
                                  ScanReport& report) {
  const int max_children = profile_.branching.max_children;
  if (tree_.can_branch(father, max_children)) return true;
  // No room: the chain displaces the father's least likely chain son (lowest existence),
  // if less likely than itself. Sons from manoeuvre pairs stay.
  const BranchNode* node = tree_.find(father);
  int least = -1;
  for (const std::int64_t son : node->children) {
    const int i = slot(son);
    if (i < 0 || !tracks_[i].from_chain || is_reported_as_firm(tracks_[i].life.status)) continue;
    if (least < 0 || tracks_[i].life.existence < tracks_[least].life.existence) least = i;
  }
  if (least < 0 || tracks_[least].life.existence >= existence) return false;
  changes_.clear();
  tree_.remove(tracks_[least].id, changes_);
  apply(changes_,
        "a likelier plot chain (plot " + std::to_string(plot_id) + ") at max_children " +
            std::to_string(max_children),
        report);
  return true;
}

void PointTracker::find_lost_fathers(const PlotScan& scan) {
  lost_fathers_.clear();
  for (std::size_t f = 0; f < tracks_.size() && f < has_previous_.size(); ++f) {
    const PointTrack& father = tracks_[f];
    if (has_previous_[f] == 0) continue;
    if (father.branch != BranchType::kFather || !father.doomed || father.undecided ||
        father.replaced || father.life.status == TrackStatus::kDeleted) {
      continue;
    }
    LostFather& lost = lost_fathers_.emplace_back();
    lost.track = static_cast<int>(f);
    lost.reach = manoeuvre_reach(previous_[f], scan, &lost.modes, &lost.predicted);
  }
}

int PointTracker::lost_father_of(const PlotMeasurement& plot, double* nis) {
  const Eigen::Vector3d position = approximate_position(plot);
  int best = -1;
  double best_nis = manoeuvre_threshold_[plot.model.size()];
  for (LostFather& lost : lost_fathers_) {
    if (tracks_[static_cast<std::size_t>(lost.track)].replaced) continue;  // earlier this batch
    if ((position - lost.reach.centre).norm() > lost.reach.radius) continue;
    if (std::none_of(lost.modes.begin(), lost.modes.end(), [&](const Sphere& m) {
          return (position - m.centre).squaredNorm() <= m.radius * m.radius;
        })) {
      continue;
    }
    // Plots of one batch often share a time (a snapshot scan): predict once per time.
    if (lost.predicted.modes.empty() || lost.predicted.time != plot.time) {
      lost.predicted =
          manoeuvre_prediction(previous_[static_cast<std::size_t>(lost.track)], plot.time);
    }
    const PlotHypothesis h = manoeuvre_->hypothesise(lost.predicted, plot);
    if (h.usable && h.min_nis <= best_nis) {
      best_nis = h.min_nis;
      best = lost.track;
    }
  }
  if (nis != nullptr) *nis = best_nis;
  return best;
}

void PointTracker::continue_lost_fathers(ScanReport& report) {
  // Nearest first (NIS in the father's manoeuvre gate): a father is replaced once, and a
  // second new track in its gate stays a track of its own.
  struct Claim {
    double nis;
    int track, father;
  };
  std::vector<Claim> claims;
  for (const int t : confirmed_now_) {
    const PointTrack& track = tracks_[t];
    if (track.branch != BranchType::kFather || track.life.status != TrackStatus::kConfirmed ||
        track.doomed || !track.last_plot || track.last_plot_batch != batches_) {
      continue;
    }
    double nis = 0.0;
    const int f = lost_father_of(*track.last_plot, &nis);
    if (f >= 0) claims.push_back({nis, t, f});
  }
  std::stable_sort(claims.begin(), claims.end(),
                   [](const Claim& a, const Claim& b) { return a.nis < b.nis; });
  for (const Claim& claim : claims) {
    const int t = claim.track;
    const PointTrack& track = tracks_[t];
    // Its nearest father replaced by a nearer new track: the next nearest, if any.
    const int f = tracks_[static_cast<std::size_t>(claim.father)].replaced
                      ? lost_father_of(*track.last_plot)
                      : claim.father;
    if (f < 0) continue;
    const std::int64_t father = tracks_[f].id, number = track.id;
    const std::string why = name(BranchType::kFather, number) + " confirmed in its manoeuvre gate";
    if (!tree_.can_branch(father, profile_.branching.max_children)) {
      // The new track is likelier than any branch that has not confirmed: the least likely
      // son makes room for it.
      const BranchNode* node = tree_.find(father);
      int least = -1;
      for (const std::int64_t son : node->children) {
        const int i = slot(son);
        if (i >= 0 && (least < 0 || tracks_[i].score < tracks_[least].score)) least = i;
      }
      if (least < 0) continue;
      changes_.clear();
      tree_.remove(tracks_[least].id, changes_);
      apply(changes_, why, report);
    }
    // §3.3 and rule 10: the new track is the lost father's son, confirmed, so it replaces
    // the father under the father's number; its own number never appeared as firm.
    changes_.clear();
    tree_.remove(number, changes_);
    tree_.add_branch(number, father);
    tracks_[t].branch = BranchType::kSon;
    // Its plots continue the father's: the coast sons it inherits compare with that sum.
    tracks_[t].life.support += tracks_[f].life.support;
    changes_.clear();
    tree_.promote(number, changes_, false);
    // Not a new track after all: its "confirmed" (held) is superseded by the promotion.
    supersede(events_, TrackEventType::kConfirmed, number);
    apply(changes_, why + " (§3.3)", report);
  }
  confirmed_now_.clear();
}

bool PointTracker::start_chain_branch(int father, const Initiation& initiation, ScanReport& report,
                                      TrackFrame& frame) {
  const std::int64_t father_id = tracks_[father].id;
  const double score = tracks_[father].score;
  const PlotMeasurement& plot = initiation.plots.back();
  PointTrack branch;
  branch.life = initiated_life(static_cast<int>(initiation.plots.size()), initiation.scans);
  branch.life.existence = profile_.track_life.initial_existence;
  branch.estimate = start_estimate(initiation, branch.life);
  if (!room_for_chain(father_id, branch.life.existence, plot.plot_id, report) ||
      !make_room(father_id, father_id, score, plot.plot_id, report)) {
    return false;
  }
  branch.id = next_provisional_++;
  branch.branch = BranchType::kSon;
  branch.from_chain = true;
  branch.quality = tracks_[father].quality;
  branch.first_plot = initiation.plots.front();
  branch.last_plot = plot;
  branch.last_plot_batch = batches_;
  branch.score = score;
  branch.life.support = tracks_[father].life.support;
  tree_.add_branch(branch.id, father_id);
  std::string detail = name(BranchType::kSon, branch.id) + " of " +
                       name(BranchType::kFather, father_id) + " from plots";
  for (const PlotMeasurement& p : initiation.plots) {
    detail.append(" ").append(std::to_string(p.plot_id));
  }
  add_event(events_, TrackEventType::kBranchCreated, father_id,
            detail.append(" (a plot chain in its manoeuvre gate)"));
  add_association(frame, branch.id, plot.plot_id, plot.scan, 1.0);
  ++report.branches_created;
  slots_[branch.id] = static_cast<int>(tracks_.size());
  tracks_.push_back(std::move(branch));
  return true;
}

void PointTracker::apply(std::span<const BranchChange> changes, const std::string& reason,
                         ScanReport& report) {
  for (const BranchChange& change : changes) {
    const int i = slot(change.track);
    if (i < 0) continue;
    PointTrack& track = tracks_[i];
    const std::string who =
        name(change.type, change.track) + " of " +
        name(change.type == BranchType::kGrandson ? BranchType::kSon : BranchType::kFather,
             change.parent);
    switch (change.kind) {
      case BranchChange::Kind::kPruned:
        track.life.status = TrackStatus::kDeleted;
        add_event(events_, TrackEventType::kBranchPruned, change.father, who + ": " + reason);
        ++report.branches_pruned;
        break;
      case BranchChange::Kind::kIndependent:
        // A new father: numbered once confirmed (number_confirmed).
        track.branch = BranchType::kFather;
        add_event(events_, TrackEventType::kInitiated, change.track,
                  "independent " + who + ": " + reason);
        ++report.initiated;
        break;
      case BranchChange::Kind::kPromoted: {
        const int f = slot(change.father);
        if (f >= 0) {
          PointTrack& old = tracks_[f];
          // A father its life deleted in this batch lives on in the branch: no "deleted".
          if (old.life.status == TrackStatus::kDeleted) {
            supersede(events_, TrackEventType::kDeleted, change.father);
          }
          old.replaced = true;
          old.life.status = TrackStatus::kDeleted;
          track.quality = old.quality;
        }
        track.branch = BranchType::kFather;
        track.coast_son = false;
        track.id = change.father;
        replaced_now_.push_back(change.father);
        slots_.erase(change.track);
        slots_[change.father] = i;
        add_event(events_, TrackEventType::kBranchPromoted, change.father,
                  who + " replaces " + name(BranchType::kFather, change.father) + ": " + reason);
        ++report.branches_promoted;
        break;
      }
    }
  }
}

}  // namespace skytrack
