#include "adversary_actions.hpp"

#include <algorithm>

namespace skytrack::adversary {
namespace {

constexpr int kMalformedPlots = 6;  // plots of the valid batch sent before each malformed one
constexpr int kHijackBatches = 3;   // BatchClock::kRestartBatches

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

}  // namespace

void Adversary::send(const PlotScan& scan, PhaseTally& tally) {
  const auto t0 = Clock::now();
  const auto ok = link_.write(scan);
  tally.write_seconds += seconds_since(t0);
  ++tally.batches;
  tally.plots += scan.plots.size();
  if (!ok) {
    if (tally.write_errors++ == 0) tally.first_error = ok.error().message;
  }
}

void Adversary::send_malformed(Malformation kind, double time, PhaseTally& tally) {
  const auto t0 = Clock::now();
  auto sample = batches_.malformed(kind, time);
  Expected<void> ok = sample ? link_.write(*sample) : unexpected(sample.error());
  tally.write_seconds += seconds_since(t0);
  ++tally.batches;
  ++tally.malformed;
  if (sample) tally.plots += sample->get().plot_ids._length;
  if (!ok) {
    if (tally.write_errors++ == 0) tally.first_error = ok.error().message;
  }
}

void Adversary::act(const Phase& phase, double time, double next_time, PhaseTally& tally) {
  if (&phase != phase_) {
    phase_ = &phase;
    next_event_ = phase.begin;
    events_ = 0;
  }
  if (phase.kind == PhaseKind::kQuiet || time >= phase.active_end) return;
  if (phase.kind == PhaseKind::kMalformed) {  // every good batch
    send(batches_.spread(time, kMalformedPlots), tally);
    send_malformed(static_cast<Malformation>(malformation_), time, tally);
    malformation_ = (malformation_ + 1) % static_cast<int>(Malformation::kCount);
    return;
  }
  if (time < next_event_) return;
  event(phase, time, next_time, tally);
  ++events_;
  while (next_event_ <= time) next_event_ += options_.period;
}

void Adversary::event(const Phase& phase, double time, double next_time, PhaseTally& tally) {
  switch (phase.kind) {
    case PhaseKind::kCloud:
      send(batches_.cloud(time, phase.size), tally);
      break;
    case PhaseKind::kBurst: {
      if (events_ >= options_.bursts) break;
      // Spread over the first half of the gap to the next good batch.
      const double gap = std::max(0.0, next_time - time);
      for (int k = 0; k < phase.size; ++k) {
        const double t = time + 0.5 * gap * static_cast<double>(k) / phase.size;
        send(batches_.spread(t, options_.burst_plots), tally);
      }
      break;
    }
    case PhaseKind::kHugeUnder:
    case PhaseKind::kHugeOver:
      if (events_ == 0) send(batches_.spread(time, phase.size), tally);
      break;
    case PhaseKind::kClockHijack:
      if (events_ > 0) break;
      for (int k = 0; k < kHijackBatches; ++k) {
        send(batches_.spread(time + kFiftyYears + k, kMalformedPlots), tally);
      }
      break;
    default:
      break;
  }
}

}  // namespace skytrack::adversary
