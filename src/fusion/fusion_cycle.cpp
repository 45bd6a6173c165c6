// One fusion cycle (TrackFusion::State::fuse_cycle): the local tracks aligned to the cycle's
// time, associated (cycle_associator.cpp), fused by covariance intersection into system
// tracks that keep their numbers, and reported as one TrackFrame.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "fusion_state.hpp"

namespace skytrack::fusion {
namespace {

using detail::PresentTrack;
using detail::SystemTrack;

TrackReport to_report(std::int64_t id, const SystemTrack& s) {
  TrackReport r;
  r.id = id;
  r.status = s.status;
  r.dims = s.state.dims;
  for (int axis = 0; axis < s.state.dims; ++axis) {
    r.position(axis) = s.state.x(2 * axis);
    r.velocity(axis) = s.state.x(2 * axis + 1);
  }
  const int n = 2 * s.state.dims;
  r.covariance.resize(static_cast<std::size_t>(n * n));
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) r.covariance[static_cast<std::size_t>(i * n + j)] = s.state.P(i, j);
  }
  r.sources = s.sources;
  return r;
}

void add_event(TrackFrame& frame, TrackEventType type, std::int64_t id, std::string detail = {}) {
  frame.events.push_back({type, id, std::move(detail), {}});
}

}  // namespace

// A merge keeps the older number: when every last source of system track X (fed no more)
// now sits in one newer system track Y, Y's sources go to X and Y is deleted, merged into X.
// Without it, a pair that parts for a cycle and joins again would leave the newer number.
void TrackFusion::State::keep_older_numbers(std::uint64_t k) {
  merges.clear();
  fed_ids = system_of;
  std::sort(fed_ids.begin(), fed_ids.end());
  for (const auto& [x, s] : systems) {
    if (s.last_sources.empty() || std::binary_search(fed_ids.begin(), fed_ids.end(), x)) continue;
    std::int64_t y = 0;
    for (const TrackSource& src : s.last_sources) {
      const auto rec = records.find({src.sensor, src.track});
      const bool here = rec != records.end() && rec->second.last_cycle == k;
      if (!here || (y != 0 && rec->second.system != y)) {
        y = 0;
        break;
      }
      y = rec->second.system;
    }
    const bool taken =
        std::any_of(merges.begin(), merges.end(), [y](const auto& m) { return m.first == y; });
    if (y > x && !taken) merges.emplace_back(y, x);
  }
  for (const auto& [from, to] : merges) {
    for (std::size_t i = 0; i < present.size(); ++i) {
      if (system_of[i] != from) continue;
      system_of[i] = to;
      present[i].record->system = to;
    }
  }
}

