#include "skytrack/tracking/initiator.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <tuple>

namespace skytrack {
namespace {

constexpr double kHalfTurn = 3.141592653589793;  // [rad] of sweep

/// Whole revolutions of sweep between two plots (one sensor's; 0 for two sensors').
int revolutions(const PlotMeasurement& a, const PlotMeasurement& b) {
  if (a.sensor != b.sensor) return 0;
  return static_cast<int>(std::lround((b.sweep - a.sweep) / (2.0 * kHalfTurn)));
}

/// Two plots of one sensor seen within half a revolution: one look, not one target's two.
bool same_revolution(const PlotMeasurement& a, const PlotMeasurement& b) {
  return a.sensor == b.sensor && b.sweep - a.sweep <= kHalfTurn;
}

/// Euclidean distance in the first `dims` coordinates (2: horizontal; otherwise 3-D).
double distance_in(const Eigen::Vector3d& a, const Eigen::Vector3d& b, int dims) {
  const Eigen::Vector3d d = a - b;
  return dims == 2 ? d.head<2>().norm() : d.norm();
}

/// Range sigma of a polar plot; position_sigma for a Cartesian one.
double range_sigma(const PlotMeasurement& plot) {
  return is_polar(plot.model.kind) ? plot.model.sigma[0] : position_sigma(plot);
}

/// |offset . line of sight| of `position - expected` at a polar plot (the line from its
/// sensor to `position`), or -1 for a Cartesian plot.
double line_of_sight_offset(const PlotMeasurement& plot, const Eigen::Vector3d& position,
                            const Eigen::Vector3d& expected, int dims) {
  if (!is_polar(plot.model.kind)) return -1.0;
  Eigen::Vector3d sight = position - plot.model.platform.position;
  if (dims == 2) sight.z() = 0.0;
  const double length = sight.norm();
  if (!(length > 0.0)) return -1.0;
  Eigen::Vector3d offset = position - expected;
  if (dims == 2) offset.z() = 0.0;
  return std::abs(offset.dot(sight)) / length;
}

}  // namespace

double position_sigma(const PlotMeasurement& plot) noexcept {
  const MeasurementModel& m = plot.model;
  if (m.kind == MeasurementKind::kCartesian) {
    return m.sigma.head(m.position_components).maxCoeff();
  }
  return std::max(m.sigma[0], plot.z[0] * m.sigma[1]);
}

ChainManoeuvre ChainManoeuvre::from_models(const std::vector<config::MotionModelSpec>& models,
                                           int dims) {
  using config::MotionModelType;
  ChainManoeuvre out{.accel = 0.0, .turn_rate = 0.0};
  for (const config::MotionModelSpec& m : models) {
    switch (m.type) {
      case MotionModelType::kConstantAcceleration:
        return {};  // an acceleration of any size is a state: no bound below 6 g
      case MotionModelType::kCoordinatedTurn:
        out.turn_rate = std::max(out.turn_rate, std::abs(m.turn_rate));
        break;
      case MotionModelType::kCoordinatedTurnEstimated:
        out.turn_rate = std::max(out.turn_rate, 3.0 * m.initial_turn_rate_sigma);
        break;
      case MotionModelType::kConstantVelocity:
      case MotionModelType::kSinger:
        break;
    }
    out.accel = std::max(out.accel, 3.0 * m.accel_sigma);
    if (dims == 3) out.accel = std::max(out.accel, 3.0 * m.vertical_accel_sigma);
  }
  return models.empty() ? ChainManoeuvre{} : out;
}

double ChainManoeuvre::at(double speed) const noexcept {
  return std::min(kMaxAcceleration, accel + turn_rate * speed);
}

Initiator::Initiator(const config::InitiationSpec& spec, int dims, ChainManoeuvre manoeuvre)
    : spec_(spec), dims_(dims), manoeuvre_(manoeuvre) {}

const std::vector<Initiation>& Initiator::step(std::uint64_t batch, double time,
                                               const std::vector<PlotMeasurement>& plots,
                                               const Coverage& covered,
                                               std::span<const Eigen::Vector3d> positions) {
  // A snapshot sensor: each batch is one revolution of sweep after the last.
  const double sweep = 2.0 * kHalfTurn * static_cast<double>(batch);
  snapshot_plots_ = plots;
  for (PlotMeasurement& p : snapshot_plots_) p.sweep = sweep;
  return step(batch, time, plots.empty() ? 0 : plots.front().sensor, sweep, snapshot_plots_,
              covered, positions);
}

const std::vector<Initiation>& Initiator::step(std::uint64_t batch, double time,
                                               std::uint32_t sensor, double sweep,
                                               const std::vector<PlotMeasurement>& plots,
                                               const Coverage& covered,
                                               std::span<const Eigen::Vector3d> positions) {
  completed_.clear();
  batch_ = batch;
  sweep_ = sweep;
  // This batch is a look at every seed and chain it covers that the beam has not passed
  // within the last half revolution (a chain predicted across the cut it was made at).
  const auto looks_at = [&](double& last, std::uint32_t seen_by, const Eigen::Vector3d& position) {
    if ((seen_by == sensor && sweep - last <= kHalfTurn) || !covered(position)) return false;
    if (seen_by == sensor) last = sweep;
    return true;
  };
  for (Seed& seed : seeds_) {
    if (seed.batch != batch && looks_at(seed.looked, seed.plot.sensor, seed.position)) {
      ++seed.looks;
    }
  }
  for (Chain& chain : chains_) {
    if (looks_at(chain.looked, chain.plots.back().sensor,
                 chain.position + chain.velocity * (time - chain.time))) {
      ++chain.looks;
    }
  }
  assert(positions.empty() || positions.size() == plots.size());
  if (positions.empty()) {
    positions_.clear();
    for (const PlotMeasurement& plot : plots) positions_.push_back(approximate_position(plot));
  } else {
    positions_.assign(positions.begin(), positions.end());
  }
  used_.assign(plots.size(), 0);
  extend_chains(batch, plots);
  pair_with_seeds(batch, plots);
  for (std::size_t i = 0; i < plots.size(); ++i) {
    if (!used_[i]) seeds_.push_back({plots[i], positions_[i], batch, 0, plots[i].sweep});
  }
  // Chains with M plots become tracks; a held chain completes again with its next plot.
  for (std::size_t c = 0; c < chains_.size();) {
    Chain& chain = chains_[c];
    const bool held = chain.held_plots > 0;
    const int plots_to_complete = held ? chain.held_plots + 1 : spec_.m;
    if (static_cast<int>(chain.plots.size()) >= plots_to_complete) {
      completed_.push_back(
          {std::move(chain.plots), chain.looks, chain.last, held, chain.held_existence});
      chains_[c] = std::move(chains_.back());
      chains_.pop_back();
    } else {
      ++c;
    }
  }
  retire();
  // In the order their last plots were seen, so that a revolution's new tracks are numbered
  // alike whether it came whole or in sectors.
  std::sort(completed_.begin(), completed_.end(), [](const Initiation& a, const Initiation& b) {
    const PlotMeasurement& x = a.plots.back();
    const PlotMeasurement& y = b.plots.back();
    return std::tie(x.time, x.z[0], x.z[1]) < std::tie(y.time, y.z[0], y.z[1]);
  });
  return completed_;
}

void Initiator::hold(const Initiation& initiation, double existence) {
  assert(initiation.plots.size() >= 2);
  // Its last M plots: enough to start an estimate from, and a chain held look after look
  // restarts from as many (its existence carries the weighing of the others).
  const std::size_t n =
      std::min(initiation.plots.size(), static_cast<std::size_t>(std::max(spec_.m, 2)));
  Chain chain;
  chain.plots.assign(initiation.plots.end() - static_cast<std::ptrdiff_t>(n),
                     initiation.plots.end());
  const PlotMeasurement& last = chain.plots[n - 1];
  const PlotMeasurement& before = chain.plots[n - 2];
  // As extend_chains left it in the step that completed it.
  chain.position = approximate_position(last);
  chain.velocity = (chain.position - approximate_position(before)) / (last.time - before.time);
  chain.time = last.time;
  chain.last_batch = batch_;
  chain.looks = initiation.scans;
  chain.looked = std::max(sweep_, last.sweep);
  chain.last = initiation.last;
  chain.held_plots = static_cast<int>(n);
  chain.held_looks = chain.looks;
  chain.held_existence = existence;
  chains_.push_back(std::move(chain));
}

void Initiator::search_regions(double time, std::vector<SearchRegion>& out) const {
  for (const Chain& chain : chains_) {
    const double dt = std::max(0.0, time - chain.time);
    out.push_back({chain.position + chain.velocity * dt,
                   4.0 * (2.0 * position_sigma(chain.plots.back())) +
                       0.5 * manoeuvre_.at(chain.velocity.norm()) * dt * dt});
  }
}

void Initiator::extend_chains(std::uint64_t batch, const std::vector<PlotMeasurement>& plots) {
  if (plots.empty()) return;
  // Plots of one batch may span a whole revolution: search around the chain's prediction at
  // the middle of the batch, widened by how far it moves in half the span.
  double t_min = plots.front().time, t_max = t_min;
  for (const PlotMeasurement& p : plots) {
    t_min = std::min(t_min, p.time);
    t_max = std::max(t_max, p.time);
  }
  const double t_mid = 0.5 * (t_min + t_max);
  extensions_.clear();
  radii_.assign(chains_.size(), -1.0);
  for (std::size_t c = 0; c < chains_.size(); ++c) {
    const Chain& chain = chains_[c];
    if (chain.last_batch == batch) continue;
    const double dt_max = t_max - chain.time;
    radii_[c] = 4.0 * (2.0 * position_sigma(chain.plots.back())) +
                0.5 * manoeuvre_.at(chain.velocity.norm()) * dt_max * dt_max +
                chain.velocity.norm() * 0.5 * (t_max - t_min);
  }
  if (chains_.empty()) return;
  // Cells of the median search radius: a search looks at a few cells around its centre.
  cell_radii_ = radii_;
  const auto median = cell_radii_.begin() + static_cast<std::ptrdiff_t>(cell_radii_.size() / 2);
  std::nth_element(cell_radii_.begin(), median, cell_radii_.end());
  index_.build(positions_, dims_, *median);
  for (std::size_t c = 0; c < chains_.size(); ++c) {
    const Chain& chain = chains_[c];
    if (radii_[c] < 0.0) continue;
    const double sigma_last = position_sigma(chain.plots.back());
    const double accel = manoeuvre_.at(chain.velocity.norm());
    index_.within(chain.position + chain.velocity * (t_mid - chain.time), radii_[c], neighbours_);
    for (const int j : neighbours_) {
      const double dt = plots[j].time - chain.time;
      if (dt <= 0.0 || same_revolution(chain.plots.back(), plots[j])) continue;
      const Eigen::Vector3d expected = chain.position + chain.velocity * dt;
      const double manoeuvre = 0.5 * accel * dt * dt;
      const double gate = 4.0 * (sigma_last + position_sigma(plots[j])) + manoeuvre;
      const double d = distance_in(positions_[j], expected, dims_);
      if (d >= gate) continue;
      // A radar measures range far better than angle: along the line of sight the gate is
      // the ranges' own four sigma (plus the manoeuvre), not the cross-range one.
      if (const double along = line_of_sight_offset(plots[j], positions_[j], expected, dims_);
          along >= 0.0) {
        const double gate_along =
            4.0 * (range_sigma(chain.plots.back()) + range_sigma(plots[j])) + manoeuvre;
        const double across2 = std::max(0.0, d * d - along * along);
        if (along * along / (gate_along * gate_along) + across2 / (gate * gate) >= 1.0) continue;
      }
      extensions_.push_back({d, static_cast<int>(c), j});
    }
  }
  // Nearest pairs first over all chains: in chain order a clutter chain whose 6 g gate
  // (kilometres wide) reaches a target's plot took it from the target's own chain, whose
  // prediction lay much nearer (paper003_exp2 seed 19: no track for 60 s).
  std::sort(extensions_.begin(), extensions_.end(), [](const Extension& a, const Extension& b) {
    return std::tie(a.distance, a.chain, a.plot) < std::tie(b.distance, b.chain, b.plot);
  });
  for (const Extension& e : extensions_) {
    Chain& chain = chains_[static_cast<std::size_t>(e.chain)];
    if (used_[e.plot] || chain.last_batch == batch) continue;
    const PlotMeasurement& plot = plots[e.plot];
    used_[e.plot] = 1;
    chain.velocity = (positions_[e.plot] - chain.position) / (plot.time - chain.time);
    chain.position = positions_[e.plot];
    chain.time = plot.time;
    chain.last_batch = batch;
    chain.looked = std::max(chain.looked, plot.sweep);
    chain.looks = std::max(chain.looks, 1 + revolutions(chain.plots.front(), plot));
    chain.last = e.plot;
    chain.plots.push_back(plot);
  }
}

void Initiator::pair_with_seeds(std::uint64_t batch, const std::vector<PlotMeasurement>& plots) {
  if (seeds_.empty() || plots.empty()) return;
  // Seeds are kept in batch order. Each batch's seeds get their own index, searched with the
  // reach of that batch's age, so a young seed batch is not searched as far as the oldest.
  // Every group is indexed in cells of the youngest group's reach (below) from the batch's
  // first plot: an older group's search is bounded by the nearest seed found in a younger
  // one, mostly within that reach, so it looks at a few small cells rather than one of its
  // own wide ones.
  seed_groups_.clear();
  double cell = std::numeric_limits<double>::infinity();
  for (std::size_t begin = 0; begin < seeds_.size();) {
    SeedGroup group{begin, begin, std::numeric_limits<double>::infinity()};
    for (; group.end < seeds_.size() && seeds_[group.end].batch == seeds_[begin].batch;
         ++group.end) {
      group.oldest = std::min(group.oldest, seeds_[group.end].plot.time);
      group.max_sigma = std::max(group.max_sigma, position_sigma(seeds_[group.end].plot));
    }
    cell = std::min(cell, spec_.max_speed * std::max(plots.front().time - group.oldest, 0.0) +
                              3.0 * (2.0 * group.max_sigma) + 1.0);
    seed_groups_.push_back(group);
    begin = group.end;
  }
  if (seed_indices_.size() < seed_groups_.size()) seed_indices_.resize(seed_groups_.size());
  for (std::size_t g = 0; g < seed_groups_.size(); ++g) {
    seed_positions_.clear();
    for (std::size_t s = seed_groups_[g].begin; s < seed_groups_[g].end; ++s) {
      seed_positions_.push_back(seeds_[s].position);
    }
    seed_indices_[g].build(seed_positions_, dims_, cell);
  }
  for (std::size_t i = 0; i < plots.size(); ++i) {
    if (used_[i]) continue;
    // The seed whose implied speed is plausible and whose distance is smallest (the first in
    // seed order among equals). The youngest batch's seeds are searched first: the nearest
    // found bounds the search among the older ones, whose speed discs are wider.
    int best = -1;
    double best_distance = std::numeric_limits<double>::infinity();
    for (std::size_t g = seed_groups_.size(); g-- > 0;) {
      const SeedGroup& group = seed_groups_[g];
      // Every seed the speed test below can accept: distance - slack <= max_speed dt.
      const double reach = spec_.max_speed * (plots[i].time - group.oldest) +
                           3.0 * (position_sigma(plots[i]) + group.max_sigma) + 1.0;
      // (A margin over the nearest so far: the tree's round-off is not the norm's.)
      seed_indices_[g].within(positions_[i], std::min(reach, best_distance * (1.0 + 1e-9) + 1e-6),
                              neighbours_);
      for (const int member : neighbours_) {
        const int s = static_cast<int>(group.begin) + member;
        const Seed& seed = seeds_[s];
        const double dt = plots[i].time - seed.plot.time;
        // A plot of a later revolution than the seed's (a rotating antenna's next plot of a
        // target may come before the beam has passed the seed's position again).
        if (dt <= 0.0 || seed.batch == batch || same_revolution(seed.plot, plots[i])) continue;
        const double distance = distance_in(positions_[i], seed.position, dims_);
        const double slack = 3.0 * (position_sigma(plots[i]) + position_sigma(seed.plot));
        const double speed_low = (distance - slack) / dt, speed_high = (distance + slack) / dt;
        if (speed_high < spec_.min_speed || speed_low > spec_.max_speed) continue;
        if (distance < best_distance || (distance == best_distance && s < best)) {
          best_distance = distance;
          best = s;
        }
      }
    }
    if (best < 0) continue;
    const Seed& seed = seeds_[best];
    Chain chain;
    chain.plots.reserve(static_cast<std::size_t>(std::max(spec_.m, 2)));  // grows to M plots
    chain.plots.push_back(seed.plot);
    chain.plots.push_back(plots[i]);
    chain.position = positions_[i];
    chain.velocity = (positions_[i] - seed.position) / (plots[i].time - seed.plot.time);
    chain.time = plots[i].time;
    chain.looks = std::max(seed.looks + 1, 1 + revolutions(seed.plot, plots[i]));
    chain.last_batch = batch;
    chain.looked = std::max(seed.looked, plots[i].sweep);
    chain.last = static_cast<int>(i);
    chains_.push_back(std::move(chain));
    used_[i] = 1;
  }
}

void Initiator::retire() {
  // A seed or chain that can no longer collect M plots within N looks is dropped.
  const int window = std::max(1, spec_.n);
  std::erase_if(seeds_, [&](const Seed& s) { return s.looks >= window - 1; });
  std::erase_if(chains_, [&](const Chain& c) {
    // A held chain looked at without taking a plot: as a track it would have been deleted.
    if (c.held_plots > 0) return c.looks > c.held_looks;
    return static_cast<int>(c.plots.size()) + (window - c.looks) < spec_.m;
  });
}

}  // namespace skytrack
