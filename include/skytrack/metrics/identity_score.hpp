#pragma once
// Scores a track output against the identities secondary-radar plots carry (Mode S address,
// else Mode 3/A code), for real recordings that have no ground truth. A segment is one
// identity's plots with no gap longer than `gap`; a track holds a plot when it is the
// confirmed or coasting track likeliest to have taken it in its batch.
//
// - breaks: per segment, the distinct tracks holding 3 or more of its plots, minus one.
// - purity: the share of held identity plots that belong to their track's dominant identity.
//   An aircraft's code change (one identity's segment ends and another's starts within `gap`
//   seconds, where the first one ended, at airliner speed) links the two identities, so a
//   track that keeps the aircraft through it stays pure; the links come from the plots alone.
// - coverage: the share of identity plots held by a track.
// Generic Mode 3/A codes (conspicuity, emergency, test: 0000, 1200, 2000, 7000, 7500, 7600,
// 7700, 7777) are not identities.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace skytrack::metrics {

struct IdentityPlot {
  double time = 0.0;
  std::string identity;               // "S:4CA2D7" (Mode S) or "A:2270" (Mode 3/A); empty: none
  double x = 0.0, y = 0.0;            // [m] horizontal position
  double range = 0.0;                 // [m] from the radar
  std::optional<std::int64_t> track;  // the track holding it
};

/// The identity a plot's transponder attributes give, or empty.
std::string plot_identity(std::optional<std::uint16_t> mode3a, std::optional<std::uint32_t> mode_s);

struct IdentitySegment {
  std::string identity;
  double first = 0.0, last = 0.0;           // [s]
  double min_range = 0.0, max_range = 0.0;  // [m]
  int plots = 0, held = 0;
  int breaks = 0;
  std::vector<std::int64_t> tracks;  // holding 3 or more of its plots, most plots first
};

struct IdentityScore {
  int identity_plots = 0, held_plots = 0;
  int segments = 0, breaks = 0, segments_with_breaks = 0;
  int code_changes = 0;
  double breaks_per_segment = 0.0;
  double purity = 1.0;
  double coverage = 0.0;
  std::vector<IdentitySegment> worst;  // most breaks, then most plots not held
};

struct IdentityScoreConfig {
  double gap = 20.0;       // [s] a longer silence ends a segment
  std::size_t worst = 10;  // segments listed
};

IdentityScore score_identities(const std::vector<IdentityPlot>& plots,
                               const IdentityScoreConfig& config);

}  // namespace skytrack::metrics
