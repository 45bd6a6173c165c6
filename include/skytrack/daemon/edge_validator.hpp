#pragma once
// Scan-level checks at the DDS edge, before a scan reaches the Pipeline: unknown sensors (when
// the configuration lists sensors), duplicate and out-of-order scans per sensor, non-finite
// batch time or platform state. A rejected scan never touches the tracks. The reasons are
// short fixed names, so the status can count them.
#include <cstdint>
#include <map>
#include <optional>
#include <string_view>
#include <vector>

#include "skytrack/core/plot.hpp"

namespace skytrack::daemon {

namespace reason {
inline constexpr std::string_view kUnknownSensor = "unknown sensor";
inline constexpr std::string_view kDuplicateScan = "duplicate scan";
inline constexpr std::string_view kOutOfOrderScan = "out-of-order scan";
inline constexpr std::string_view kTimeBackwards = "time goes backwards";
inline constexpr std::string_view kNonFiniteTime = "non-finite batch time";
inline constexpr std::string_view kNonFinitePlatform = "non-finite platform state";
inline constexpr std::string_view kTooManyPlots = "too many plots";
inline constexpr std::string_view kMalformedSample = "malformed sample";
inline constexpr std::string_view kClutter = "clutter";
inline constexpr std::string_view kPipelineRejected = "rejected by the pipeline";
}  // namespace reason

class EdgeValidator {
 public:
  /// `sensors` empty: every sensor is accepted.
  explicit EdgeValidator(std::vector<std::int64_t> sensors = {});

  /// Why the scan must be skipped, or nullopt; an accepted scan advances its sensor's clock.
  std::optional<std::string_view> check(const PlotScan& scan);

 private:
  struct Clock {
    std::uint64_t scan = 0;
    double time = 0.0;
  };
  std::vector<std::int64_t> sensors_;
  std::map<std::uint32_t, Clock> clocks_;
};

}  // namespace skytrack::daemon
