#pragma once
// The point tracker, the estimator of `mode: point` (estimator.hpp): IMM-JPDA (paper 003 §3)
// with logic-based initiation and track life. One call per look, whose plots the preprocessing
// stage has prepared; it asks that stage for clutter rejection once its gates say which plots
// its confirmed tracks protect, and for the clutter density once they say which are false.
//
// Per batch: each track's search region comes from its IMM prediction at the middle of the
// batch; candidate plots from a k-d tree are tested in an ellipsoidal gate at the track's
// own update time (the time of its nearest candidate plot, so a rotating antenna's plots are
// used at the time they were measured); tracks sharing plots form clusters whose JPDA
// marginals (exact, or k-best above a size) weight each track's IMM-PDA update. Plots in no
// gate, and gated plots the association leaves unexplained (the gating tracks each give more
// than initiation.gated_seed_beta to another plot: a formation member in its neighbour's
// gate), feed the initiator. Reported states are predicted to the batch time.
//
// With branching on (profile `branching`, paper 003 §1-§2.3) each reported track (father) may
// carry hidden sons and grandsons: a second, wider manoeuvre gate per track, pairs of five
// kinds with their own JPDA probabilities, their ordered confirmation
// (tracking/branch_association.hpp) and the tree rules (tracking/branch_tree.hpp), in
// point_tracker_branch*.cpp and point_tracker_lost_fathers.cpp. With branching off the tracker
// is plain IMM-JPDA. The plain tracker's parts: point_tracker.cpp (creation, a look's steps),
// _gating, _association (clutter rejection and density, JPDA, IMM-PDA update), _initiation,
// _report and _looks (search regions, numbering).
#include <chrono>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "skytrack/association/cluster_builder.hpp"
#include "skytrack/association/gnn_associator.hpp"
#include "skytrack/association/jpda_solver.hpp"
#include "skytrack/association/plot_index.hpp"
#include "skytrack/config/profile.hpp"
#include "skytrack/core/expected.hpp"
#include "skytrack/core/look.hpp"
#include "skytrack/core/plot.hpp"
#include "skytrack/core/scan_report.hpp"
#include "skytrack/core/track_report.hpp"
#include "skytrack/filter/imm_filter.hpp"
#include "skytrack/measurement/plot_measurement.hpp"
#include "skytrack/tracking/branch_association.hpp"
#include "skytrack/tracking/branch_tree.hpp"
#include "skytrack/tracking/estimator.hpp"
#include "skytrack/tracking/initiator.hpp"
#include "skytrack/tracking/track_life.hpp"

namespace skytrack {

/// A father's state in the branch layer (paper 003); every father of a plain tracker (branching
/// off) stays active.
enum class FatherState : std::uint8_t {
  kActive,  // reported; takes every kind of pair
  // Its update weighed two plots above branching.ambiguity_beta: still reported while the sons
  // from its plots decide; active again once none is left.
  kUndecided,
  // Its track life deleted it (its gate too wide, or too many misses) while a branch may
  // still replace it: not reported ("suspended" event), coasts and takes no non-manoeuvre
  // pair; it starts sons from its manoeuvre gate until its misses reach
  // delete_confirmed_misses, and is deleted (and reported so) once it has no branches left
  // after that. A branch that replaces it brings its number back.
  kSuspended,
};

/// What started a son or grandson.
enum class BranchOrigin : std::uint8_t {
  kManoeuvrePair,  // a pair in its parent's manoeuvre gate (paper 003 §2.3)
  // A plot chain completed in a suspended father's manoeuvre gate (§3.3): confirmed on its
  // existence, as the same chain would be as a new track, not on plot counts.
  kPlotChain,
  // A coast son (branching.coast_sons): its father's last motion before a plot that may have
  // been a false alarm; it holds and gates on that motion (last_detected) until it takes
  // plots of its own, and is a plain father once it replaces its father.
  kCoast,
};

struct PointTrack {
  std::int64_t id = 0;
  TrackLife life;
  ImmEstimate estimate;  // posterior at estimate.time
  double quality = 0.0;  // running mean of the detection probability, in [0, 1]

