#include "skytrack/pipeline/batch_clock.hpp"

#include <cmath>

namespace skytrack {

std::string_view BatchClock::refusal(const Mark& mark, const Mark& next, double max_jump) {
  if (next.scan == mark.scan) return batch_reason::kDuplicateScan;
  if (next.scan < mark.scan) return batch_reason::kOutOfOrderScan;
  if (next.time < mark.time) return batch_reason::kTimeBackwards;
  if (next.time - mark.time > max_jump) return batch_reason::kTimeJump;
  return {};
}

BatchClock::Verdict BatchClock::admit(std::uint64_t scan, double time, double max_jump) {
  if (!std::isfinite(time)) return {batch_reason::kNonFiniteTime};
  const Mark next{scan, time};
  const std::string_view why = latest_ ? refusal(*latest_, next, max_jump) : std::string_view{};
  if (why.empty()) {
    latest_ = next;
    restart_.reset();
    restart_batches_ = 0;
    return {};
  }
  // A refused batch that follows the previous refused one continues a possible restart.
  restart_batches_ =
      restart_ && refusal(*restart_, next, max_jump).empty() ? restart_batches_ + 1 : 1;
  restart_ = next;
  if (restart_batches_ < kRestartBatches) return {why};
  latest_ = next;
  restart_.reset();
  restart_batches_ = 0;
  return {{}, true};
}

}  // namespace skytrack
