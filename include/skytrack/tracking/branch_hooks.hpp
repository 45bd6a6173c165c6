#pragma once
// Where the branch layer (branch_layer.hpp, paper 003) joins the plain IMM-JPDA tracker's
// gater and updater, per track. With branching off nobody is called: the plain components
// behave as the tracker without a branch layer.
#include <cstdint>
#include <span>

#include "skytrack/filter/imm_filter.hpp"
#include "skytrack/tracking/point_track.hpp"

namespace skytrack {

class BranchHooks {
 public:
  virtual ~BranchHooks() = default;

  // Gating (gater.hpp).
  /// Track t's prediction `mid` to the batch's middle `time`, `covered` when the look ages
  /// it: true when it takes non-manoeuvre candidates (a father suspended here does not).
  virtual bool at_mid_batch(int t, bool covered, const Gaussian& mid, double time) = 0;
  /// May replace `predicted` (track t's, at its update time) with the prediction its gate
  /// is tested on (its last motion), and mark it in a clutter area, from the plots round it.
  virtual void narrow(int t, ImmEstimate& predicted, std::span<const int> neighbours,
                      std::uint8_t& clutter_area) = 0;

  // A father's update (imm_pda_updater.hpp).
  /// After its IMM-PDA update; `valid`: a plot likelier than its miss (paper 003 §2.2).
  virtual void updated(PointTrack& track, bool valid) = 0;
  /// Its track life's input: whether it was detected, given the plain tracker's answer.
  virtual bool detected(int t, bool valid, bool plain) = 0;
  /// Its track life confirmed it.
  virtual void confirmed(int t) = 0;
};

}  // namespace skytrack