  // Per sensor, the antenna's sweep when it last looked at the track or the track took one
  // of its plots: a look within half a revolution of it is not another look (a rotating
  // antenna's sector looks).
  std::vector<std::pair<std::uint32_t, double>> looked;
  double looked_by(std::uint32_t sensor) const {
    for (const auto& [s, sweep] : looked) {
      if (s == sensor) return sweep;
    }
    return -std::numeric_limits<double>::infinity();
  }
  void set_looked(std::uint32_t sensor, double sweep) {
    for (auto& [s, last] : looked) {
      if (s == sensor) {
        last = sweep;
        return;
      }
    }
    looked.emplace_back(sensor, sweep);
  }

  // Branch tracking (paper 003); fathers only while branching is off.
  BranchType branch = BranchType::kFather;    // only fathers are reported
  std::optional<PlotMeasurement> first_plot;  // a branch's start plot (§1 (6)-(7))
  std::optional<PlotMeasurement> last_plot;   // the plot of its latest confirmed pair
  std::uint64_t last_plot_batch = 0;
  double score = 0.0;     // a branch's summed log pair probabilities: the least likely is pruned
  bool replaced = false;  // a father a branch replaced: dropped without a report
  FatherState state = FatherState::kActive;
  BranchOrigin origin = BranchOrigin::kManoeuvrePair;
  // Its estimate after its latest update with a valid association (a plot likelier than its
  // miss), kept with branching.coast_on_last_motion: a firm father that missed since coasts
  // and gates on that motion.
  std::optional<ImmEstimate> last_detected;
  // While it holds its last motion: what its IMM would have coasted to since (the turns it
  // may have started), from which its manoeuvre gate and sons start.
  std::optional<ImmEstimate> coasted;

  /// Suspended or undecided: waiting for its branches to decide.
  bool doomed() const { return state != FatherState::kActive; }
  bool undecided() const { return state == FatherState::kUndecided; }
  bool from_chain() const { return origin == BranchOrigin::kPlotChain; }
  bool coast_son() const { return origin == BranchOrigin::kCoast; }
};

class PointTracker final : public Estimator {
 public:
  /// Checks the profile's models and matrices; fails with a message naming what is wrong.
  static Expected<PointTracker> create(const config::TrackingProfile& profile, int dims);

  /// Processes one look (estimator.hpp): its plots are `pre`'s.
  void process(const PlotScan& scan, Preprocessing& pre, TrackFrame& frame,
               ScanReport& report) override;

  void report_only(const PlotScan& scan, TrackFrame& frame, ScanReport& report) override;

  /// The search region of every track (its widest gate round its prediction to `time`, for
  /// plots with the sigmas of batch `header`) and of every candidate chain of the initiator:
  /// where this tracker may take a plot.
  void search_regions(const PlotScan& header, double time,
                      std::vector<SearchRegion>& out) const override;

  /// Every track: the fathers (reported) and, with branching, their sons and grandsons.
  const std::vector<PointTrack>& tracks() const { return tracks_; }
  const BranchTree& branch_tree() const { return tree_; }
  int dims() const { return layout_.dims; }

 private:
  PointTracker(const config::TrackingProfile& profile, StateLayout layout, ImmFilter filter,
               std::optional<ImmFilter> manoeuvre, std::optional<ImmFilter> hold);

  struct Candidate {  // a gated track-plot pair
    int track = 0;
    int plot = 0;
    PlotHypothesis hypothesis;  // against the track's IMM prediction (its update)
    double likelihood = 0.0;    // what JPDA weighs it with (the gate's own model set)
  };
  /// JPDA over the clusters of the candidates `list` (indices into `pool`, grouped by track),
  /// calling `on_track(t, mine, beta, beta_miss)` per track of each cluster in cluster order
  /// (also for tracks with no candidate: empty spans, beta_miss 1).
  using OnTrack = std::function<void(int, std::span<const int>, std::span<const double>, double)>;
  void solve_clusters(const std::vector<Candidate>& pool, std::span<const int> list,
                      double gate_probability, ScanReport& report, const OnTrack& on_track,
                      bool pda_above_exact = false);
  /// Per-track PDA weights of a cluster (each track as if alone), for the manoeuvre kinds'
  /// clusters above association.max_exact_cluster_size: their wide gates in dense clutter
  /// chain hundreds of tracks, where k-best joint events cost seconds.
  const JpdaResult& pda_marginals(const JpdaProblem& problem);
  /// Likelihood over clutter density, L_i / lambda_i, of a track's gated plots.
  struct PlotRatios {
    double sum = 0.0;   // over the plots: the existence update's likelihood ratio
    double best = 0.0;  // the likeliest plot's: its support (TrackLife::support)
  };
  /// IMM-PDA update of track t with its weighted candidates from `pool`; reports the
  /// associations under `number`.
  PlotRatios soft_update(int t, std::vector<Candidate>& pool, std::span<const int> candidates,
                         std::span<const double> beta_plots, double beta_miss, std::int64_t number,
                         TrackFrame& frame);

