// Secondary-radar reply attributes of simulated plots; the rules are in transponder_reply.hpp.
#include "transponder_reply.hpp"

#include <cmath>

#include "skytrack/core/transponder.hpp"
#include "skytrack/geometry/altitude.hpp"

namespace skytrack::sim {

void stamp_reply(Plot& plot, const Eigen::Vector3d& position, const SensorSpec& sensor,
                 const TargetSpec* target) {
  if (target) {
    plot.mode3a = target->mode3a;
    plot.mode_s = target->mode_s;
  }
  const double step = sensor.flight_level_step;
  if (!(step > 0.0) || (target && !target->reports_altitude)) return;
  // A transponder encodes its altitude in whole steps (Mode C: 100 ft), so the report is
  // rounded, not noisy: its error is uniform within half a step.
  const double level = altitude_of(position) / (100.0 * kFeetToMetres);
  const double reported = std::round(level / step) * step;
  if (plausible_flight_level(reported)) plot.flight_level = reported;
}

}  // namespace skytrack::sim
