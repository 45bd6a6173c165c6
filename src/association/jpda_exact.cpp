// Exact JPDA marginals by dynamic programming over (track, used shared plots); see
// jpda_exact.hpp for the recursion (paper 003 eq. 8-9) and its complexity.
#include "skytrack/association/jpda_exact.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <limits>

#include "jpda_input.hpp"

namespace skytrack {
namespace {

constexpr std::int64_t kMaxCount = std::numeric_limits<std::int64_t>::max();
constexpr std::size_t kInitialSlots = 64;

std::size_t at(int i) {
  return static_cast<std::size_t>(i);
}

std::int64_t saturating_add(std::int64_t a, std::int64_t b) {
  std::int64_t r = 0;
  return __builtin_add_overflow(a, b, &r) ? kMaxCount : r;
}

std::int64_t saturating_mul(std::int64_t a, std::int64_t b) {
  std::int64_t r = 0;
  return __builtin_mul_overflow(a, b, &r) ? kMaxCount : r;
}

std::size_t slot_of(std::uint64_t key, std::size_t mask) {
  std::uint64_t h = key * 0x9E3779B97F4A7C15ULL;  // Fibonacci hashing, high bits folded down
  h ^= h >> 29;
  return static_cast<std::size_t>(h) & mask;
}

}  // namespace

JpdaExactOutcome JpdaExact::compute(const Eigen::Ref<const Eigen::MatrixXd>& weights,
                                    std::int64_t max_states,
                                    Eigen::Ref<Eigen::MatrixXd> beta) noexcept {
  plan(weights);
  return run(weights, max_states, beta);
}

void JpdaExact::plan(const Eigen::Ref<const Eigen::MatrixXd>& weights,
                     std::span<const std::int64_t> unused_events) noexcept {
  tracks_ = static_cast<int>(weights.rows());
  columns_ = static_cast<int>(weights.cols());
  unused_events_.assign(unused_events.begin(), unused_events.end());
  planned_ok_ = true;
  planned_states_ = 2.0;
  if (tracks_ == 1) return;
  classify_plots(weights);
  order_tracks();
  planned_ok_ = assign_key_bits();
  if (!planned_ok_) {
    planned_states_ = std::numeric_limits<double>::infinity();
    return;
  }
  build_steps(weights);
  plan_states();
}

JpdaExactOutcome JpdaExact::run(const Eigen::Ref<const Eigen::MatrixXd>& weights,
                                std::int64_t max_states,
                                Eigen::Ref<Eigen::MatrixXd> beta) noexcept {
  if (tracks_ == 1) return one_track(weights, max_states, beta);
  JpdaExactOutcome outcome;
  outcome.shared_plots = static_cast<int>(shared_column_.size());
  if (!planned_ok_) {
    outcome.key_bits = kMaxKeyBits + 1;
    return outcome;
  }
  outcome.key_bits = key_bits_;
  outcome.max_frontier = max_frontier_;
  if (must_stop(max_states)) return outcome;
  const bool done = forward(max_states);
  outcome.states = static_cast<std::int64_t>(keys_.size());
  if (!done) return outcome;
  backward();
  outcome.completed = true;
  const int terminal = level_begin_[at(tracks_)];
  const bool any = terminal < static_cast<int>(keys_.size());
  outcome.events = any ? events_[at(terminal)] : 0;
  outcome.total_weight = g_.empty() ? 0.0 : g_[0];
  if (outcome.total_weight > 0.0) marginals(weights, outcome.total_weight, beta);
  return outcome;
}

std::int64_t JpdaExact::unused(int column) const noexcept {
  return unused_events_.empty() ? 1 : unused_events_[at(column - 1)];
}

// A row's private plots (gated by it alone), each standing for unused(c) events when not
// taken: its stay edge stands for [miss] prod_c u_c + sum_c prod_{c' != c} u_c' events, a
// shared edge for prod_c u_c. With every u_c = 1: [miss] + (private plots) and 1.
void JpdaExact::count_private(const Eigen::Ref<const Eigen::MatrixXd>& weights, int t,
                              Step& step) noexcept {
  std::int64_t all = 1, one_taken = 0;
  for (int c = 1; c < columns_; ++c) {
    const double w = weights(t, c);
    if (!(w > 0.0) || (tracks_ > 1 && column_shared_[at(c)] != 0)) continue;
    step.stay += w;
    one_taken = saturating_add(saturating_mul(one_taken, unused(c)), all);
    all = saturating_mul(all, unused(c));
  }
  step.stay_events = saturating_add(weights(t, 0) > 0.0 ? all : 0, one_taken);
  step.edge_events = all;
}

JpdaExactOutcome JpdaExact::one_track(const Eigen::Ref<const Eigen::MatrixXd>& weights,
                                      std::int64_t max_states,
                                      Eigen::Ref<Eigen::MatrixXd> beta) noexcept {
  JpdaExactOutcome outcome;
  Step step;
  step.stay = weights(0, 0);
  count_private(weights, 0, step);
  const double stay = step.stay;
  // The root and, when any event has weight, the terminal state.
  outcome.states = stay > 0.0 ? 2 : 1;
  if (outcome.states > max_states) return outcome;
  outcome.completed = true;
  if (!(stay > 0.0)) return outcome;
  std::int64_t events = step.stay_events;
  for (int c = 1; c < columns_; ++c) {
    if (!(weights(0, c) > 0.0)) events = saturating_mul(events, unused(c));
  }
  outcome.events = events;
  outcome.total_weight = stay;
  beta.setZero();
  for (int c = 0; c < columns_; ++c) {
    if (c == 0 || weights(0, c) > 0.0) beta(0, c) = weights(0, c);
  }
  beta.row(0) /= stay;
  return outcome;
}

// A lower bound on each level's states: placed tracks with disjoint sets S_i of live plots
// they gate reach at least prod (1 + |S_i|) distinct keys (each misses or takes one plot of
// its S_i, the others miss; live plots have distinct key bits). Levels whose bounds sum past
// max_states prove that the forward pass would stop at the bound. Checked only when a level
// could hold that many (a frontier wider than log2(max_states / tracks)) and every track
// can miss (stay > 0).
bool JpdaExact::must_stop(std::int64_t max_states) noexcept {
  if (!(std::ldexp(1.0, max_frontier_) * tracks_ > static_cast<double>(max_states))) return false;
  for (const Step& step : steps_) {
    if (!(step.stay > 0.0)) return false;
  }
  double total = 1.0;  // the root; the pass stops when all its levels together exceed the bound
  for (int k = 0; k < tracks_; ++k) {
    // Round by round each placed track claims one more live plot of its own: balanced sets
    // give a larger product than one track taking all it gates.
    claimed_.assign(shared_column_.size(), 0);
    taken_.assign(at(k + 1), 0);
    for (bool any = true; any;) {
      any = false;
      for (int j = 0; j <= k; ++j) {
        const int t = order_[at(j)];
        for (int i = track_begin_[at(t)]; i < track_begin_[at(t + 1)]; ++i) {
          const int p = track_shared_[at(i)];
          if (last_[at(p)] > k && claimed_[at(p)] == 0) {  // gated by a track still to come
            claimed_[at(p)] = 1;
            ++taken_[at(j)];
            any = true;
            break;
          }
        }
      }
    }
    double states = 1.0;
    for (int j = 0; j <= k; ++j) states *= 1.0 + taken_[at(j)];
    total += states;
    if (total > static_cast<double>(max_states)) return true;
  }
  return false;
}

// Shared plots (gated by >= 2 tracks) get an index and per-track lists (CSR).
void JpdaExact::classify_plots(const Eigen::Ref<const Eigen::MatrixXd>& weights) noexcept {
  detail::find_shared_plots(weights, shared_column_, column_shared_);
  track_begin_.assign(at(tracks_ + 1), 0);
  track_shared_.clear();
  for (int t = 0; t < tracks_; ++t) {
    for (int p = 0; p < static_cast<int>(shared_column_.size()); ++p) {
      if (weights(t, shared_column_[at(p)]) > 0.0) track_shared_.push_back(p);
    }
    track_begin_[at(t + 1)] = static_cast<int>(track_shared_.size());
  }
}

// Greedy order: next is the track whose placement grows the frontier (shared plots touched
// by placed tracks and still gated by unplaced ones) least; ties go to the lowest index.
// Placing t changes the frontier by sum over its plots of [others still gate p] - [p touched].
void JpdaExact::order_tracks() noexcept {
  const std::size_t shared = shared_column_.size();
  remaining_.assign(shared, 0);
  touched_.assign(shared, 0);
  for (int p : track_shared_) ++remaining_[at(p)];
  order_.clear();
  placed_.assign(at(tracks_), 0);
  for (int k = 0; k < tracks_; ++k) {
    int best = -1;
    int best_delta = std::numeric_limits<int>::max();
    for (int t = 0; t < tracks_; ++t) {
      if (placed_[at(t)] != 0) continue;
      int delta = 0;
      for (int i = track_begin_[at(t)]; i < track_begin_[at(t + 1)]; ++i) {
        const int p = track_shared_[at(i)];
        delta += (remaining_[at(p)] > 1 ? 1 : 0) - (touched_[at(p)] != 0 ? 1 : 0);
      }
      if (delta < best_delta) {
        best = t;
        best_delta = delta;
      }
    }
    placed_[at(best)] = 1;
    order_.push_back(best);
    for (int i = track_begin_[at(best)]; i < track_begin_[at(best + 1)]; ++i) {
      const int p = track_shared_[at(i)];
      --remaining_[at(p)];
      touched_[at(p)] = 1;
    }
  }
}

// Key bits by interval colouring: shared plot p is live from the first to the last position
// (in the order) of a track gating it; plots whose live intervals are disjoint share a bit.
// Greedy by start position is optimal for interval graphs; fails beyond 64 live plots.
bool JpdaExact::assign_key_bits() noexcept {
  const std::size_t shared = shared_column_.size();
  first_.assign(shared, -1);
  last_.assign(shared, -1);
  for (int k = 0; k < tracks_; ++k) {
    const int t = order_[at(k)];
    for (int i = track_begin_[at(t)]; i < track_begin_[at(t + 1)]; ++i) {
      const int p = track_shared_[at(i)];
      if (first_[at(p)] < 0) first_[at(p)] = k;
      last_[at(p)] = k;
    }
  }
  std::array<int, kMaxKeyBits> busy_until{};
  busy_until.fill(-1);
  slot_.assign(shared, -1);
  key_bits_ = 0;
  for (int k = 0; k < tracks_; ++k) {
    const int t = order_[at(k)];
    for (int i = track_begin_[at(t)]; i < track_begin_[at(t + 1)]; ++i) {
      const int p = track_shared_[at(i)];
      if (first_[at(p)] != k) continue;
      int slot = 0;
      while (slot < kMaxKeyBits && busy_until[at(slot)] >= k) ++slot;
      if (slot == kMaxKeyBits) return false;
      busy_until[at(slot)] = last_[at(p)];
      slot_[at(p)] = slot;
      key_bits_ = std::max(key_bits_, slot + 1);
    }
  }
  keep_.assign(at(tracks_), 0);  // keep_[k]: bits still live after the k-th track
  for (std::size_t p = 0; p < shared; ++p) {
    for (int k = first_[p]; k < last_[p]; ++k) keep_[at(k)] |= std::uint64_t{1} << slot_[p];
  }
  return true;
}

void JpdaExact::build_steps(const Eigen::Ref<const Eigen::MatrixXd>& weights) noexcept {
  steps_.clear();
  edges_.clear();
  leaving_.clear();
  max_frontier_ = 0;
  root_events_ = 1;
  for (int c = 1; c < columns_; ++c) {  // plots no track gates
    bool gated = false;
    for (int t = 0; t < tracks_ && !gated; ++t) gated = weights(t, c) > 0.0;
    if (!gated) root_events_ = saturating_mul(root_events_, unused(c));
  }
  for (int k = 0; k < tracks_; ++k) {
    const int t = order_[at(k)];
    Step step;
    step.track = t;
    step.stay = weights(t, 0);
    count_private(weights, t, step);  // private plots: the key does not change
    step.edge_begin = static_cast<int>(edges_.size());
    step.leave_begin = static_cast<int>(leaving_.size());
    for (int i = track_begin_[at(t)]; i < track_begin_[at(t + 1)]; ++i) {
      const int p = track_shared_[at(i)];
      const int c = shared_column_[at(p)];
      const std::uint64_t bit = std::uint64_t{1} << slot_[at(p)];
      edges_.push_back({bit, c, weights(t, c)});
      if (last_[at(p)] == k && unused(c) != 1) leaving_.push_back({bit, unused(c)});
    }
    step.edge_count = static_cast<int>(edges_.size()) - step.edge_begin;
    step.leave_count = static_cast<int>(leaving_.size()) - step.leave_begin;
    steps_.push_back(step);
    max_frontier_ = std::max(max_frontier_, std::popcount(keep_[at(k)]));
  }
}

void JpdaExact::plan_states() noexcept {
  planned_states_ = 1.0;
  for (int k = 0; k < tracks_; ++k) {
    const int live = std::popcount(keep_[at(k)]);
    double subsets = 0.0, choose = 1.0;  // sum_{i <= min(k + 1, live)} C(live, i)
    for (int i = 0; i <= std::min(k + 1, live); ++i) {
      subsets += choose;
      choose = choose * (live - i) / (i + 1);
    }
    planned_states_ += subsets;
  }
}

void JpdaExact::start_level() noexcept {
  if (table_.empty()) table_.resize(kInitialSlots);
  if (++stamp_ == 0) {  // wrapped: clear the stamps once every 2^32 levels
    for (Slot& slot : table_) slot.stamp = 0;
    stamp_ = 1;
  }
  level_start_ = static_cast<int>(keys_.size());
  level_size_ = 0;
}

int JpdaExact::find_or_insert(std::uint64_t key) noexcept {
  if (2 * at(level_size_ + 1) > table_.size()) grow_table();
  const std::size_t mask = table_.size() - 1;
  std::size_t i = slot_of(key, mask);
  while (table_[i].stamp == stamp_) {
    if (table_[i].key == key) return table_[i].index;
    i = (i + 1) & mask;
  }
  const int index = static_cast<int>(keys_.size());
  table_[i] = {key, index, stamp_};
  keys_.push_back(key);
  f_.push_back(0.0);
  events_.push_back(0);
  ++level_size_;
  return index;
}

// Doubles the table and re-inserts the current level (its states are contiguous in keys_).
void JpdaExact::grow_table() noexcept {
  table_.assign(table_.size() * 2, Slot{});
  stamp_ = 1;
  const std::size_t mask = table_.size() - 1;
  for (int s = level_start_; s < static_cast<int>(keys_.size()); ++s) {
    std::size_t i = slot_of(keys_[at(s)], mask);
    while (table_[i].stamp == stamp_) i = (i + 1) & mask;
    table_[i] = {keys_[at(s)], s, stamp_};
  }
}

bool JpdaExact::forward(std::int64_t max_states) noexcept {
  keys_.clear();
  f_.clear();
  events_.clear();
  succ_.clear();
  level_begin_.assign(at(tracks_ + 2), 0);
  succ_begin_.assign(at(tracks_ + 1), 0);
  start_level();
  const int root = find_or_insert(0);
  f_[at(root)] = 1.0;
  events_[at(root)] = root_events_;
  for (int k = 0; k < tracks_; ++k) {
    const int end = static_cast<int>(keys_.size());
    level_begin_[at(k + 1)] = end;
    succ_begin_[at(k)] = static_cast<int>(succ_.size());
    start_level();
    for (int s = level_begin_[at(k)]; s < end; ++s) {
      expand(k, s);
      if (static_cast<std::int64_t>(keys_.size()) > max_states) return false;
    }
  }
  level_begin_[at(tracks_ + 1)] = static_cast<int>(keys_.size());
  return true;
}

// Successors of one state of level k: the stay edge, then one per shared plot (-1 = none).
// A shared plot this track is the last to gate leaves the key: untaken, it stands for its
// unused events.
void JpdaExact::expand(int k, int s) noexcept {
  const Step& step = steps_[at(k)];
  const std::uint64_t used = keys_[at(s)];
  const std::uint64_t keep = keep_[at(k)];
  const double f = f_[at(s)];
  const std::int64_t events = events_[at(s)];
  const auto left_unused = [&](std::uint64_t taken, std::int64_t n) {
    for (int i = step.leave_begin; i < step.leave_begin + step.leave_count; ++i) {
      if ((taken & leaving_[at(i)].bit) == 0) n = saturating_mul(n, leaving_[at(i)].events);
    }
    return n;
  };
  int next = -1;
  if (step.stay > 0.0) {
    next = find_or_insert(used & keep);
    f_[at(next)] += f * step.stay;
    events_[at(next)] = saturating_add(events_[at(next)],
                                       left_unused(used, saturating_mul(events, step.stay_events)));
  }
  succ_.push_back(next);
  for (int e = step.edge_begin; e < step.edge_begin + step.edge_count; ++e) {
    const Edge& edge = edges_[at(e)];
    next = -1;
    if ((used & edge.bit) == 0) {
      next = find_or_insert((used | edge.bit) & keep);
      f_[at(next)] += f * edge.weight;
      events_[at(next)] =
          saturating_add(events_[at(next)],
                         left_unused(used | edge.bit, saturating_mul(events, step.edge_events)));
    }
    succ_.push_back(next);
  }
}

void JpdaExact::backward() noexcept {
  g_.assign(keys_.size(), 0.0);
  const int terminal = level_begin_[at(tracks_)];
  if (terminal < static_cast<int>(keys_.size())) g_[at(terminal)] = 1.0;  // the key {} only
  for (int k = tracks_ - 1; k >= 0; --k) {
    const Step& step = steps_[at(k)];
    const int width = 1 + step.edge_count;
    const int begin = level_begin_[at(k)];
    for (int s = begin; s < level_begin_[at(k + 1)]; ++s) {
      const int* next = &succ_[at(succ_begin_[at(k)] + (s - begin) * width)];
      double g = next[0] >= 0 ? step.stay * g_[at(next[0])] : 0.0;
      for (int e = 0; e < step.edge_count; ++e) {
        if (next[1 + e] >= 0) g += edges_[at(step.edge_begin + e)].weight * g_[at(next[1 + e])];
      }
      g_[at(s)] = g;
    }
  }
}

void JpdaExact::marginals(const Eigen::Ref<const Eigen::MatrixXd>& weights, double z,
                          Eigen::Ref<Eigen::MatrixXd> beta) const noexcept {
  beta.setZero();
  for (int k = 0; k < tracks_; ++k) {
    const Step& step = steps_[at(k)];
    const int t = step.track;
    const int width = 1 + step.edge_count;
    const int begin = level_begin_[at(k)];
    double stay = 0.0;  // sum_S f(k, S) g(k+1, S & F_{k+1})
    for (int s = begin; s < level_begin_[at(k + 1)]; ++s) {
      const int* next = &succ_[at(succ_begin_[at(k)] + (s - begin) * width)];
      const double f = f_[at(s)];
      if (next[0] >= 0) stay += f * g_[at(next[0])];
      for (int e = 0; e < step.edge_count; ++e) {
        const Edge& edge = edges_[at(step.edge_begin + e)];
        if (next[1 + e] >= 0) beta(t, edge.column) += f * edge.weight * g_[at(next[1 + e])];
      }
    }
    beta(t, 0) = weights(t, 0) * stay;
    for (int c = 1; c < columns_; ++c) {
      if (column_shared_[at(c)] == 0 && weights(t, c) > 0.0) beta(t, c) = weights(t, c) * stay;
    }
    beta.row(t) /= z;
  }
}

}  // namespace skytrack
