#pragma once
// Exact JPDA marginal association probabilities of one cluster (paper 003 eq. 8-9;
// Fortmann, Bar-Shalom & Scheffe 1983) WITHOUT enumerating the feasible joint events.
//
// Method: dynamic programming over the tracks in a fixed order; the state after k tracks is
// the set S of plots they used. This is the memoised depth-first recursion over tracks
// keyed by the used set, evaluated level by level, with two reductions, both exact:
//  (1) only SHARED plots (gated by >= 2 tracks) enter the key: a plot only one track can
//      take never conflicts, so its weight joins that track's miss weight ("stay" edge);
//  (2) the key at level k keeps only the shared plots some track at level >= k can still
//      use (the frontier F_k); states that differ elsewhere have the same completions and
//      merge. F_k is kept small by ordering the tracks greedily (least frontier first).
// With forward sums f(k, S) over partial events of the first k tracks and backward sums
// g(k, S) over completions (g is the memo table of the recursion), for the k-th track t
//   Z        = g(0, {}) = sum over all feasible joint events of their weight,
//   beta_t0  = sum_S f(k, S) miss_t g(k+1, S & F_{k+1}) / Z,
//   beta_tj  = sum_{S: j not in S} f(k, S) w_tj g(k+1, (S | j) & F_{k+1}) / Z,
// (for a plot only t gates, S | j is S). Rows sum to 1 because sum_S f(k,S) g(k,S) = Z.
// Key bits: a shared plot is live from the first to the last position of a track gating it;
// plots with disjoint live intervals share a bit (interval colouring, greedy by start,
// optimal), so the cluster may have any number of shared plots as long as at most 64 are
// live at once.
//
// Complexity: time and memory O(sum_k |states_k| * (1 + s_k)), s_k = shared plots of the
// k-th track, |states_k| <= sum_{i <= min(k, |F_k|)} C(|F_k|, i) <= 2^|F_k|, plus
// O(T P + T sum_t s_t) to classify plots and order the tracks. A chain of tracks in which
// neighbours share c plots has |F_k| ~ c, so the cost is linear in the number of tracks where
// enumeration is exponential (prod_t (1 + gated_t) events). Limits: at most 64 shared plots live at
// once (the key is one 64-bit word) and a caller-given bound on the number of states; beyond
// either, compute() returns completed = false and the caller falls back to an approximation.
// Measured on the dev box: 0.1-0.3 us per state (hash look-ups dominate).
//
// Buffers are kept between calls: after warm-up on the largest cluster, no allocation.
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

namespace skytrack {

struct JpdaExactOutcome {
  bool completed = false;     // false: > 64 live plots or > max_states states; beta untouched
  double total_weight = 0.0;  // Z, the summed weight of all feasible joint events
  std::int64_t events = 0;    // number of feasible joint events (saturates at INT64_MAX)
  std::int64_t states = 0;    // (level, key) states created
  int shared_plots = 0;       // plots gated by >= 2 tracks
  int key_bits = 0;           // bits of the key after interval colouring (> 64: gave up)
  int max_frontier = 0;       // max_k |F_k|; states per level <= 2^max_frontier
};

class JpdaExact {
 public:
  static constexpr int kMaxKeyBits = 64;

  /// weights: tracks x (1 + plots), column 0 = weight of "undetected", column 1 + j = weight
  /// of plot j; entries >= 0 and finite, 0 = infeasible (not gated). beta (same shape) gets
  /// the marginals when completed and Z > 0.
  JpdaExactOutcome compute(const Eigen::Ref<const Eigen::MatrixXd>& weights,
                           std::int64_t max_states, Eigen::Ref<Eigen::MatrixXd> beta) noexcept;

  /// compute() in two parts. plan() classifies the plots, orders the tracks and colours the
  /// key bits; run() makes the states and the marginals of the same `weights`. Between them
  /// planned_states() bounds what the run can make. `unused_events`, one per plot column
  /// (weights column 1 + j), is the number of joint events a plot stands for when no track
  /// takes it (empty: 1 each); it changes only the events count (JpdaByPlots uses it).
  void plan(const Eigen::Ref<const Eigen::MatrixXd>& weights,
            std::span<const std::int64_t> unused_events = {}) noexcept;
  JpdaExactOutcome run(const Eigen::Ref<const Eigen::MatrixXd>& weights, std::int64_t max_states,
                       Eigen::Ref<Eigen::MatrixXd> beta) noexcept;
  /// An upper bound on the states of the planned run: level k + 1 holds at most the subsets of
  /// |F_k| live bits with at most k + 1 members (+infinity when the key does not fit).
  double planned_states() const noexcept { return planned_states_; }

