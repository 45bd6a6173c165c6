#pragma once
// The point tracker's track-life rules that depend on where a track is (not installed): a
// target masked in a clutter area is not evidence that there is none (IPDA with a
// detectability chain, branching.detectability), elsewhere P_D alone.
#include "skytrack/config/profile.hpp"
#include "skytrack/tracking/track_life.hpp"

namespace skytrack::tracking_detail {

/// The detectability chain of a track in a clutter area or not.
inline config::DetectabilitySpec detectability_at(const config::TrackingProfile& profile,
                                                  bool clutter_area) {
  // Masking is a clutter area's (branching.last_motion_false_plots): elsewhere a miss is
  // independent of the last, as P_D says.
  config::DetectabilitySpec chain = profile.point.branching.detectability;
  if (!clutter_area) chain.hide = 0.0;
  return chain;
}

/// One scan's TrackLife::support (`best`: the likeliest plot's ratio; 0: a miss) and the
/// detectability update (`sum` of the ratios).
inline void add_support(const config::TrackingProfile& profile, TrackLife& life, double best,
                        double sum, bool clutter_area) {
  const double pd = support_detection_probability(life, profile.association.detection_probability,
                                                  detectability_at(profile, clutter_area));
  life.support += scan_support(best, pd, profile.association.gate_probability);
  update_detectability(life, sum, profile.association.detection_probability,
                       profile.association.gate_probability,
                       detectability_at(profile, clutter_area));
}

/// One look's weighing of a track by its gated plots (`best`, `sum` as for add_support): the
/// existence update on P_D on its detectability chain, then its support.
inline void weigh_look(const config::TrackingProfile& profile, TrackLife& life, double best,
                       double sum, bool clutter_area) {
  update_existence(life, sum,
                   support_detection_probability(life, profile.association.detection_probability,
                                                 detectability_at(profile, clutter_area)),
                   profile.association.gate_probability, profile.point.track_life);
  add_support(profile, life, best, sum, clutter_area);
}

}  // namespace skytrack::tracking_detail
