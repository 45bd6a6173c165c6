#pragma once
// Track life: tentative -> confirmed -> coasting -> deleted. Confirmation is M of the last N
// scans with a plot, counted from the track's first plot, or (profile's choice) the
// probability of existence reaching a threshold; deletion after K consecutive misses (fewer
// for tentative tracks), when the existence falls below a threshold, or when the position
// uncertainty outgrows a limit.
//
// Existence (IPDA, Musicki, Evans & Stankovic 1994, IEEE Trans. AC-39(6)) per scan:
//   predicted  chi- = P_S chi
//   update     delta = P_D P_G - P_D sum_i L_i / lambda_i   (the track's gated plots, L_i
//              the plot's likelihood, lambda_i the clutter density in measurement space)
//              chi = (1 - delta) chi- / (1 - delta chi-)
// A plot much likelier under the track than as clutter raises chi; a miss multiplies the
// odds by 1 - P_D P_G; clutter alone in the gate leaves them about where they were.
//
// Support (the track score of track-oriented MHT, Blackman 2004, IEEE AES Magazine 19(1))
// per scan: log of the likelihood ratio, target against clutter, of the scan's best single
// hypothesis: the miss, 1 - P_D P_G, or its likeliest plot as the target, P_D L_i / lambda_i.
// Two hypotheses of one target compare on it (branching.coast_sons).
//
// Detectability (branching.detectability, Musicki et al.'s "Markov chain two"), for the support
// only, where the tracker applies it (a clutter area): the probability d that the target is
// detectable, not hidden, predicted per scan
//   d- = (1 - hide) d + reveal (1 - d)
// and updated like the existence, a hidden target's plots being all clutter:
//   d = d- (1 - delta) / (d- (1 - delta) + 1 - d-),  delta as above.
// The support then weighs the scan at P_D d-: after a miss with nothing in the gate the next
// miss costs less (four in a row from a detection at P_D 0.9, hide 0.05, reveal 0.3: log of
// 0.145, 0.35, 0.61, 0.69 instead of log 0.1 each), a target masked for a few looks being
// likelier than independent misses say.
#include <cstdint>

#include "skytrack/config/profile.hpp"
#include "skytrack/core/track_report.hpp"

namespace skytrack {

/// Detection history of one track, one bit per scan (bit 0 = the latest).
struct TrackLife {
  TrackStatus status = TrackStatus::kTentative;
  std::uint32_t history = 0;  // 1 = detected in that scan
  int scans = 0;              // scans since the first plot, inclusive
  int consecutive_misses = 0;
  int hits = 0;
  double existence = 1.0;   // probability that the track is a target (existence method)
  double support = 0.0;     // summed scan_support of its scans since it started
  double detectable = 1.0;  // probability that the target was detectable in the last scan
};

/// What a scan's outcome did to a track's life.
struct LifeChange {
  bool confirmed = false;  // became confirmed this scan
  bool started_coasting = false;
  bool deleted = false;
};

/// Applies one scan's outcome: `detected` when the track had plots this scan (for JPDA, when
/// its probability of detection sum(beta) exceeded one half), `position_sigma` is
/// sqrt(max eigenvalue) of the position covariance [m].
LifeChange advance_life(TrackLife& life, bool detected, double position_sigma,
                        const config::TrackLifeSpec& spec) noexcept;

/// One scan's existence update (see the top of this file); `likelihood_ratio` is
/// sum_i L_i / lambda_i over the track's gated plots (0 when it had none).
void update_existence(TrackLife& life, double likelihood_ratio, double detection_probability,
                      double gate_probability, const config::TrackLifeSpec& spec) noexcept;

/// One scan's support (see the top of this file); `best_ratio` is the largest L_i / lambda_i
/// over the track's gated plots (0 when it had none).
double scan_support(double best_ratio, double detection_probability,
                    double gate_probability) noexcept;

/// The detection probability with which the track's next scan counts in its support: P_D
/// times its predicted detectability.
double support_detection_probability(const TrackLife& life, double detection_probability,
                                     const config::DetectabilitySpec& spec) noexcept;

/// One scan's detectability update (see the top of this file), after the support of that
/// scan; `likelihood_ratio` as for update_existence.
void update_detectability(TrackLife& life, double likelihood_ratio, double detection_probability,
                          double gate_probability, const config::DetectabilitySpec& spec) noexcept;

/// The least existence with which a new track outlives its next look if that look has no plot
/// for it: below it, the miss takes the existence under delete_existence. The miss is weighed
/// at P_D times a fresh track's predicted detectability (the most lenient weighing a track's
/// miss gets). 0 when tracks are confirmed by M of N (existence deletes none then).
double existence_to_outlive_a_miss(double detection_probability, double gate_probability,
                                   const config::TrackLifeSpec& spec,
                                   const config::DetectabilitySpec& detectability) noexcept;

/// Starts a life from an initiation that used `plots` plots over `scans` scans.
TrackLife initiated_life(int plots, int scans) noexcept;

}  // namespace skytrack
