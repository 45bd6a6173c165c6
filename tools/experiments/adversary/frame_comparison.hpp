#pragma once
// Whether the good sensor's tracks stayed as they are without the adversary: the live frames
// of its batches against an offline Pipeline run of its batches alone. Compared: the firm
// tracks (confirmed or coasting) outside the flooded sector, matched one to one by position
// within a tolerance, with the same status. Track numbers are reported but not required to
// agree: numbers are handed out at confirmation from one counter, so a track the adversary
// gets confirmed legitimately shifts every later number.
#include <optional>
#include <string>
#include <vector>

#include "adversary_geometry.hpp"
#include "skytrack/config/profile.hpp"
#include "skytrack/core/expected.hpp"
#include "skytrack/core/track_report.hpp"

namespace skytrack::adversary {

/// The frame the Pipeline gives each good batch alone (nullopt: it skipped the batch), after
/// the same DDS round trip as the daemon's input.
Expected<std::vector<std::optional<TrackFrame>>> offline_frames(
    const config::TrackingProfile& profile, const std::vector<PlotScan>& scans);

struct FrameVerdict {
  bool unchanged = false;
  bool numbers_differ = false;  // matched tracks with other numbers
  double max_deviation = 0.0;   // [m] between matched tracks
  std::size_t firm = 0;         // firm tracks compared (offline)
  std::size_t adversary = 0;    // live firm tracks inside the sector
  std::string difference;       // the first difference, when changed
};

/// `live` (nullptr: no TrackBatch arrived) against `offline`.
FrameVerdict compare_frames(const TrackFrame* live, const std::optional<TrackFrame>& offline,
                            const AdversaryGeometry& geometry, double tolerance);

}  // namespace skytrack::adversary
