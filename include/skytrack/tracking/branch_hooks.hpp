#pragma once
// The seam between the plain IMM-JPDA point tracker and its branch layer (paper 003,
// branch_layer.hpp): the points of a look where the branch layer joins in. This base class
// answers as the plain tracker (branching off: nothing happens, every track takes its
// non-manoeuvre gate and its plain life step); BranchLayer overrides it. The tracker and its
// components call the hooks unconditionally, so no option test is spread through them.
#include <cstdint>
#include <span>
#include <utility>

#include "skytrack/core/look.hpp"
#include "skytrack/core/scan_report.hpp"
#include "skytrack/core/track_report.hpp"
#include "skytrack/filter/imm_filter.hpp"
#include "skytrack/tracking/initiator.hpp"
#include "skytrack/tracking/point_track.hpp"

namespace skytrack {

struct PointLook;

class BranchHooks {
 public:
  virtual ~BranchHooks() = default;

  // A look (point_tracker.cpp), in this order.
  /// The look's parts, held for the hooks until end.
  virtual void begin(PointLook& /*look*/) {}
  virtual void before_gating() {}
  /// Collects the suspended fathers that may still branch and continues them with the
  /// fathers confirmed in this look in their manoeuvre gates (§3.3).
  virtual void before_initiation(const PlotScan& /*scan*/, ScanReport& /*report*/) {}
  /// True when a chain completed in the initiator starts something else than a new father
  /// (a lost father's son).
  virtual bool take_chain(const Initiation& /*initiation*/, ScanReport& /*report*/,
                          TrackFrame& /*frame*/) {
    return false;
  }
  /// Track t is a new father started from `initiation`.
  virtual void father_started(int /*t*/, const Initiation& /*initiation*/) {}
  virtual void after_initiation() {}
  /// Fathers numbered on confirmation: (provisional, number).
  virtual void renamed(std::span<const std::pair<std::int64_t, std::int64_t>> /*renamed*/) {}
  virtual void end() {}

  // Gating (gater.hpp), per track.
  /// Track t's prediction `mid` to the batch's middle `time`, `covered` when the look ages
  /// it: true when it takes non-manoeuvre candidates (a father suspended here does not).
  virtual bool at_mid_batch(int /*t*/, bool /*covered*/, const Gaussian& /*mid*/, double /*time*/) {
    return true;
  }
  /// May replace `predicted` (track t's, at its update time) with the prediction its gate
  /// is tested on (its last motion), and mark it in a clutter area, from the plots round it.
  virtual void narrow(int /*t*/, ImmEstimate& /*predicted*/, std::span<const int> /*neighbours*/,
                      std::uint8_t& /*clutter_area*/) {}

  // A father's update (imm_pda_updater.hpp).
  /// After its IMM-PDA update with candidates; `valid`: a plot likelier than its miss
  /// (paper 003 §2.2).
  virtual void updated(PointTrack& /*track*/, bool /*valid*/) {}
  /// Its track life's input: whether it was detected, given the plain tracker's answer.
  virtual bool detected(int /*t*/, bool /*valid*/, bool plain) { return plain; }
  /// Its track life confirmed it.
  virtual void confirmed(int /*t*/) {}

  // The look's report (track_reporter.hpp).
  /// The branch whose estimate the report gives for `father` in this look: one of its sons
  /// or grandsons that took a plot in this look while the father took none, likelier than
  /// the father's own prediction; null if none.
  virtual const PointTrack* stand_in(const PointTrack& /*father*/) const { return nullptr; }
};

}  // namespace skytrack