  /// A region holding track t's gate at `threshold` (chi-square) round its prediction to
  /// `time`, for a target accelerating up to `accel` [m/s^2]: cheap, never smaller than the
  /// gate's own search region.
  SearchRegion region_bound(int t, const PlotScan& header, double time, double threshold,
                            double accel) const;
  double seed_speed(int t) const {
    return region_seeds_[static_cast<std::size_t>(t)].velocity.norm();
  }
  void start_frame(const PlotScan& scan, TrackFrame& frame) const;
  double plot_spread_at(const Eigen::Vector3d& position, const PlotScan& scan) const;
  /// True when the batch looked at `position` (always, unless it covers only a sector).
  bool covers(const PlotScan& scan, const Eigen::Vector3d& position) const;
  /// True when a search region (centre, radius) reaches into the batch's coverage.
  bool covers_region(const PlotScan& scan, const Eigen::Vector3d& centre, double radius) const;
  void gate(const PlotScan& scan, double batch_mid, double half_span);
  /// A father whose manoeuvre gate and sons start from its IMM's coast since its last
  /// detection (it holds its last motion since a miss), not from its estimate.
  bool starts_from_coast(const PointTrack& track) const;
  /// branching.coast_on_last_motion is on (and branching).
  bool holds_last_motion() const;
  /// branching.last_motion_false_plots: a father's last motion's gate, of which `last_motion`
  /// is the test at plot `plot`, expects at least that many false plots there.
  bool in_dense_clutter(const Innovation& last_motion, int plot) const;
  /// A missing father's estimate becomes its last motion's prediction; `coasted` keeps what
  /// its IMM would have coasted to.
  void hold_last_motion(PointTrack& track) const;
  /// A firm father that missed since its last valid association (or any firm father, with
  /// non_manoeuvre_gate last_motion): its likeliest mode then, predicted alone to `time` (the
  /// motion it was last seen in), held by every mode at the modes' predicted probabilities.
  /// Empty otherwise.
  std::optional<ImmEstimate> last_motion(const PointTrack& track, double time,
                                         bool missing_now = false) const;
  /// Radius of the region around `centre` holding g's gate at `threshold` (chi-square).
  double search_radius(const Gaussian& g, const Eigen::Vector3d& centre, double threshold,
                       const PlotScan& scan) const;
  /// Time of the plot in neighbours_ nearest to `centre`.
  double nearest_time(const Eigen::Vector3d& centre) const;
  void reject_clutter(ScanReport& report);
  void associate_and_update(ScanReport& report, TrackFrame& frame);
  /// reports_deletion false: the caller turns a deletion into a suspension (update_father).
  void update_track(int t, std::span<const int> candidates, std::span<const double> beta_plots,
                    double beta_miss, TrackFrame& frame, bool reports_deletion = true);
  /// Marks the plots a track's association holds back from initiation (held_).
  void note_explained(const std::vector<Candidate>& pool, std::span<const int> mine,
                      std::span<const double> beta);
  /// True when plot j may feed the initiator: in no gate, or in gates but unexplained.
  bool free_for_initiation(std::size_t j) const;
  void initiate(const PlotScan& scan, ScanReport& report, TrackFrame& frame);

