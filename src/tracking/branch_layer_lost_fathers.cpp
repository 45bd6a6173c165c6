// The branch layer's lost fathers (paper 003 §3.3): a plot chain of the initiator that ends
// in a suspended father's manoeuvre gate continues that father as its son.
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

void BranchLayer::find_lost_fathers(const PlotScan& scan) {
  lost_fathers_.clear();
  for (std::size_t f = 0; f < store().size() && f < has_previous_.size(); ++f) {
    const PointTrack& father = store()[f];
    if (has_previous_[f] == 0) continue;
    if (father.branch != BranchType::kFather || !father.doomed() || father.undecided() ||
        father.replaced || father.life.status == TrackStatus::kDeleted) {
      continue;
    }
    LostFather& lost = lost_fathers_.emplace_back();
    lost.track = static_cast<int>(f);
    lost.reach = manoeuvre_reach(previous_[f], scan, &lost.modes, &lost.predicted);
  }
}

int BranchLayer::lost_father_of(const PlotMeasurement& plot, double* nis) {
  const Eigen::Vector3d position = approximate_position(plot);
  int best = -1;
  double best_nis = manoeuvre_threshold_[plot.model.size()];
  for (LostFather& lost : lost_fathers_) {
    if (store()[static_cast<std::size_t>(lost.track)].replaced) continue;  // earlier this batch
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
      lost.shapes.clear();
    }
    // The smallest NIS over the manoeuvre models (+inf when none can take the plot).
    const double least = manoeuvre_.min_nis(lost.predicted, plot, lost.shapes);
    if (std::isfinite(least) && least <= best_nis) {
      best_nis = least;
      best = lost.track;
    }
  }
  if (nis != nullptr) *nis = best_nis;
  return best;
}

void BranchLayer::continue_lost_fathers(ScanReport& report) {
  // Nearest first (NIS in the father's manoeuvre gate): a father is replaced once, and a
  // second new track in its gate stays a track of its own.
  struct Claim {
    double nis;
    int track, father;
  };
  std::vector<Claim> claims;
  for (const int t : confirmed_now_) {
    const PointTrack& track = store()[t];
    if (track.branch != BranchType::kFather || track.life.status != TrackStatus::kConfirmed ||
        track.doomed() || !track.last_plot || track.last_plot_batch != look_->batch) {
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
    const PointTrack& track = store()[t];
    // Its nearest father replaced by a nearer new track: the next nearest, if any.
    const int f = store()[static_cast<std::size_t>(claim.father)].replaced
                      ? lost_father_of(*track.last_plot)
                      : claim.father;
    if (f < 0) continue;
    const std::int64_t father = store()[f].id, number = track.id;
    const std::string why = name(BranchType::kFather, number) + " confirmed in its manoeuvre gate";
    if (!tree_.can_branch(father, profile_.point.branching.max_children)) {
      // The new track is likelier than any branch that has not confirmed: the least likely
      // son makes room for it.
      const BranchNode* node = tree_.find(father);
      int least = -1;
      for (const std::int64_t son : node->children) {
        const int i = store().slot(son);
        if (i >= 0 && (least < 0 || store()[i].score < store()[least].score)) least = i;
      }
      if (least < 0) continue;
      changes_.clear();
      tree_.remove(store()[least].id, changes_);
      apply(changes_, why, report);
    }
    // §3.3 and rule 10: the new track is the lost father's son, confirmed, so it replaces
    // the father under the father's number; its own number never appeared as firm.
    changes_.clear();
    tree_.remove(number, changes_);
    tree_.add_branch(number, father);
    store()[t].branch = BranchType::kSon;
    // Its plots continue the father's: the coast sons it inherits compare with that sum.
    store()[t].life.support += store()[f].life.support;
    changes_.clear();
    tree_.promote(number, changes_, false);
    // Not a new track after all: its "confirmed" (held) is superseded by the promotion.
    supersede(events(), TrackEventType::kConfirmed, number);
    apply(changes_, why + " (§3.3)", report);
  }
  confirmed_now_.clear();
}

bool BranchLayer::start_chain_branch(int father, const Initiation& initiation, ScanReport& report,
                                     TrackFrame& frame) {
  const std::int64_t father_id = store()[father].id;
  const double score = store()[father].score;
  const PlotMeasurement& plot = initiation.plots.back();
  PointTrack branch;
  branch.life = initiated_life(static_cast<int>(initiation.plots.size()), initiation.scans);
  branch.life.existence = profile_.point.track_life.initial_existence;
  branch.estimate = *start_estimate(*look_, initiation, branch.life);
  if (!room_for_chain(father_id, branch.life.existence, plot.plot_id, report) ||
      !make_room(father_id, father_id, score, plot.plot_id, report)) {
    return false;
  }
  branch.id = store().provisional();
  branch.branch = BranchType::kSon;
  branch.origin = BranchOrigin::kPlotChain;
  branch.quality = store()[father].quality;
  branch.first_plot = initiation.plots.front();
  branch.last_plot = plot;
  branch.last_plot_batch = look_->batch;
  branch.score = score;
  branch.life.support = store()[father].life.support;
  tree_.add_branch(branch.id, father_id);
  std::string detail = name(BranchType::kSon, branch.id) + " of " +
                       name(BranchType::kFather, father_id) + " from plots";
  for (const PlotMeasurement& p : initiation.plots) {
    detail.append(" ").append(std::to_string(p.plot_id));
  }
  add_event(events(), TrackEventType::kBranchCreated, father_id,
            detail.append(" (a plot chain in its manoeuvre gate)"));
  add_association(frame, branch.id, plot.plot_id, plot.scan, 1.0);
  ++report.point.branches_created;
  store().add(std::move(branch));
  return true;
}

void BranchLayer::apply(std::span<const BranchChange> changes, const std::string& reason,
                        ScanReport& report) {
  for (const BranchChange& change : changes) {
    const int i = store().slot(change.track);
    if (i < 0) continue;
    PointTrack& track = store()[i];
    const std::string who =
        name(change.type, change.track) + " of " +
        name(change.type == BranchType::kGrandson ? BranchType::kSon : BranchType::kFather,
             change.parent);
    switch (change.kind) {
      case BranchChange::Kind::kPruned:
        track.life.status = TrackStatus::kDeleted;
        add_event(events(), TrackEventType::kBranchPruned, change.father, who + ": " + reason);
        ++report.point.branches_pruned;
        break;
      case BranchChange::Kind::kIndependent:
        // A new father: numbered once confirmed (number_confirmed).
        track.branch = BranchType::kFather;
        add_event(events(), TrackEventType::kInitiated, change.track,
                  "independent " + who + ": " + reason);
        ++report.initiated;
        break;
      case BranchChange::Kind::kPromoted: {
        const int f = store().slot(change.father);
        if (f >= 0) {
          PointTrack& old = store()[f];
          // A father its life deleted in this batch lives on in the branch: no "deleted".
          if (old.life.status == TrackStatus::kDeleted) {
            supersede(events(), TrackEventType::kDeleted, change.father);
          }
          old.replaced = true;
          old.life.status = TrackStatus::kDeleted;
          track.quality = old.quality;
        }
        track.branch = BranchType::kFather;
        if (track.coast_son()) track.origin = BranchOrigin::kManoeuvrePair;
        store().renumber(i, change.father);
        replaced_now_.push_back(change.father);
        add_event(events(), TrackEventType::kBranchPromoted, change.father,
                  who + " replaces " + name(BranchType::kFather, change.father) + ": " + reason);
        ++report.point.branches_promoted;
        break;
      }
    }
  }
}

}  // namespace skytrack
