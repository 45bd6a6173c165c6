// Exact JPDA marginals by dynamic programming over (track, used shared plots); see
// jpda_exact.hpp for the recursion (paper 003 eq. 8-9) and its complexity.
#include "skytrack/association/jpda_exact.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <limits>

#include "jpda_exact_detail.hpp"

namespace skytrack {

using namespace jpda_exact_detail;

namespace {

constexpr std::size_t kInitialSlots = 64;

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