  // Branch tracking (point_tracker_branch*.cpp, point_tracker_lost_fathers.cpp).
  bool branching() const { return manoeuvre_.has_value(); }
  ImmEstimate manoeuvre_prediction(const ImmEstimate& estimate, double time) const;
  void associate_branches(const PlotScan& scan, ScanReport& report, TrackFrame& frame);
  /// Manoeuvre candidates of track t; with `for_update` (grandsons) also its IMM hypotheses
  /// and its prediction at the nearest candidate's time.
  void gate_manoeuvre(const PlotScan& scan, int t, bool for_update);
  struct Sphere {
    Eigen::Vector3d centre;
    double radius = 0.0;
  };
  /// The region holding the manoeuvre gate started from `prior`, at the batch's middle; with
  /// `modes`, also each manoeuvre model's own region.
  Sphere manoeuvre_reach(const ImmEstimate& prior, const PlotScan& scan, std::vector<Sphere>* modes,
                         ImmEstimate* mid = nullptr) const;
  /// JPDA over one pair kind (§2.1 (3)); collects its valid pairs, updates fathers.
  void solve_kind(PairKind kind, ScanReport& report, TrackFrame& frame);
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
  /// update_track for a father; a firm father its life deletes becomes doomed instead.
  void update_father(int t, std::span<const int> candidates, std::span<const double> beta_plots,
                     double beta_miss, TrackFrame& frame);
  void confirm_branch_pairs(ScanReport& report, TrackFrame& frame);
  void update_branch(const BranchPair& pair, ScanReport& report, TrackFrame& frame);
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
  // One scan's TrackLife::support (no ratios: a miss) and detectability on the chain of
  // branching.detectability where track `where` is (detectability_at); the score of track
  // t's miss on the same chain.
  config::DetectabilitySpec detectability_at(int where) const;
  void add_support(TrackLife& life, const PlotRatios& ratios, int where) const;
  void update_detectability(TrackLife& life, double likelihood_ratio, int where) const;
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
  /// Deletes the doomed fathers that have no branch left and may start no more sons.
  void retire_doomed_fathers();
  /// Collects the suspended fathers that may still branch, with their manoeuvre gates' reach.
  void find_lost_fathers(const PlotScan& scan);
  /// Room under max_children for a chain son of `father` whose existence is `existence`:
  /// displaces the least likely chain son if need be; false if there is none less likely.
  bool room_for_chain(std::int64_t father, double existence, std::int64_t plot_id,
                      ScanReport& report);
  /// The suspended father in whose manoeuvre gate `plot` lies (the nearest), or -1.
  int lost_father_of(const PlotMeasurement& plot, double* nis = nullptr);
  /// §3.3 for chains that completed before their target's father was suspended: a father
  /// confirmed in this batch whose plot lies in a suspended father's manoeuvre gate
  /// replaces it under its number.
  void continue_lost_fathers(ScanReport& report);
  /// Starts the chain as a son of `father` instead of a new father; false when the branch
  /// caps leave no room (the chain then starts a new father).
  bool start_chain_branch(int father, const Initiation& initiation, ScanReport& report,
                          TrackFrame& frame);
  void apply(std::span<const BranchChange> changes, const std::string& reason, ScanReport& report);
  int slot(std::int64_t number) const;
  void report_tracks(double time, ScanReport& report, TrackFrame& frame);
  /// Gives the fathers confirmed with a provisional number their numbers, in the order of
  /// their latest plots; this frame names them by it.
  void number_confirmed(TrackFrame& frame);
  void estimate_clutter_density();
  /// The start of a new track's estimate; the chain's plots after the first two also update
  /// its existence.
  ImmEstimate start_estimate(const Initiation& initiation, TrackLife& life) const;
  /// An update, its failed modes (which kept their prediction) counted for the report.
  ImmEstimate counted(ImmEstimate update) const {
    numeric_failures_ += update.numeric_failure() ? 1 : 0;
    return update;
  }

