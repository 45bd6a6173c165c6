// The fusion role's front: local frames in, the cycle clock, fused frames out
// (include/skytrack/fusion/track_fusion.hpp). The cycle itself: fusion_cycle.cpp.
#include "skytrack/fusion/track_fusion.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <Eigen/Cholesky>

#include "fusion_state.hpp"

namespace skytrack::fusion {
namespace {

using detail::LocalInput;
using detail::SensorFrame;

double time_epsilon(double t) {
  return 1e-9 * std::max(1.0, std::abs(t));
}

bool usable_status(TrackStatus status, bool firm_only) {
  if (status == TrackStatus::kDeleted) return false;
  return !firm_only || is_reported_as_firm(status);
}

/// The local track as a state [x, vx, y, vy, z, vz]; nullopt when it is not finite, its
/// covariance has the wrong size or is not positive definite.
std::optional<StateEstimate> to_state(const TrackReport& t, const FusionSpec& spec) {
  StateEstimate s;
  s.dims = t.dims >= 3 ? 3 : 2;
  const int n = 2 * s.dims;
  for (int axis = 0; axis < s.dims; ++axis) {
    s.x(2 * axis) = t.position(axis);
    s.x(2 * axis + 1) = t.velocity(axis);
  }
  if (!s.x.head(n).allFinite()) return std::nullopt;
  s.P.setIdentity();
  if (t.covariance.empty()) {
    const double p2 = spec.missing_position_sigma * spec.missing_position_sigma;
    const double v2 = spec.missing_velocity_sigma * spec.missing_velocity_sigma;
    for (int axis = 0; axis < s.dims; ++axis) {
      s.P(2 * axis, 2 * axis) = p2;
      s.P(2 * axis + 1, 2 * axis + 1) = v2;
    }
    return s;
  }
  if (t.covariance.size() != static_cast<std::size_t>(n * n)) return std::nullopt;
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) s.P(r, c) = t.covariance[static_cast<std::size_t>(r * n + c)];
  }
  if (!s.P.topLeftCorner(n, n).allFinite()) return std::nullopt;
  const StateEstimate::Mat sym = 0.5 * (s.P + s.P.transpose());
  s.P = sym;
  const bool pd =
      n == 6 ? Eigen::LLT<StateEstimate::Mat>(s.P).info() == Eigen::Success
             : Eigen::LLT<Eigen::Matrix4d>(s.P.topLeftCorner<4, 4>()).info() == Eigen::Success;
  if (!pd) return std::nullopt;
  return s;
}

}  // namespace

TrackFusion::State::State(FusionSpec s) : spec(s), associator(s) {
  if (!(spec.cycle > 0.0) || !std::isfinite(spec.cycle)) spec.cycle = 1.0;  // never a stuck clock
  const double ratio = spec.cycle > 0.0 ? spec.window / spec.cycle : 1.0;
  window_cycles = static_cast<std::uint64_t>(std::clamp(std::floor(ratio + 1e-9), 1.0, 10000.0));
}

TrackFusion::TrackFusion(FusionSpec spec) : state_(std::make_unique<State>(spec)) {}
TrackFusion::~TrackFusion() = default;
TrackFusion::TrackFusion(TrackFusion&&) noexcept = default;
TrackFusion& TrackFusion::operator=(TrackFusion&&) noexcept = default;

const FusionSpec& TrackFusion::spec() const {
  return state_->spec;
}
const FusionCounters& TrackFusion::counters() const {
  return state_->counters;
}

// A gap in data time longer than anything the fusion remembers is jumped over rather than
// fused cycle by empty cycle.
std::vector<TrackFrame> TrackFusion::State::run_due_cycles(bool flushing) {
  State& st = *this;
  std::vector<TrackFrame> out;
  if (!st.started || !(st.spec.cycle > 0.0)) return out;
  const double horizon =
      st.spec.sensor_timeout + st.spec.coast_time + st.spec.window + st.spec.cycle;
  for (;;) {
    double ready = st.data_time;
    if (!flushing) {
      for (const auto& [id, sensor] : st.sensors) {
        if (sensor.live) ready = std::min(ready, sensor.last_time);
      }
    }
    const double b = st.cycle_time(st.next_cycle);
    if (b > ready + time_epsilon(b)) break;
    // The first cycle waits for data past it: sensors not heard from yet may report at b.
    if (!flushing && !st.fused_any && !(st.data_time > b + time_epsilon(b))) break;
    if (ready - b > horizon) {
      const double target = std::floor((ready - horizon - st.grid_origin) / st.spec.cycle);
      const auto k = static_cast<std::uint64_t>(std::max(target, 0.0));
      if (k > st.next_cycle) {
        st.counters.cycles_skipped += k - st.next_cycle;
        st.next_cycle = k;
        continue;
      }
    }
    out.push_back(st.fuse_cycle());
  }
  return out;
}

std::vector<TrackFrame> TrackFusion::add(const TrackFrame& local) {
  State& st = *state_;
  if (!std::isfinite(local.time)) {
    ++st.counters.frames_invalid;
    return {};
  }
  const auto found = st.sensors.find(local.sensor);
  const bool joining = found == st.sensors.end() || !found->second.live;
  const bool late = st.fused_any && local.time <= st.last_fused + time_epsilon(local.time);
  if ((late && !joining) || (found != st.sensors.end() && local.time <= found->second.last_time)) {
    ++st.counters.frames_late;
    return {};
  }
  // A new or returning sensor's frame that is late for its cycle still makes the sensor
  // live, so the next cycles wait for it: without, a sensor reporting just after the others
  // would stay late for ever.
  if (late) ++st.counters.frames_late;
  SensorFrame frame;
  frame.time = local.time;
  frame.tracks.reserve(local.tracks.size());
  for (const TrackReport& t : local.tracks) {
    if (!usable_status(t.status, st.spec.firm_only)) continue;
    const std::optional<StateEstimate> s = to_state(t, st.spec);
    if (!s) {
      ++st.counters.tracks_invalid;
      continue;
    }
    frame.tracks.push_back({t.id, *s});
  }
  std::sort(frame.tracks.begin(), frame.tracks.end(),
            [](const LocalInput& a, const LocalInput& b) { return a.id < b.id; });
  const auto duplicate =
      std::unique(frame.tracks.begin(), frame.tracks.end(),
                  [](const LocalInput& a, const LocalInput& b) { return a.id == b.id; });
  st.counters.tracks_invalid += static_cast<std::uint64_t>(frame.tracks.end() - duplicate);
  frame.tracks.erase(duplicate, frame.tracks.end());

  detail::SensorState& sensor = st.sensors[local.sensor];
  sensor.frames.push_back(std::move(frame));
  if (sensor.frames.size() > static_cast<std::size_t>(std::max(st.spec.max_queued_frames, 2))) {
    sensor.frames.pop_front();
    ++st.counters.frames_dropped;
  }
  sensor.last_time = local.time;
  sensor.live = true;
  if (!late) ++st.counters.frames;
  st.data_time = std::max(st.data_time, local.time);
  if (!st.started) {
    st.started = true;
    st.grid_origin = std::ceil(local.time / st.spec.cycle - 1e-9) * st.spec.cycle;
    st.next_cycle = 0;
  }
  for (auto& [id, s] : st.sensors) {
    if (s.live && st.data_time - s.last_time > st.spec.sensor_timeout) {
      s.live = false;
      ++st.counters.sensors_dropped;
    }
  }
  return st.run_due_cycles(false);
}

std::vector<TrackFrame> TrackFusion::flush() {
  return state_->run_due_cycles(true);
}

}  // namespace skytrack::fusion
