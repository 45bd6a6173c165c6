#pragma once
// The branch ("filiation") layer of paper 003 (§1 rules 5-10, §2.1-2.3, §3.3) on top of the
// plain IMM-JPDA point tracker: each reported track (father) may carry hidden sons and
// grandsons, with a second, wider manoeuvre gate per track, pairs of five kinds with their
// own JPDA probabilities, their ordered confirmation (branch_association.hpp) and the tree
// rules (branch_tree.hpp). The point tracker owns one when the profile's branching is on and
// calls it, as its BranchHooks (branch_hooks.hpp, docs/point-tracker.md "Components"), at a
// few points of a look: before gating, per track in the gater and in a father's update,
// instead of the plain association (associate), round initiation (§3.3's lost fathers) and
// when fathers are numbered. Between begin and end it holds the look's parts (point_look.hpp).
// Files: branch_layer.cpp (creation, hooks), _kinds (the pair kinds and their JPDA), _pairs,
// _changes, _lost_fathers, _last_motion.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "skytrack/config/profile.hpp"
#include "skytrack/core/expected.hpp"
#include "skytrack/core/look.hpp"
#include "skytrack/core/scan_report.hpp"
#include "skytrack/core/track_report.hpp"
#include "skytrack/filter/imm_filter.hpp"
#include "skytrack/tracking/branch_association.hpp"
#include "skytrack/tracking/branch_hooks.hpp"
#include "skytrack/tracking/branch_tree.hpp"
#include "skytrack/tracking/gater.hpp"
#include "skytrack/tracking/imm_pda_updater.hpp"
#include "skytrack/tracking/initiator.hpp"
#include "skytrack/tracking/point_track.hpp"

namespace skytrack {

struct PointLook;
class TrackStore;
class ClusterAssociator;

class BranchLayer final : public BranchHooks {
 public:
  /// Empty when the profile's branching is off; fails when its manoeuvre models are wrong.
  static Expected<std::optional<BranchLayer>> create(const config::TrackingProfile& profile,
                                                     const ImmFilter& main, int dims);

  // BranchHooks: a look.
  void begin(PointLook& look) override { look_ = &look; }
  void before_gating() override;
  void associate(const PlotScan& scan, ScanReport& report, TrackFrame& frame);
  /// Collects the suspended fathers that may still branch and continues them with the
  /// fathers confirmed in this look in their manoeuvre gates (§3.3).
  void before_initiation(const PlotScan& scan, ScanReport& report) override;
  /// A chain that ends in a suspended father's manoeuvre gate starts as its son: true when
  /// it did (the caps may leave no room; it then starts a new father).
  bool take_chain(const Initiation& initiation, ScanReport& report, TrackFrame& frame) override;
  /// Track t is a new father started from `initiation`.
  void father_started(int t, const Initiation& initiation) override;
  /// Deletes the doomed fathers that have no branch left and may start no more sons.
  void after_initiation() override;
  void renamed(std::span<const std::pair<std::int64_t, std::int64_t>> renamed) override;
  void end() override { look_ = nullptr; }
  const BranchTree& tree() const { return tree_; }

  // BranchHooks: per track.
  bool at_mid_batch(int t, bool covered, const Gaussian& mid, double time) override;
  void narrow(int t, ImmEstimate& predicted, std::span<const int> neighbours,
              std::uint8_t& clutter_area) override;
  void updated(PointTrack& track, bool valid) override;
  bool detected(int t, bool valid, bool plain) override;
  void confirmed(int t) override { confirmed_now_.push_back(t); }
  /// The likeliest (highest score) son or grandson, coast sons aside, that took a plot in
  /// this look while `father` took none, whose pair's probability beta outweighs the
  /// father's IMM prior of a manoeuvre (onset x beta > (1 - onset) x (1 - beta)).
  const PointTrack* stand_in(const PointTrack& father) const override;

 private:
  BranchLayer(const config::TrackingProfile& profile, ImmFilter manoeuvre,
              std::optional<ImmFilter> hold);

  // The look's parts (between begin and end).
  TrackStore& store();
  const TrackStore& store() const;
  Gater& gater();
  const Gater& gater() const;
  const ImmFilter& filter() const;
  Preprocessing& pre() const;
  std::vector<TrackEvent>& events();