  config::TrackingProfile profile_;
  config::TrackLifeSpec branch_life_;  // sons and grandsons: M-of-N confirmation
  StateLayout layout_;
  ImmFilter filter_;
  // Updates with failed modes and clusters whose association failed, since the last report:
  // counted where they happen, some of them in const members.
  mutable int numeric_failures_ = 0;
  std::optional<ImmFilter> manoeuvre_;  // the manoeuvre gate's models; set when branching
  std::optional<ImmFilter> hold_;       // a held last motion's (last_motion_accel_sigma)
  Eigen::VectorXd manoeuvre_start_;     // their probabilities at a gate's start (uniform)
  Initiator initiator_;
  struct RegionSeed {  // a track's combined estimate at its own time (search_regions)
    std::int64_t id = -1;
    double time = 0.0;
    Eigen::Vector3d position = Eigen::Vector3d::Zero(), velocity = Eigen::Vector3d::Zero();
    double spread = 0.0, velocity_spread = 0.0;  // [m], [m/s]
  };
  mutable std::vector<RegionSeed> region_seeds_;  // per track slot
  double region_accel_ = 0.0;                     // [m/s^2]
  double max_turn_rate_ = 0.0;                    // [rad/s]
  std::vector<std::uint8_t> took_candidates_;     // per track: a plot of this look in its gate
  ClusterBuilder clusters_;
  JpdaSolver jpda_;
  JpdaSolver jpda_manoeuvre_;  // the manoeuvre kinds' clusters (branching)
  GnnAssociator gnn_;
  std::vector<PointTrack> tracks_;
  // A track's number is given when it is confirmed, in the order of the plots that confirmed
  // it, so neither tentative tracks of clutter nor the grouping of plots into looks shifts
  // the numbers; until then a track (and a branch, until it replaces its father) carries a
  // provisional number from kProvisionalNumber on.
  std::int64_t next_number_ = 1;
  std::int64_t next_provisional_ = kProvisionalNumber;
  std::uint64_t batches_ = 0;
  double gate_threshold_[kMaxMeasurementDim + 1] = {};  // chi-square quantile per dims
  // per dims: the gate's volume times N(nu; 0, S)'s peak, (g/2)^(d/2) / Gamma(d/2 + 1)
  double gate_volume_per_peak_[kMaxMeasurementDim + 1] = {};
  double manoeuvre_threshold_[kMaxMeasurementDim + 1] = {};
  double batch_mid_ = 0.0, half_span_ = 0.0;  // this batch's plot times
  BranchTree tree_;
  std::unordered_map<std::int64_t, int> slots_;  // track number -> index in tracks_

  Preprocessing* pre_ = nullptr;  // this look's plots, during process

  // Per-batch workspaces (reused).
  std::vector<std::uint8_t> gated_;
  std::vector<std::uint8_t> dense_;     // per track: a plot round it in_dense_clutter this batch
  std::vector<std::uint8_t> covered_;   // per track: inside this batch's coverage
  std::vector<int> suspended_at_gate_;  // fathers suspended on their prediction
  std::vector<ImmEstimate> predicted_;  // per track, at its update time
  std::vector<ImmEstimate> previous_;   // per track, before this batch (branching)
  std::vector<std::uint8_t> has_previous_;  // previous_ holds this batch's prior
  struct LostFather {  // a suspended father and its manoeuvre gate's reach this batch
    int track = 0;
    Sphere reach;
    std::vector<Sphere> modes;  // each manoeuvre model's region (reach is their union's)
    ImmEstimate predicted;      // its manoeuvre prediction to the last plot time asked for
  };
  std::vector<LostFather> lost_fathers_;
  std::vector<int> confirmed_now_;  // fathers confirmed in this batch (branching only)
  // This batch's events, held until the batch has decided them all (process emits them
  // into the frame): a later decision may supersede one, which then never appears.
  std::vector<TrackEvent> events_;
  struct PendingSplit {  // a father whose update weighed two plots above ambiguity_beta
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
  std::vector<Candidate> candidates_;            // non-manoeuvre gates
  std::vector<Candidate> manoeuvre_candidates_;  // manoeuvre gates (branching)
  std::vector<int> kind_list_;
  struct SoftUpdate {  // a branch's JPDA weights in the kind that updates it
    std::vector<int> candidates;
    std::vector<double> beta;
    double miss = 1.0;
  };
  std::vector<SoftUpdate> branch_updates_;  // per track
  std::vector<BranchPair> branch_pairs_;
  std::vector<std::uint8_t> touched_;         // per track: updated or created this batch
  std::vector<std::uint8_t> used_by_branch_;  // per plot: taken by a confirmed pair
  // Per plot: held by a non-manoeuvre gate, i.e. the most likely plot of a track that
  // explains it, or any plot of a track that explains none (initiation.gated_seed_beta).
  std::vector<std::uint8_t> held_;
  std::vector<BranchChange> changes_;
  JpdaResult pda_result_;
  std::vector<int> neighbours_;
  std::vector<GatedPair> pairs_;
  std::vector<PlotHypothesis> hypotheses_;  // one track's update
  std::vector<double> kept_beta_;
  std::vector<std::uint8_t> false_plots_;  // per plot: no firm track gates it (clutter map)
};

}  // namespace skytrack
