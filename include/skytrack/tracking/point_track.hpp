#pragma once
// A track of the point tracker: a father (reported) or, with branching (paper 003), one of its
// hidden sons and grandsons; its life, IMM estimate and branch-layer state.
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "skytrack/filter/imm_filter.hpp"
#include "skytrack/measurement/plot_measurement.hpp"
#include "skytrack/tracking/branch_tree.hpp"
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
  double score = 0.0;  // a branch's summed log pair probabilities: the least likely is pruned
  double pair_probability = 0.0;  // a branch's latest pair's association probability
  bool replaced = false;          // a father a branch replaced: dropped without a report
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

}  // namespace skytrack
