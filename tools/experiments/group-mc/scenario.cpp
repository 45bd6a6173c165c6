// Paper 000 §4.1 and §4.2 scenarios; the readings of the paper are in docs/group.md.
#include "scenario.hpp"

#include <cmath>
#include <numbers>
#include <random>

namespace group_mc {
namespace {

using skytrack::group::BoxMat;
using skytrack::group::group_transition;
using skytrack::group::GroupMotion;

void propagate(TruthGroup& g, const ScenarioSpec& s, std::mt19937_64& rng) {
  const BoxMat F = group_transition(GroupMotion::kCoordinatedTurn, s.turn_rate, s.dt);
  std::normal_distribution<double> noise(0.0, s.process_sigma);
  for (int k = g.first + 1; k <= g.last; ++k) {
    BoxVec x = F * g.state[static_cast<std::size_t>(k - 2)];
    const double ax = noise(rng);
    const double ay = noise(rng);
    x(0) += 0.5 * s.dt * s.dt * ax;
    x(1) += s.dt * ax;
    x(2) += 0.5 * s.dt * s.dt * ay;
    x(3) += s.dt * ay;
    g.state[static_cast<std::size_t>(k - 1)] = x;
  }
}

TruthGroup start(int id, int first, int last, const BoxVec& x0, int scans) {
  TruthGroup g;
  g.id = id;
  g.first = first;
  g.last = last;
  g.state.assign(static_cast<std::size_t>(scans), BoxVec::Constant(std::nan("")));
  g.state[static_cast<std::size_t>(first - 1)] = x0;
  return g;
}

void make_scans(Scenario& sc, std::mt19937_64& rng) {
  const ScenarioSpec& s = sc.spec;
  std::uniform_real_distribution<double> spread(-s.half_spread, s.half_spread);
  std::uniform_real_distribution<double> area(-s.area_half, s.area_half);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, s.measurement_sigma);
  for (int k = 1; k <= s.scans; ++k) {
    Scan scan;
    scan.time = (k - 1) * s.dt;
    for (const TruthGroup& g : sc.groups) {
      if (!g.alive(k)) {
        continue;
      }
      if (unit(rng) >= s.group_detection) {
        scan.missed.push_back(g.id);
        continue;
      }
      const BoxVec& x = g.state[static_cast<std::size_t>(k - 1)];
      const int n = std::poisson_distribution<int>(g.plot_rate)(rng);
      for (int i = 0; i < n; ++i) {
        // One draw per statement: the order of a sum's operands is unspecified in C++.
        const double spread_x = spread(rng);
        const double px = x(0) + spread_x + noise(rng);
        const double spread_y = spread(rng);
        const double py = x(2) + spread_y + noise(rng);
        scan.plots.emplace_back(px, py, 0.0);
        scan.source.push_back(g.id);
      }
    }
    const int clutter = std::poisson_distribution<int>(s.clutter_rate)(rng);
    for (int i = 0; i < clutter; ++i) {
      const double px = area(rng);
      scan.plots.emplace_back(px, area(rng), 0.0);
      scan.source.push_back(0);
    }
    sc.scans.push_back(std::move(scan));
  }
}

}  // namespace

std::vector<Eigen::VectorXd> Scenario::truth_positions(int k, std::vector<int>* ids) const {
  std::vector<Eigen::VectorXd> out;
  if (ids != nullptr) {
    ids->clear();
  }
  for (const TruthGroup& g : groups) {
    if (!g.alive(k)) {
      continue;
    }
    const BoxVec& x = g.state[static_cast<std::size_t>(k - 1)];
    out.push_back(Eigen::Vector2d(x(0), x(2)));
    if (ids != nullptr) {
      ids->push_back(g.id);
    }
  }
  return out;
}

Scenario make_experiment1(std::uint64_t seed) {
  Scenario sc;
  sc.spec.turn_rate = 3.0 * std::numbers::pi / 180.0;
  const int n = sc.spec.scans;
  std::mt19937_64 rng(seed);
  // Group 2 merges into group 1 at k = 10: it ends at 9 and group 1 carries both groups'
  // plots from 10 on. Group 4 splits from group 3 at k = 25 with velocity (50, 10) and lives
  // to the end (the paper gives no end).
  TruthGroup g1 = start(1, 1, 30, BoxVec(-800, 40, 600, -40), n);
  TruthGroup g2 = start(2, 1, 9, BoxVec(-740, 50, -30, 30), n);
  TruthGroup g3 = start(3, 15, 45, BoxVec(-400, 40, -800, 40), n);
  TruthGroup g5 = start(5, 20, 50, BoxVec(400, -30, -800, 30), n);
  TruthGroup g6 = start(6, 15, 35, BoxVec(550, -50, 700, -40), n);
  for (TruthGroup* g : {&g1, &g2, &g3, &g5, &g6}) {
    propagate(*g, sc.spec, rng);
  }
  const BoxVec at_split = g3.state[24];
  TruthGroup g4 = start(4, 25, 50, BoxVec(at_split(0), 50, at_split(2), 10), n);
  propagate(g4, sc.spec, rng);
  sc.groups = {g1, g2, g3, g4, g5, g6};
  make_scans(sc, rng);
  // From the merge on group 1 returns both groups' plots: its own Poisson(15) plus group 2's.
  std::uniform_real_distribution<double> spread(-sc.spec.half_spread, sc.spec.half_spread);
  std::normal_distribution<double> noise(0.0, sc.spec.measurement_sigma);
  for (int k = 10; k <= g1.last; ++k) {
    const BoxVec& x = g1.state[static_cast<std::size_t>(k - 1)];
    Scan& scan = sc.scans[static_cast<std::size_t>(k - 1)];
    const int extra = std::poisson_distribution<int>(g2.plot_rate)(rng);
    for (int i = 0; i < extra; ++i) {
      const double spread_x = spread(rng);
      const double px = x(0) + spread_x + noise(rng);
      const double spread_y = spread(rng);
      const double py = x(2) + spread_y + noise(rng);
      scan.plots.emplace_back(px, py, 0.0);
      scan.source.push_back(1);
    }
  }
  return sc;
}

Scenario make_experiment2(std::uint64_t seed) {
  Scenario sc;
  sc.spec.turn_rate = 0.0;
  sc.spec.group_detection = 0.98;
  std::mt19937_64 rng(seed);
  TruthGroup g1 = start(1, 1, 50, BoxVec(-900, 35, 900, -35), sc.spec.scans);
  TruthGroup g2 = start(2, 1, 50, BoxVec(900, -30, 900, -35), sc.spec.scans);
  propagate(g1, sc.spec, rng);
  propagate(g2, sc.spec, rng);
  sc.groups = {g1, g2};
  make_scans(sc, rng);
  return sc;
}

}  // namespace group_mc
