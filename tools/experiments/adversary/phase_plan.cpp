#include "phase_plan.hpp"

#include <fmt/format.h>

namespace skytrack::adversary {
namespace {

/// Number of adversarial phases the options ask for.
int adversarial_phases(const Options& o) {
  return static_cast<int>(o.cloud_sizes.size()) + (o.bursts > 0 ? 1 : 0) + (o.huge ? 2 : 0) +
         (o.malformed ? 1 : 0) + (o.clock_hijack ? 1 : 0);
}

}  // namespace

double planned_duration(const Options& o) {
  return o.warmup + o.phase * adversarial_phases(o) + o.recovery;
}

std::vector<Phase> plan_phases(const Options& o, int max_plots, double start) {
  std::vector<Phase> phases;
  double t = start;
  const auto quiet = [&](const std::string& name, double length) {
    phases.push_back({name, PhaseKind::kQuiet, 0, t, t, t + length, "sensor 1 alone"});
    t += length;
  };
  const auto add = [&](std::string name, PhaseKind kind, int size, std::string what) {
    phases.push_back(
        {std::move(name), kind, size, t, t + o.phase - o.settle, t + o.phase, std::move(what)});
    t += o.phase;
  };
  quiet("warm-up", o.warmup);
  for (const int n : o.cloud_sizes) {
    add(fmt::format("cloud {}", n), PhaseKind::kCloud, n,
        fmt::format("a batch of {} co-located plots every {} s", n, o.period));
  }
  if (o.bursts > 0) {
    add(fmt::format("burst {}x{}", o.bursts, o.burst_batches), PhaseKind::kBurst, o.burst_batches,
        fmt::format("{} bursts of {} batches of {} plots, back to back, {} s apart", o.bursts,
                    o.burst_batches, o.burst_plots, o.period));
  }
  if (o.huge) {
    add(fmt::format("huge {}", max_plots - 1), PhaseKind::kHugeUnder, max_plots - 1,
        fmt::format("one batch of {} plots spread over the sector (max_plots_per_scan {})",
                    max_plots - 1, max_plots));
    add(fmt::format("huge {}", max_plots + 1), PhaseKind::kHugeOver, max_plots + 1,
        fmt::format("one batch of {} plots (max_plots_per_scan {})", max_plots + 1, max_plots));
  }
  if (o.malformed) {
    add("malformed", PhaseKind::kMalformed, 0,
        "after each sensor-1 batch a valid sensor-2 batch and a malformed sample, each kind in "
        "turn");
  }
  if (o.clock_hijack) {
    add("clock hijack", PhaseKind::kClockHijack, 3,
        "three sensor-2 batches dated 50 years ahead, each following the one before");
  }
  quiet("recovery", o.recovery);
  return phases;
}

}  // namespace skytrack::adversary