TrackFrame TrackFusion::State::fuse_cycle() {
  const std::uint64_t k = next_cycle;
  const double b = cycle_time(k);
  const double eps = 1e-9 * std::max(1.0, std::abs(b));

  // Each live sensor's latest frame at or before b, its tracks predicted to b.
  present.clear();
  for (auto& [sensor_id, sensor] : sensors) {
    while (sensor.frames.size() >= 2 && sensor.frames[1].time <= b + eps) sensor.frames.pop_front();
    if (sensor.frames.empty() || sensor.frames.front().time > b + eps) continue;
    const detail::SensorFrame& f = sensor.frames.front();
    if (b - f.time > spec.sensor_timeout) continue;
    for (const detail::LocalInput& t : f.tracks) {
      PresentTrack p;
      p.sensor = sensor_id;
      p.id = t.id;
      p.state = predict_cv(t.state, std::max(0.0, b - f.time), spec.accel_psd);
      p.position = detail::position_of(p.state);
      p.sigma2 = p.position.cov.trace();
      auto [it, inserted] = records.try_emplace({sensor_id, t.id});
      if (inserted) it->second.history.reserve(window_cycles);
      // A system track deleted meanwhile is not rejoined: its number is never reused.
      if (it->second.system != 0 && !systems.contains(it->second.system)) it->second.system = 0;
      p.record = &it->second;
      present.push_back(p);
    }
  }
  associator.associate(present, k, window_cycles, next_id, system_of);
  counters.pairs_scored += associator.pairs_scored();

  // The local tracks remember this cycle's system track and position.
  for (std::size_t i = 0; i < present.size(); ++i) {
    detail::LocalRecord& rec = *present[i].record;
    rec.system = system_of[i];
    rec.last_cycle = k;
    if (rec.history.size() >= window_cycles) rec.history.erase(rec.history.begin());
    rec.history.push_back({k, present[i].position});
  }
  keep_older_numbers(k);
  // An absent local track keeps its system track: back within the window, it rejoins it.
  for (auto it = records.begin(); it != records.end();) {
    const bool stale = it->second.last_cycle + window_cycles <= k;
    it = stale ? records.erase(it) : std::next(it);
  }

  // System tracks: the sources of each, in (system, sensor, local number) order.
  std::vector<int>& order = associator_order;
  order.resize(present.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int x, int y) {
    return system_of[static_cast<std::size_t>(x)] < system_of[static_cast<std::size_t>(y)] ||
           (system_of[static_cast<std::size_t>(x)] == system_of[static_cast<std::size_t>(y)] &&
            x < y);
  });
  for (const std::int64_t id : system_of) {
    auto [it, inserted] = systems.try_emplace(id);
    if (!inserted) continue;
    it->second.fresh = true;
    ++counters.system_tracks;
  }

  TrackFrame frame;
  frame.sensor = spec.output_sensor;
  frame.scan = counters.cycles + 1;
  frame.time = b;
  frame.tracks.reserve(systems.size());
  std::size_t cursor = 0;
  for (auto it = systems.begin(); it != systems.end();) {
    const std::int64_t id = it->first;
    SystemTrack& s = it->second;
    s.sources.clear();
    fuse_inputs.clear();
    while (cursor < order.size() && system_of[static_cast<std::size_t>(order[cursor])] == id) {
      const PresentTrack& p = present[static_cast<std::size_t>(order[cursor])];
      s.sources.push_back({p.sensor, p.id});
      fuse_inputs.push_back(p.state);
      ++cursor;
    }
    if (!s.sources.empty()) {
      const FusedEstimate fused = covariance_intersection(fuse_inputs);
      if (fused.ok) {
        s.state = fused.estimate;
      } else {  // a covariance CI could not invert: the most precise source alone
        s.state = *std::min_element(fuse_inputs.begin(), fuse_inputs.end(),
                                    [](const StateEstimate& x, const StateEstimate& y) {
                                      return x.P.trace() < y.P.trace();
                                    });
      }
      if (s.fresh) {
        add_event(frame, TrackEventType::kInitiated, id);
        add_event(frame, TrackEventType::kConfirmed, id);
      } else if (s.status == TrackStatus::kCoasting) {
        add_event(frame, TrackEventType::kConfirmed, id, "sources again");
      }
      s.status = TrackStatus::kConfirmed;
      s.last_fed = b;
    } else {
      // Merged: every last source is here this cycle, fused into another system track.
      std::int64_t merged_into = 0;
      const auto renumbered =
          std::find_if(merges.begin(), merges.end(), [id](const auto& m) { return m.first == id; });
      bool merged = !s.last_sources.empty() || renumbered != merges.end();
      for (const TrackSource& src : s.last_sources) {
        const auto rec = records.find({src.sensor, src.track});
        if (rec == records.end() || rec->second.last_cycle != k || rec->second.system == id) {
          merged = false;
          break;
        }
        merged_into = rec->second.system;
      }
      if (renumbered != merges.end()) {
        merged = true;
        merged_into = renumbered->second;
      }
      s.state = predict_cv(s.state, b - s.state_time, spec.accel_psd);
      if (merged) {
        s.status = TrackStatus::kDeleted;
        add_event(frame, TrackEventType::kDeleted, id,
                  "merged into " + std::to_string(merged_into));
      } else if (b - s.last_fed > spec.coast_time + eps) {
        s.status = TrackStatus::kDeleted;
        add_event(frame, TrackEventType::kDeleted, id, "no sources");
      } else if (s.status != TrackStatus::kCoasting) {
        s.status = TrackStatus::kCoasting;
        add_event(frame, TrackEventType::kCoasting, id);
      }
    }
    s.state_time = b;
    s.fresh = false;
    s.last_sources = s.sources;
    frame.tracks.push_back(to_report(id, s));
    it = s.status == TrackStatus::kDeleted ? systems.erase(it) : std::next(it);
  }

  for (auto it = sensors.begin(); it != sensors.end();) {
    const bool gone = !it->second.live && b - it->second.last_time > spec.sensor_timeout;
    it = gone ? sensors.erase(it) : std::next(it);
  }
  ++counters.cycles;
  ++next_cycle;
  fused_any = true;
  last_fused = b;
  return frame;
}

}  // namespace skytrack::fusion