  struct Sphere {
    Eigen::Vector3d centre;
    double radius = 0.0;
  };
  ImmEstimate manoeuvre_prediction(const ImmEstimate& estimate, double time) const;
  /// Manoeuvre candidates of track t; with `for_update` (grandsons) also its IMM hypotheses
  /// and its prediction at the nearest candidate's time.
  void gate_manoeuvre(const PlotScan& scan, int t, bool for_update);
  /// The region holding the manoeuvre gate started from `prior`, at the batch's middle; with
  /// `modes`, also each manoeuvre model's own region.
  Sphere manoeuvre_reach(const ImmEstimate& prior, const PlotScan& scan, std::vector<Sphere>* modes,
                         ImmEstimate* mid = nullptr) const;
  /// JPDA over one pair kind (§2.1 (3)); collects its valid pairs, updates fathers.
  void solve_kind(PairKind kind);
  /// The life rules of a branch: a chain-started son's are a new track's (existence).
  const config::TrackLifeSpec& life_of(const PointTrack& branch) const;
  /// Whether a branch's existence is updated (chain sons; all with existence confirmation).
  bool weighs_existence(const PointTrack& branch) const;
  /// A firm father not yet doomed, or doomed with fewer than delete_confirmed_misses misses.
  bool may_start_sons(const PointTrack& father) const;
  int recovery_misses() const;
  /// A firm, not yet doomed father whose prediction `mid` is already wider than
  /// delete_position_sigma: its non-manoeuvre gate would take clutter and cut the branch
  /// that follows the target, so it is suspended before gating.
  bool suspends_before_gating(const PointTrack& track, const Gaussian& mid, double time) const;
  /// Notes the likeliest plot of father `t`'s non-manoeuvre update in claimed_by_.
  void claim_best_plot(int t, const std::vector<Candidate>& pool, std::span<const int> mine,
                       std::span<const double> beta, double miss);
  /// Makes undecided the fathers whose update weighed two plots above ambiguity_beta that
  /// are no other father's likeliest plot.
  void split_undecided_fathers();
  /// The plain update of a father; a firm father its life deletes becomes doomed instead.
  void update_father(int t, std::span<const int> candidates, std::span<const double> beta_plots,
                     double beta_miss);
  void confirm_branch_pairs(ScanReport& report, TrackFrame& frame);
  void update_branch(const BranchPair& pair, ScanReport& report);
  /// Rule 10 for the undecided fathers' sons confirmed in this scan, likeliest first.
  void promote_confirmed_sons(ScanReport& report);
  bool of_undecided_father(std::int64_t son) const;
  void create_branch(const BranchPair& pair, ScanReport& report, TrackFrame& frame);
  /// branching.coast_sons: notes father `t`'s non-manoeuvre pair when its plot may be a false
  /// alarm; start_coast_sons starts the coast sons once this batch's sons took their pairs.
  void note_doubtful_update(const BranchPair& pair);
  void start_coast_sons(ScanReport& report, TrackFrame& frame);
  /// A coast son that took no plot: holds its last motion; deleted after
  /// delete_confirmed_misses misses in a row: false when it is to be deleted.
  bool age_coast_son(int t, double time);
  /// TrackLife::support and detectability of a scan (no ratios: a miss) on the chain where
  /// track `where` is; the score of track t's miss on the same chain.
  void add_support(TrackLife& life, const PlotRatios& ratios, int where) const;
  double miss_score(int t) const;
  /// The best support of a father and its sons and grandsons (coast sons aside).
  double family_support(std::int64_t father) const;
  /// A son's start: its father's prediction through the manoeuvre models, updated by `plot`.
  ImmEstimate son_start(int father, const PlotMeasurement& plot) const;
  /// Frees a place under the caps for a branch of `father` scoring `score`; false if the new
  /// branch itself is the least likely.
  bool make_room(std::int64_t father, std::int64_t parent, double score, std::int64_t plot_id,
                 ScanReport& report);
  void age_branches(ScanReport& report, TrackFrame& frame);
  /// Room under max_children for a chain son of `father` whose existence is `existence`:
  /// displaces the least likely chain son if need be; false if there is none less likely.
  bool room_for_chain(std::int64_t father, double existence, std::int64_t plot_id,
                      ScanReport& report);
  /// The suspended father in whose manoeuvre gate `plot` lies (the nearest), or -1.
  int lost_father_of(const PlotMeasurement& plot, double* nis = nullptr);
  /// Starts the chain as a son of `father` instead of a new father; false when the branch
  /// caps leave no room (the chain then starts a new father).
  bool start_chain_branch(int father, const Initiation& initiation, ScanReport& report,
                          TrackFrame& frame);
  /// Collects the suspended fathers that may still branch, with their manoeuvre gates' reach.
  void find_lost_fathers(const PlotScan& scan);
  /// §3.3 for chains that completed before their target's father was suspended: a father
  /// confirmed in this batch whose plot lies in a suspended father's manoeuvre gate
  /// replaces it under its number.
  void continue_lost_fathers(ScanReport& report);
  void apply(std::span<const BranchChange> changes, const std::string& reason, ScanReport& report);

