#pragma once
// Internal types of the fusion role shared by its source files (not installed).
#include <cstdint>
#include <vector>

#include "skytrack/fusion/covariance_intersection.hpp"
#include "skytrack/fusion/track_distance.hpp"

namespace skytrack::fusion::detail {

/// What the fusion remembers of one local track between cycles.
struct LocalRecord {
  std::vector<HistoryPoint> history;  // increasing cycles, at most the window's
  std::int64_t system = 0;            // the system track it was last fused into (0: none)
  std::uint64_t last_cycle = 0;
};

/// A local track in this cycle, aligned to the cycle's time.
struct PresentTrack {
  std::uint32_t sensor = 0;
  std::int64_t id = 0;
  StateEstimate state;
  PositionEstimate position;
  double sigma2 = 0.0;  // [m^2] trace of the position covariance (spatial gate)
  LocalRecord* record = nullptr;
};

inline PositionEstimate position_of(const StateEstimate& s) {
  PositionEstimate p;
  p.dims = s.dims;
  constexpr int kIndex[3] = {0, 2, 4};
  for (int r = 0; r < 3; ++r) {
    p.mean(r) = s.x(kIndex[r]);
    for (int c = 0; c < 3; ++c) p.cov(r, c) = s.P(kIndex[r], kIndex[c]);
  }
  if (s.dims < 3) {
    p.mean(2) = 0.0;
    p.cov.row(2).setZero();
    p.cov.col(2).setZero();
  }
  return p;
}

}  // namespace skytrack::fusion::detail
