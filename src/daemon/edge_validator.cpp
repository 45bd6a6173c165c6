#include "skytrack/daemon/edge_validator.hpp"

#include <algorithm>

namespace skytrack::daemon {

EdgeValidator::EdgeValidator(std::vector<std::int64_t> sensors, std::optional<double> max_ahead)
    : sensors_(std::move(sensors)), max_ahead_(max_ahead) {}

std::optional<std::string_view> EdgeValidator::check(const PlotScan& scan, double host_time) const {
  if (!sensors_.empty() && std::find(sensors_.begin(), sensors_.end(),
                                     static_cast<std::int64_t>(scan.sensor)) == sensors_.end()) {
    return reason::kUnknownSensor;
  }
  if (max_ahead_ && scan.time > host_time + *max_ahead_) return reason::kAheadOfHost;
  return std::nullopt;
}

}  // namespace skytrack::daemon
