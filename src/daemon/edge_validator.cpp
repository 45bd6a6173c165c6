#include "skytrack/daemon/edge_validator.hpp"

#include <algorithm>
#include <cmath>

namespace skytrack::daemon {

EdgeValidator::EdgeValidator(std::vector<std::int64_t> sensors) : sensors_(std::move(sensors)) {}

std::optional<std::string_view> EdgeValidator::check(const PlotScan& scan) {
  if (!sensors_.empty() && std::find(sensors_.begin(), sensors_.end(),
                                     static_cast<std::int64_t>(scan.sensor)) == sensors_.end()) {
    return reason::kUnknownSensor;
  }
  if (!std::isfinite(scan.time)) return reason::kNonFiniteTime;
  const auto it = clocks_.find(scan.sensor);
  if (it != clocks_.end()) {
    if (scan.scan == it->second.scan) return reason::kDuplicateScan;
    if (scan.scan < it->second.scan) return reason::kOutOfOrderScan;
    if (scan.time < it->second.time) return reason::kTimeBackwards;
  }
  if (!scan.platform.position.allFinite() || !scan.platform.velocity.allFinite() ||
      !scan.platform.attitude.allFinite()) {
    return reason::kNonFinitePlatform;
  }
  clocks_[scan.sensor] = {scan.scan, scan.time};
  return std::nullopt;
}

}  // namespace skytrack::daemon