  // The last motion (branching.coast_on_last_motion, branch_layer_last_motion.cpp).
  /// A father whose manoeuvre gate and sons start from its IMM's coast since its last
  /// detection (it holds its last motion since a miss), not from its estimate.
  bool starts_from_coast(const PointTrack& track) const;
  bool holds_last_motion() const { return profile_.point.branching.coast_on_last_motion; }
  /// log det S of the innovation of the last motion in narrowed_ for plots of `plot`'s model
  /// (NaN when there is none).
  double last_motion_log_det(const PlotMeasurement& plot) const;
  /// branching.last_motion_false_plots: a father's last motion's gate, whose innovation
  /// covariance has log det S = `log_det` at plot `plot`, expects at least that many false
  /// plots there.
  bool in_dense_clutter(double log_det, int plot) const;
  /// A missing father's estimate becomes its last motion's prediction; `coasted` keeps what
  /// its IMM would have coasted to.
  void hold_last_motion(PointTrack& track) const;
  /// A firm father that missed since its last valid association (or any firm father, with
  /// non_manoeuvre_gate last_motion): its likeliest mode then, predicted alone to `time` (the
  /// motion it was last seen in), held by every mode at the modes' predicted probabilities.
  /// Empty otherwise.
  std::optional<ImmEstimate> last_motion(const PointTrack& track, double time,
                                         bool missing_now = false) const;
  /// The same written over `out` (its storage reused); false, `out` untouched, when empty.
  bool last_motion(const PointTrack& track, double time, bool missing_now, ImmEstimate& out) const;

  config::TrackingProfile profile_;
  config::TrackLifeSpec branch_life_;  // sons and grandsons: M-of-N confirmation
  ImmFilter manoeuvre_;                // the manoeuvre gate's models
  std::optional<ImmFilter> hold_;      // a held last motion's (last_motion_accel_sigma)
  Eigen::VectorXd manoeuvre_start_;    // their probabilities at a gate's start (uniform)
  double manoeuvre_threshold_[kMaxMeasurementDim + 1] = {};
  BranchTree tree_;
  PointLook* look_ = nullptr;

  // Per-look workspaces (reused).
  std::vector<int> suspended_at_gate_;      // fathers suspended on their prediction
  std::vector<ImmEstimate> previous_;       // per track, before this batch
  ImmEstimate narrowed_;                    // narrow()'s last motion of one track
  std::vector<std::uint8_t> has_previous_;  // previous_ holds this batch's prior
  struct LostFather {  // a suspended father and its manoeuvre gate's reach this batch
    int track = 0;
    Sphere reach;
    std::vector<Sphere> modes;  // each manoeuvre model's region (reach is their union's)
    ImmEstimate predicted;      // its manoeuvre prediction to the last plot time asked for
    HypothesisShapes shapes;    // of that prediction
  };
  std::vector<LostFather> lost_fathers_;
  std::vector<int> confirmed_now_;  // fathers confirmed in this batch
  struct PendingSplit {             // a father whose update weighed two plots above ambiguity_beta
    int track = 0;
    std::vector<int> plots;
    std::vector<double> beta;
    double miss = 0.0;
    std::optional<ImmEstimate> last_detected;  // before this update (coast_on_last_motion)
  };
  std::vector<PendingSplit> pending_splits_;
  struct ConfirmedSon {  // a son confirmed by its non-manoeuvre pair, awaiting promotion
    int track = 0;
    double likelihood = 0.0;  // of the plot of its pair
    std::int64_t plot_id = 0;
  };
  std::vector<ConfirmedSon> confirmed_sons_;
  struct BeforeUpdate {  // a father before this look's update: what its coast sons start from
    std::optional<ImmEstimate> motion;  // last_detected
    double support = 0.0;               // life.support
    double detectable = 1.0;            // life.detectable
    bool valid = false;                 // set in this look (the slots keep their storage)
  };
  std::vector<BeforeUpdate> before_update_;  // per track (coast sons)
  struct DoubtfulUpdate {  // a father's non-manoeuvre pair whose plot may be a false alarm
    int track = 0;
    double doubt = 0.0;  // the plot's clutter density over its density under track + clutter
    std::int64_t plot_id = 0;
  };
  std::vector<DoubtfulUpdate> doubtful_;
  std::vector<std::int64_t> replaced_now_;  // numbers a branch took over in this batch
  std::vector<int> claimed_by_;  // per plot: the father whose likeliest it is; -1 none, -2 several
  std::vector<Sphere> mode_reach_;               // gate_manoeuvre's models' regions
  std::vector<Candidate> manoeuvre_candidates_;  // manoeuvre gates
  std::vector<int> kind_list_;
  struct SoftUpdate {  // a branch's JPDA weights in the kind that updates it
    std::vector<int> candidates;
    std::vector<double> beta;
    double miss = 1.0;
  };
  std::vector<SoftUpdate> branch_updates_;  // per track
  std::vector<BranchPair> branch_pairs_;
  std::vector<std::uint8_t> touched_;  // per track: updated or created this batch
  std::vector<BranchChange> changes_;
  std::vector<int> neighbours_;
  HypothesisShapes shapes_, manoeuvre_shapes_;  // of one track's predictions
};

}  // namespace skytrack
