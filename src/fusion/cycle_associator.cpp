// One fusion cycle's track-to-track association (src/fusion/cycle_associator.hpp).
#include "cycle_associator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace skytrack::fusion::detail {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

int find_root(std::vector<int>& parent, int x) {
  while (parent[static_cast<std::size_t>(x)] != x) {
    int& p = parent[static_cast<std::size_t>(x)];
    p = parent[static_cast<std::size_t>(p)];
    x = p;
  }
  return x;
}

}  // namespace

CycleAssociator::CycleAssociator(const FusionSpec& spec) : spec_(spec) {
  // Daw >= (1 - beta) D with beta at most w, and D >= min(c, |dx| / sqrt(tr S)) (normalised)
  // or min(c, |dx|) (metres): a pair farther than gamma / (1 - w) can never pass the gate
  // as long as gamma < (1 - w) c. Otherwise every pair must be scored.
  const double w = spec.blend == Blend::kAdaptive ? spec.epsilon : spec.history_weight;
  const bool gate_possible = w < 1.0 && spec.gate < (1.0 - w) * spec.cutoff;
  gate_radius_ = gate_possible ? spec.gate / (1.0 - w) : kInf;
}

void CycleAssociator::find_neighbours(std::span<const PresentTrack> tracks, std::uint64_t cycle,
                                      std::uint64_t window_cycles) {
  const std::size_t n = tracks.size();
  if (neighbours_.size() < n) neighbours_.resize(n);
  for (std::size_t i = 0; i < n; ++i) neighbours_[i].clear();
  by_x_.resize(n);
  std::iota(by_x_.begin(), by_x_.end(), 0);
  const auto x_of = [&](int i) { return tracks[static_cast<std::size_t>(i)].position.mean.x(); };
  std::sort(by_x_.begin(), by_x_.end(),
            [&](int a, int b) { return x_of(a) < x_of(b) || (x_of(a) == x_of(b) && a < b); });
  double sigma2_max = 0.0;
  for (const PresentTrack& t : tracks) sigma2_max = std::max(sigma2_max, t.sigma2);
  const bool normalised = spec_.metric == Metric::kNormalised;
  for (std::size_t ii = 0; ii < n; ++ii) {
    const int i = by_x_[ii];
    const PresentTrack& a = tracks[static_cast<std::size_t>(i)];
    const double reach =
        normalised ? gate_radius_ * std::sqrt(a.sigma2 + sigma2_max) : gate_radius_;
    for (std::size_t jj = ii + 1; jj < n; ++jj) {
      const int j = by_x_[jj];
      const PresentTrack& b = tracks[static_cast<std::size_t>(j)];
      if (b.position.mean.x() - a.position.mean.x() > reach) break;
      if (a.sensor == b.sensor) continue;
      const int dims = std::min(a.position.dims, b.position.dims) >= 3 ? 3 : 2;
      const double dist = (a.position.mean - b.position.mean).head(dims).norm();
      const double radius =
          normalised ? gate_radius_ * std::sqrt(a.sigma2 + b.sigma2) : gate_radius_;
      if (dist > radius) continue;
      const bool labels_differ = a.record->system == 0 || a.record->system != b.record->system;
      const double m = pair_mospa(a.position, b.position, a.record->history, b.record->history,
                                  cycle, window_cycles, labels_differ, spec_);
      neighbours_[static_cast<std::size_t>(i)].push_back({j, m});
      neighbours_[static_cast<std::size_t>(j)].push_back({i, m});
      ++pairs_scored_;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    std::sort(neighbours_[i].begin(), neighbours_[i].end(),
              [](const Neighbour& x, const Neighbour& y) { return x.other < y.other; });
  }
}

double CycleAssociator::mospa_of(int a, int b) const {
  const auto& list = neighbours_[static_cast<std::size_t>(a)];
  const auto it = std::lower_bound(list.begin(), list.end(), b,
                                   [](const Neighbour& x, int v) { return x.other < v; });
  return it != list.end() && it->other == b ? it->mospa : spec_.cutoff;
}

int CycleAssociator::dense_index(std::int64_t system_id, std::int64_t& next_id, bool create) {
  if (create) {
    system_ids_.push_back(next_id++);
    if (members_.size() < system_ids_.size()) members_.resize(system_ids_.size());
    members_[system_ids_.size() - 1].clear();
    decided_sensor_member_.push_back(false);
    return static_cast<int>(system_ids_.size()) - 1;
  }
  const auto it = std::lower_bound(system_ids_.begin(), system_ids_.end(), system_id);
  return static_cast<int>(it - system_ids_.begin());
}

void CycleAssociator::associate(std::span<const PresentTrack> tracks, std::uint64_t cycle,
                                std::uint64_t window_cycles, std::int64_t& next_id,
                                std::vector<std::int64_t>& system_of) {
  pairs_scored_ = 0;
  const std::size_t n = tracks.size();
  system_ids_.clear();
  for (const PresentTrack& t : tracks) {
    if (t.record->system != 0) system_ids_.push_back(t.record->system);
  }
  std::sort(system_ids_.begin(), system_ids_.end());
  system_ids_.erase(std::unique(system_ids_.begin(), system_ids_.end()), system_ids_.end());
  if (members_.size() < system_ids_.size()) members_.resize(system_ids_.size());
  for (std::size_t s = 0; s < system_ids_.size(); ++s) members_[s].clear();
  decided_sensor_member_.assign(system_ids_.size(), false);
  previous_.assign(n, -1);
  for (std::size_t i = 0; i < n; ++i) {
    const std::int64_t id = tracks[i].record->system;
    if (id == 0) continue;
    previous_[i] = dense_index(id, next_id, false);
    members_[static_cast<std::size_t>(previous_[i])].push_back(static_cast<int>(i));
  }
  current_ = previous_;
  find_neighbours(tracks, cycle, window_cycles);
  for (std::size_t begin = 0; begin < n;) {
    std::size_t end = begin;
    while (end < n && tracks[end].sensor == tracks[begin].sensor) ++end;
    decide_sensor(tracks, static_cast<int>(begin), static_cast<int>(end), next_id);
    begin = end;
  }
  system_of.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    system_of[i] = system_ids_[static_cast<std::size_t>(current_[i])];
  }
}

