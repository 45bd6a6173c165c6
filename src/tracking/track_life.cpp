#include "skytrack/tracking/track_life.hpp"

#include <algorithm>
#include <bit>

namespace skytrack {

TrackLife initiated_life(int plots, int scans) noexcept {
  TrackLife life;
  life.scans = std::max(1, scans);
  life.hits = plots;
  // The first and the last initiating plots bound the window; the others sit just before
  // the last one (which scans they came from does not matter for M-of-N).
  const int span = std::min(life.scans, 32);
  life.history = 1u | (1u << (span - 1));
  for (int i = 1; i < plots - 1 && i < span - 1; ++i) life.history |= 1u << i;
  return life;
}

LifeChange advance_life(TrackLife& life, bool detected, double position_sigma,
                        const config::TrackLifeSpec& spec) noexcept {
  LifeChange change;
  life.history = (life.history << 1) | (detected ? 1u : 0u);
  ++life.scans;
  if (detected) {
    ++life.hits;
    life.consecutive_misses = 0;
  } else {
    ++life.consecutive_misses;
  }

  const bool firm = life.status == TrackStatus::kConfirmed || life.status == TrackStatus::kCoasting;
  if (!firm) {
    const int window = std::min(spec.confirm_n, 32);
    const std::uint32_t mask = window == 32 ? 0xFFFFFFFFu : (1u << window) - 1u;
    if (std::popcount(life.history & mask) >= spec.confirm_m) {
      life.status = TrackStatus::kConfirmed;
      change.confirmed = true;
    } else if (life.consecutive_misses >= spec.delete_tentative_misses ||
               position_sigma > spec.delete_position_sigma) {
      life.status = TrackStatus::kDeleted;
      change.deleted = true;
    }
    return change;
  }
  if (life.consecutive_misses >= spec.delete_confirmed_misses ||
      position_sigma > spec.delete_position_sigma) {
    life.status = TrackStatus::kDeleted;
    change.deleted = true;
  } else if (!detected) {
    change.started_coasting = life.status != TrackStatus::kCoasting;
    life.status = TrackStatus::kCoasting;
  } else {
    life.status = TrackStatus::kConfirmed;
  }
  return change;
}

}  // namespace skytrack