 private:
  struct Step {  // one track, in processing order
    int track = 0;
    double stay = 0.0;             // miss + private plot weights (key unchanged)
    std::int64_t stay_events = 0;  // the joint events those stand for
    std::int64_t edge_events = 1;  // the events a shared edge stands for (private plots unused)
    int leave_begin = 0;           // shared plots whose last track this is, in leaving_
    int leave_count = 0;
    int edge_begin = 0;  // its shared plots in edges_
    int edge_count = 0;
  };
  struct Edge {
    std::uint64_t bit = 0;
    int column = 0;  // column in weights (1 + plot)
    double weight = 0.0;
  };
  struct Leaving {  // a shared plot no later track gates, standing for `events` if unused
    std::uint64_t bit = 0;
    std::int64_t events = 1;
  };
  struct Slot {
    std::uint64_t key = 0;
    int index = 0;
    std::uint32_t stamp = 0;
  };

  /// compute() for a cluster of one track: it shares no plot, so its one step is the stay
  /// edge; the same sums in the same order, without building the graph.
  JpdaExactOutcome one_track(const Eigen::Ref<const Eigen::MatrixXd>& weights,
                             std::int64_t max_states, Eigen::Ref<Eigen::MatrixXd> beta) noexcept;
  /// True when some level must hold more than max_states states, so the forward pass would
  /// stop at the bound: skipping it gives the stopped pass's outcome without its work.
  bool must_stop(std::int64_t max_states) noexcept;
  void classify_plots(const Eigen::Ref<const Eigen::MatrixXd>& weights) noexcept;
  void order_tracks() noexcept;
  bool assign_key_bits() noexcept;
  void build_steps(const Eigen::Ref<const Eigen::MatrixXd>& weights) noexcept;
  bool forward(std::int64_t max_states) noexcept;
  void expand(int level, int state) noexcept;
  void backward() noexcept;
  void marginals(const Eigen::Ref<const Eigen::MatrixXd>& weights, double z,
                 Eigen::Ref<Eigen::MatrixXd> beta) const noexcept;
  void start_level() noexcept;
  int find_or_insert(std::uint64_t key) noexcept;
  void grow_table() noexcept;
  std::int64_t unused(int column) const noexcept;  // unused_events of a weights column
  /// The events a row's stay edge and its shared edges stand for, from its private plots.
  void count_private(const Eigen::Ref<const Eigen::MatrixXd>& weights, int t, Step& step) noexcept;
  void plan_states() noexcept;

  int tracks_ = 0;
  int columns_ = 0;
  std::vector<int> shared_column_;   // weights column of each shared plot
  std::vector<char> column_shared_;  // per weights column
  std::vector<int> track_begin_;     // CSR: shared plots of track t are
  std::vector<int> track_shared_;    //   track_shared_[track_begin_[t] .. [t + 1])
  std::vector<int> remaining_;       // per shared plot: unplaced tracks gating it
  std::vector<char> touched_;
  std::vector<int> order_;  // processing order of the tracks
  std::vector<char> placed_;
  std::vector<int> first_, last_, slot_;  // per shared plot: live interval, key bit
  std::vector<char> claimed_;             // must_stop: a live plot given to a placed track
  std::vector<int> taken_;                // must_stop: live plots given to each placed track
  std::vector<std::uint64_t> keep_;       // key bits still live after the k-th track
  std::vector<Step> steps_;
  std::vector<Edge> edges_;
  std::vector<std::int64_t> unused_events_;  // per plot column; empty: 1 each
  std::vector<Leaving> leaving_;
  std::int64_t root_events_ = 1;  // the plots no track gates, unused in every event
  bool planned_ok_ = false;       // the key fits (at most 64 live plots)
  double planned_states_ = 0.0;
  std::vector<int> level_begin_;  // states of level k: [begin_k, begin_{k+1})
  std::vector<int> succ_begin_;   // successors of level k start here in succ_
  std::vector<std::uint64_t> keys_;
  std::vector<double> f_, g_;
  std::vector<std::int64_t> events_;
  std::vector<int> succ_;    // per state: stay edge, then each shared edge
  std::vector<Slot> table_;  // open addressing, key -> state, one level
  std::uint32_t stamp_ = 0;
  int level_start_ = 0;
  int level_size_ = 0;
  int key_bits_ = 0;
  int max_frontier_ = 0;
};

}  // namespace skytrack
