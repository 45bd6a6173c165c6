#include "skytrack/pipeline/sensor_timeline.hpp"

#include <algorithm>
#include <cmath>

namespace skytrack {

SensorTimeline::Placement SensorTimeline::place(std::uint32_t id, double time, bool restarted,
                                                double max_jump) {
  Sensor& sensor = sensors_[id];
  if (restarted) {
    // Its old clock was the wrong one when its new one agrees with another sensor's.
    const bool agrees = std::any_of(sensors_.begin(), sensors_.end(), [&](const auto& other) {
      return other.first != id && !other.second.held && other.second.latest &&
             std::abs(*other.second.latest - time) <= max_jump;
    });
    if (agrees) {
      sensor.held = false;
      sensor.hold_start.reset();
      return Placement::kRejoins;
    }
  } else if (!time_ || std::abs(time - *time_) <= max_jump) {
    const bool was_held = sensor.held;
    sensor.held = false;
    sensor.hold_start.reset();
    return was_held ? Placement::kRejoins : Placement::kOnTime;
  }
  if (!another_on_time(id, max_jump)) return new_timeline();
  return hold(sensor, time, max_jump);
}

SensorTimeline::Placement SensorTimeline::hold(Sensor& sensor, double time, double max_jump) {
  if (!sensor.held) {
    sensor.held = true;
    sensor.hold_start = time;
    return Placement::kHeld;
  }
  if (!sensor.hold_start) sensor.hold_start = time;
  // Its own clock only moves forward (batch_clock.hpp), so this is time it has been alone.
  if (time - *sensor.hold_start > max_jump) return new_timeline();
  return Placement::kHeld;
}

SensorTimeline::Placement SensorTimeline::new_timeline() {
  time_.reset();
  for (auto& [id, sensor] : sensors_) {
    sensor.held = false;
    sensor.hold_start.reset();
  }
  return Placement::kNewTimeline;
}

bool SensorTimeline::another_on_time(std::uint32_t id, double max_jump) const {
  return time_ && std::any_of(sensors_.begin(), sensors_.end(), [&](const auto& other) {
           return other.first != id && !other.second.held && other.second.latest &&
                  std::abs(*other.second.latest - *time_) <= max_jump;
         });
}

void SensorTimeline::fed(std::uint32_t id, double time) {
  sensors_[id].latest = time;
  time_ = time_ ? std::max(*time_, time) : time;
  for (auto& [other, sensor] : sensors_) {
    if (other != id && sensor.held) sensor.hold_start.reset();
  }
}

}  // namespace skytrack
