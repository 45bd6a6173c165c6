// The exact JPDA's plan (jpda_exact.hpp): which plots are shared, the order the tracks are
// placed in, the key bits of the live shared plots, each step's edges, and the bounds on the
// states the forward pass will hold.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <limits>

#include "jpda_exact_detail.hpp"
#include "jpda_input.hpp"
#include "skytrack/association/jpda_exact.hpp"

namespace skytrack {

using namespace jpda_exact_detail;

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

}  // namespace skytrack
