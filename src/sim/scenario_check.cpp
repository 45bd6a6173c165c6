#include "scenario_check.hpp"

#include <optional>
#include <string>

namespace skytrack::sim {
namespace {

bool needs(const std::optional<double>& sigma) {
  return sigma.has_value() && *sigma > 0.0;
}

}  // namespace

Expected<void> check_scenario(const Scenario& scenario) {
  const SensorSpec& sensor = scenario.sensor;
  const bool three_d = scenario.dimensions == 3;
  if (scenario.dimensions != 2 && scenario.dimensions != 3) {
    return make_error("scenario.dimensions: expected 2 or 3");
  }
  if (!(sensor.scan_period > 0.0)) return make_error("sensor.scan_period: must be positive");
  if (sensor.sectors < 1) return make_error("sensor.sectors: must be at least 1");
  if (!(scenario.duration >= 0.0)) return make_error("scenario.duration: must be >= 0");
  if (sensor.type == SensorSpec::Type::kPolar) {
    if (!needs(sensor.sigma.range) || !needs(sensor.sigma.azimuth) ||
        (three_d && sensor.elevation && !needs(sensor.sigma.elevation)) ||
        (sensor.range_rate && !needs(sensor.sigma.range_rate))) {
      return make_error("sensor.sigma: a polar sensor needs range, azimuth" +
                        std::string(three_d && sensor.elevation ? ", elevation" : "") +
                        (sensor.range_rate ? ", range_rate" : "") + " sigmas");
    }
  } else if (!needs(sensor.sigma.x) || !needs(sensor.sigma.y) ||
             (three_d && !needs(sensor.sigma.z))) {
    return make_error("sensor.sigma: a Cartesian sensor needs x, y" +
                      std::string(three_d ? ", z" : "") + " sigmas");
  }
  return {};
}

}  // namespace skytrack::sim