void CycleAssociator::decide_sensor(std::span<const PresentTrack> tracks, int begin, int end,
                                    std::int64_t& next_id) {
  const std::uint32_t sensor = tracks[static_cast<std::size_t>(begin)].sensor;
  edges_.clear();
  for (int i = begin; i < end; ++i) {
    const std::size_t row_start = edges_.size();
    for (const Neighbour& nb : neighbours_[static_cast<std::size_t>(i)]) {
      const int s = current_[static_cast<std::size_t>(nb.other)];
      if (s < 0) continue;
      const bool seen = std::any_of(edges_.begin() + static_cast<std::ptrdiff_t>(row_start),
                                    edges_.end(), [s](const Edge& e) { return e.column == s; });
      if (seen) continue;
      double sum = 0.0;
      int count = 0;
      for (const int m : members_[static_cast<std::size_t>(s)]) {
        if (tracks[static_cast<std::size_t>(m)].sensor == sensor) continue;
        sum += mospa_of(i, m);
        ++count;
      }
      if (count > 0 && sum / count < spec_.gate) edges_.push_back({i, s, sum / count});
    }
  }
  solve_components(begin, end);
  const auto move_to = [&](int i, int s) {
    int& cur = current_[static_cast<std::size_t>(i)];
    if (cur != s) {
      if (cur >= 0) std::erase(members_[static_cast<std::size_t>(cur)], i);
      members_[static_cast<std::size_t>(s)].push_back(i);
      cur = s;
    }
    decided_sensor_member_[static_cast<std::size_t>(s)] = true;
  };
  for (int i = begin; i < end; ++i) {
    const int s = assigned_[static_cast<std::size_t>(i - begin)];
    if (s >= 0) move_to(i, s);
  }
  for (int i = begin; i < end; ++i) {
    if (assigned_[static_cast<std::size_t>(i - begin)] >= 0) continue;
    const int p = previous_[static_cast<std::size_t>(i)];
    if (p >= 0 && !decided_sensor_member_[static_cast<std::size_t>(p)]) {
      move_to(i, p);
    } else {
      move_to(i, dense_index(0, next_id, true));
    }
  }
}

void CycleAssociator::solve_components(int begin, int end) {
  const int rows = end - begin;
  assigned_.assign(static_cast<std::size_t>(rows), -1);
  if (edges_.empty()) return;
  // Union-find over rows [0, rows) and the dense system indices shifted by rows.
  int max_column = 0;
  for (const Edge& e : edges_) max_column = std::max(max_column, e.column);
  parent_.resize(static_cast<std::size_t>(rows + max_column + 1));
  std::iota(parent_.begin(), parent_.end(), 0);
  for (const Edge& e : edges_) {
    const int a = find_root(parent_, e.row - begin);
    const int b = find_root(parent_, rows + e.column);
    if (a != b) parent_[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
  }
  std::sort(edges_.begin(), edges_.end(), [&](const Edge& x, const Edge& y) {
    const int rx = find_root(parent_, x.row - begin), ry = find_root(parent_, y.row - begin);
    return rx < ry || (rx == ry && (x.row < y.row || (x.row == y.row && x.column < y.column)));
  });
  for (std::size_t first = 0; first < edges_.size();) {
    const int root = find_root(parent_, edges_[first].row - begin);
    std::size_t last = first;
    while (last < edges_.size() && find_root(parent_, edges_[last].row - begin) == root) ++last;
    if (last - first == 1) {  // the common case: one track, one system track
      assigned_[static_cast<std::size_t>(edges_[first].row - begin)] = edges_[first].column;
      first = last;
      continue;
    }
    component_rows_.clear();
    component_columns_.clear();
    for (std::size_t k = first; k < last; ++k) {
      component_rows_.push_back(edges_[k].row);
      component_columns_.push_back(edges_[k].column);
    }
    for (auto* v : {&component_rows_, &component_columns_}) {
      std::sort(v->begin(), v->end());
      v->erase(std::unique(v->begin(), v->end()), v->end());
    }
    const auto local = [](const std::vector<int>& v, int x) {
      return static_cast<Eigen::Index>(std::lower_bound(v.begin(), v.end(), x) - v.begin());
    };
    cost_.setConstant(static_cast<Eigen::Index>(component_rows_.size()),
                      static_cast<Eigen::Index>(component_columns_.size()), kInf);
    for (std::size_t k = first; k < last; ++k) {
      cost_(local(component_rows_, edges_[k].row), local(component_columns_, edges_[k].column)) =
          edges_[k].cost;
    }
    const AssignmentResult& r = solver_.solve(cost_);
    for (std::size_t row = 0; row < component_rows_.size(); ++row) {
      const int col = r.row_to_col[row];
      if (col >= 0) {
        assigned_[static_cast<std::size_t>(component_rows_[row] - begin)] =
            component_columns_[static_cast<std::size_t>(col)];
      }
    }
    first = last;
  }
}

}  // namespace skytrack::fusion::detail
