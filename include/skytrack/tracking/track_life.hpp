#pragma once
// Track life: tentative -> confirmed -> coasting -> deleted. Confirmation is M of the last N
// scans with a plot, counted from the track's first plot; deletion after K consecutive
// misses (fewer for tentative tracks) or when the position uncertainty outgrows a limit.
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

/// Starts a life from an initiation that used `plots` plots over `scans` scans.
TrackLife initiated_life(int plots, int scans) noexcept;

}  // namespace skytrack
