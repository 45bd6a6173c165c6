#pragma once
// When the adversary sends what: after each good batch the run asks it to act, and it sends
// what the current phase sends at that point of stream time. Its batches are dated between
// the good batch just sent and the next, so both sensors' batches reach the shared tracker in
// time order.
#include <cstdint>
#include <string>

#include "adversary_batches.hpp"
#include "dds_link.hpp"
#include "options.hpp"
#include "phase_plan.hpp"

namespace skytrack::adversary {

/// What the adversary sent in one phase.
struct PhaseTally {
  std::uint64_t batches = 0;    // batches written (valid or not)
  std::uint64_t plots = 0;      // plots in them
  std::uint64_t malformed = 0;  // of which malformed samples
  std::uint64_t write_errors = 0;
  double write_seconds = 0.0;  // [s] in conversion and dds_write
  std::string first_error;
};

class Adversary {
 public:
  Adversary(AdversaryBatches& batches, DdsLink& link, const Options& options)
      : batches_(batches), link_(link), options_(options) {}

  /// After the good batch at `time` (the next one at `next_time`): sends what `phase` sends now.
  void act(const Phase& phase, double time, double next_time, PhaseTally& tally);

 private:
  void send(const PlotScan& scan, PhaseTally& tally);
  void send_malformed(Malformation kind, double time, PhaseTally& tally);
  /// The phase's event at `time` (the index-th of the phase).
  void event(const Phase& phase, double time, double next_time, PhaseTally& tally);

  AdversaryBatches& batches_;
  DdsLink& link_;
  const Options& options_;
  const Phase* phase_ = nullptr;
  double next_event_ = 0.0;  // [s] stream time
  int events_ = 0;           // in this phase so far
  int malformation_ = 0;     // the next kind
};

}  // namespace skytrack::adversary
