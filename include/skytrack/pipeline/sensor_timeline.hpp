#pragma once
// Which sensors' batches share the tracks' time. Each sensor's own clock (batch_clock.hpp)
// keeps its batches in order, but sensors are fused on one time: a sensor whose clock
// disagrees with the tracks' time by more than max_time_jump (a corrupted or hostile clock, a
// restart onto a wrong time, a new sensor on another epoch) is held, its batches refused,
// while another sensor goes on in the tracks' time; one sensor can neither drag the tracks
// years ahead nor wipe the others' tracks. It rejoins when its time agrees again. The tracks
// restart on its clock only when no other sensor is on the tracks' time, or when none has
// been heard while its own clock advanced by max_time_jump (the others have stopped).
#include <cstdint>
#include <map>
#include <optional>

namespace skytrack {

class SensorTimeline {
 public:
  enum class Placement {
    kOnTime,       // fed as usual
    kRejoins,      // fed, after its looks restart (a clock restart that agrees, or a release)
    kHeld,         // refused: its time disagrees with the tracks' and another sensor is on it
    kNewTimeline,  // fed after every track and look restarts: the tracks take its time
  };

  /// Places sensor `id`'s batch at `time`, which the sensor's own clock has accepted
  /// (`restarted`: as a restart of that clock). `max_jump` [s] is the agreement bound.
  Placement place(std::uint32_t id, double time, bool restarted, double max_jump);
  /// Sensor `id`'s batch at `time` reached the tracks.
  void fed(std::uint32_t id, double time);
  /// The tracks' time: the latest time fed to them, if any since the last new timeline.
  const std::optional<double>& time() const { return time_; }

 private:
  struct Sensor {
    std::optional<double> latest;  // its latest batch fed
    bool held = false;
    std::optional<double> hold_start;  // its time when it was held or another was last fed
  };
  /// True when a sensor other than `id`, not held, was last fed on the tracks' time.
  bool another_on_time(std::uint32_t id, double max_jump) const;
  Placement hold(Sensor& sensor, double time, double max_jump);
  Placement new_timeline();

  std::map<std::uint32_t, Sensor> sensors_;
  std::optional<double> time_;
};

}  // namespace skytrack
