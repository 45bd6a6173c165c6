#pragma once
// Checks at the daemon's edge, before a batch reaches the Pipeline: unknown sensors (when the
// configuration lists sensors), and, when configured, a batch time too far ahead of the host's
// clock (for sensors that date their batches in UTC seconds since 1970). Order and time per
// sensor are the Pipeline's (batch_clock.hpp). The reasons are short fixed names, so the
// status can count them.
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "skytrack/core/plot.hpp"

namespace skytrack::daemon {

namespace reason {
inline constexpr std::string_view kUnknownSensor = "unknown sensor";
inline constexpr std::string_view kAheadOfHost = "time ahead of the host clock";
inline constexpr std::string_view kTooManyPlots = "too many plots";
inline constexpr std::string_view kMalformedSample = "malformed sample";
inline constexpr std::string_view kClutter = "clutter";
}  // namespace reason

class EdgeValidator {
 public:
  /// `sensors` empty: every sensor is accepted. `max_ahead` [s]: a batch dated further ahead
  /// of the host's UTC clock is refused; nullopt: not checked.
  explicit EdgeValidator(std::vector<std::int64_t> sensors = {},
                         std::optional<double> max_ahead = std::nullopt);

  /// Why the batch must be skipped, or nullopt; `host_time` is the host's UTC clock [s since
  /// 1970].
  std::optional<std::string_view> check(const PlotScan& scan, double host_time) const;

 private:
  std::vector<std::int64_t> sensors_;
  std::optional<double> max_ahead_;
};

}  // namespace skytrack::daemon
