#pragma once
// One sensor's clock: the number and time of its latest accepted batch. A batch must come
// after it (a higher number, a time not earlier and not further ahead than a bound), so that
// a duplicate, a late batch or a corrupted time never reaches the tracks, and one batch dated
// years ahead cannot set the clock and lock the sensor out. A sensor whose clock really
// restarts (a reboot, a new recording) delivers batches that follow each other but not the
// old clock: after kRestartBatches of them in a row the clock restarts at the last.
#include <cstdint>
#include <optional>
#include <string_view>

namespace skytrack {

/// Why a batch was not tracked: short fixed names, counted by the daemon's status.
namespace batch_reason {
inline constexpr std::string_view kNonFiniteTime = "non-finite batch time";
inline constexpr std::string_view kNonFinitePlatform = "non-finite platform state";
inline constexpr std::string_view kDuplicateScan = "duplicate scan";
inline constexpr std::string_view kOutOfOrderScan = "out-of-order scan";
inline constexpr std::string_view kTimeBackwards = "time goes backwards";
inline constexpr std::string_view kTimeJump = "time jumps forward";
inline constexpr std::string_view kClockDisagrees = "clock disagrees with the other sensors";
}  // namespace batch_reason

class BatchClock {
 public:
  /// Refused batches in a row, in order among themselves, that restart the clock: one
  /// corrupted batch (or two) is refused, a sensor that goes on from a new time is followed.
  static constexpr int kRestartBatches = 3;

  struct Verdict {
    std::string_view refusal;  // empty: accepted
    bool restarted = false;    // accepted as the third of a new clock's batches
  };

  /// Judges the next batch; an accepted one advances the clock. `max_jump` [s] bounds the
  /// forward step from the clock, and between the batches of a restart.
  Verdict admit(std::uint64_t scan, double time, double max_jump);

  struct Mark {
    std::uint64_t scan = 0;
    double time = 0.0;
  };
  /// The latest accepted batch, if any.
  const std::optional<Mark>& latest() const { return latest_; }

 private:
  /// Why `next` cannot follow `mark`, or empty.
  static std::string_view refusal(const Mark& mark, const Mark& next, double max_jump);

  std::optional<Mark> latest_;
  std::optional<Mark> restart_;  // the latest of the refused batches in a row
  int restart_batches_ = 0;
};

}  // namespace skytrack
