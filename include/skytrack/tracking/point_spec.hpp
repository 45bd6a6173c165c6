#pragma once
// The point tracker's own profile section (`point`: initiation, track life, branching).
// Plain structs in skytrack::config, the profile's namespace (profile.hpp gathers them);
// defaults and ranges in config/README.md.
#include <string>
#include <string_view>
#include <vector>

namespace skytrack::config {

enum class ConfirmationMethod { kMOfN, kExistence };
enum class NonManoeuvreGate { kUnion, kLastMotion };

/// A target's detectability as a two-state Markov chain per scan (Musicki, Evans & Stankovic
/// 1994, IEEE Trans. AC-39(6), "Markov chain two"): detectable, seen with P_D, or hidden
/// (masked by clutter, faded, shadowed), seen with 0.
struct DetectabilitySpec {
  double hide = 0.05;   // P(detectable -> hidden) per scan; 0: misses independent at 1 - P_D
  double reveal = 0.3;  // P(hidden -> detectable) per scan
  bool operator==(const DetectabilitySpec&) const = default;
};

/// M-of-N plot-to-plot initiation with a speed gate.
struct InitiationSpec {
  int m = 3;                 // plots needed ...
  int n = 4;                 // ... within this many consecutive scans
  double min_speed = 0.0;    // [m/s] slower plot pairs are taken as stationary clutter
  double max_speed = 700.0;  // [m/s] faster plot pairs cannot be one target
  // A track whose most likely plot has an association probability above this explains that
  // plot alone; the other plots in its gate may still seed (or extend) chains, e.g. a
  // formation member inside its neighbour's gate. A track without such a plot holds its
  // whole gate. 1: only plots in no gate seed chains.
  double gated_seed_beta = 0.7;
  // The track capacity for tentative tracks: a chain completed while this many are held
  // starts none (counted, reported as an overload event), so a batch of random plots (a
  // jammer, a broken extractor) cannot grow the tracker without bound.
  int max_tentative = 5000;
  bool operator==(const InitiationSpec&) const = default;
};

/// tentative -> confirmed -> coasting -> deleted.
struct TrackLifeSpec {
  // m_of_n: confirmed on M plots in the last N scans. existence: on the probability that
  // the track is a target (IPDA, Musicki et al. 1994), which weighs each plot's likelihood
  // against the clutter density, so chains of clutter plots rarely confirm.
  ConfirmationMethod confirmation = ConfirmationMethod::kExistence;
  int confirm_m = 3;                      // confirmed when M of the last N scans had a plot
  int confirm_n = 4;                      // (counted from the track's first plot)
  double initial_existence = 0.05;        // of a new track, before its chain's later plots
  double confirm_existence = 0.95;        // confirmed at or above
  double delete_existence = 0.02;         // deleted below (tentative or confirmed)
  double survival_probability = 0.98;     // a target is still there one scan later
  int delete_tentative_misses = 2;        // consecutive misses that delete a tentative track
  int delete_confirmed_misses = 5;        // K consecutive misses that delete a confirmed track
  double delete_position_sigma = 2000.0;  // [m] or when sqrt(max eig of P_pos) exceeds this
  bool operator==(const TrackLifeSpec&) const = default;
};

/// Branch ("filiation") tracking, paper 003.
struct BranchingSpec {
  bool enabled = true;
  int max_children = 3;  // sons per father, grandsons per son (paper: 3)
  // The manoeuvre gate is the union of the gates of these models' predictions at this
  // probability; the non-manoeuvre gate uses association.gate_probability.
  double manoeuvre_gate_probability = 0.9999;
  std::vector<std::string> manoeuvre_models = {"cv", "ct_left", "ct_right"};
  // [m/s^2] the manoeuvre gate's models take at least this white acceleration (their own
  // accel_sigma if larger): the range of manoeuvres a target may start between two looks.
  double manoeuvre_accel_sigma = 20.0;
  // A firm father whose non-manoeuvre update weighs two plots each at least this much (and
  // more than a miss), neither the likeliest plot of another father, cannot decide in one
  // frame: the plots start its sons, which decide, while it is still reported. 1: never
  // (the father takes the likelier plot, rule 5).
  double ambiguity_beta = 0.3;
  // A firm father with no valid association in a scan (no plot likelier than its miss)
  // coasts on the motion it was last seen in: its likeliest mode at its latest valid
  // association, predicted alone (IMM mixing blends in the other modes' diverging
  // predictions), and gates non-manoeuvre pairs on it; plots off that motion lie in its
  // manoeuvre gate only and start sons (paper 003 §4.2), whose gate starts from its IMM's
  // own coast. false: the IMM-JPDA update and the union of all modes' gates, and the
  // options below that need it are inert. On by default with them (paper 003 exp. 2 in
  // clutter areas, docs/branch-tracker.md).
  bool coast_on_last_motion = true;
  // A firm father's non-manoeuvre gate: union, the union of its IMM modes' gates; last_motion
  // (needs coast_on_last_motion), its last motion's gate in every scan, not only after a
  // miss (paper 003 §1: a non-manoeuvre association keeps the motion unchanged), so that a
  // plot only a turn mode reaches starts a son instead of turning the father.
  NonManoeuvreGate non_manoeuvre_gate = NonManoeuvreGate::kLastMotion;
  // Where the last motion applies (needs coast_on_last_motion; 0: everywhere): only where its
  // gate expects at least this many false plots (the clutter density at a plot times the
  // gate's volume there), in a clutter area. Elsewhere the father gates on the union and
  // coasts on its IMM, whose turn modes follow a manoeuvre through a missed look.
  double last_motion_false_plots = 0.3;
  // [m/s^2] White acceleration of a held last motion (its gate and its coast), at most each
  // model's own accel_sigma; 0: the model's own. A motion held unchanged over missed looks
  // spreads along the range, which the radar measures to tens of metres, by the model's
  // noise alone (2 m/s^2: 290 m after 40 s), and a wider gate holds more false alarms.
  double last_motion_accel_sigma = 0.5;
  // How a son or grandson started from a manoeuvre pair confirms (rule 10): m_of_n on one
  // more plot (the paper's examples); existence as track_life does (IPDA), from
  // track_life.initial_existence, weighing each later plot against the clutter density
  // round it, so that a clutter area's plots confirm branches slowly.
  ConfirmationMethod confirmation = ConfirmationMethod::kExistence;
  // Coast sons (needs coast_on_last_motion; 0: none): when a firm father takes a plot that
  // may be a false alarm (its clutter density is at least coast_son_doubt of the plot's
  // density under the father and the clutter together), its last motion before that plot
  // stays as a hidden son that rule 5 does not cut: the hypothesis that its target was
  // missed. It coasts and gates on that motion, takes non-manoeuvre pairs, and replaces the
  // father in a look where it takes a plot and its TrackLife::support passes the father's
  // and the father's sons' and grandsons'. At most this many per father (the oldest
  // untouched goes); deleted after track_life.delete_confirmed_misses misses in a row.
  int coast_sons = 5;
  double coast_son_doubt = 0.1;
  // The coast sons' decision window (0: none): a coast son that has not replaced its father
  // within this many looks of its split is pruned, the father's plots then standing (the
  // N-scan pruning of a multi-hypothesis tracker, on the miss-or-false-alarm question).
  int coast_son_looks = 8;
  // The chain by which TrackLife::support, and the branches' scores, count misses where the
  // last motion's gate expects last_motion_false_plots or more (a clutter area, where a
  // target is masked for looks on end): a run of misses there costs less than independent
  // misses at 1 - P_D, so that a coast son that took the target's returning plot can pass a
  // father that took false plots meanwhile. Elsewhere, and in JPDA, existence and the
  // filter everywhere, P_D alone.
  DetectabilitySpec detectability;
  int max_branches_per_father = 12;  // sons + grandsons of one father (3 + 9 at 3 children)
  int max_total_branches = 2000;     // in the whole tracker: bounds time and memory
  bool operator==(const BranchingSpec&) const = default;
};

/// The point tracker's own sections (mode: point): logic-based initiation, track life and
/// branch tracking (paper 003).
struct PointSpec {
  InitiationSpec initiation;
  TrackLifeSpec track_life;
  BranchingSpec branching;
  bool operator==(const PointSpec&) const = default;
};

constexpr std::string_view to_string(ConfirmationMethod method) {
  return method == ConfirmationMethod::kMOfN ? "m_of_n" : "existence";
}

constexpr std::string_view to_string(NonManoeuvreGate gate) {
  return gate == NonManoeuvreGate::kUnion ? "union" : "last_motion";
}

}  // namespace skytrack::config
