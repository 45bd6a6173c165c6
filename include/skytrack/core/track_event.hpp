#pragma once
// Track-management events (CONTRACTS.md §3 "events"): a closed set in the core; their names
// are the edges' business (JSON Lines, DDS), which use to_string / parse_track_event_type.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace skytrack {

enum class TrackEventType : std::uint8_t {
  kInitiated,
  kConfirmed,
  kCoasting,
  kDeleted,
  kBranchCreated,
  kBranchPromoted,
  kBranchPruned,
  kSuspended,
  kUndecided,
  kClutterRejected,
  kJpdaApproximated,
  kPlotCloud,
  kOverload,
  kOther,  // read at an edge under a name the core does not know (TrackEvent::other_type)
};

/// Every type the core emits, for tests and tools that enumerate them (not kOther).
inline constexpr TrackEventType kTrackEventTypes[] = {
    TrackEventType::kInitiated,        TrackEventType::kConfirmed,
    TrackEventType::kCoasting,         TrackEventType::kDeleted,
    TrackEventType::kBranchCreated,    TrackEventType::kBranchPromoted,
    TrackEventType::kBranchPruned,     TrackEventType::kSuspended,
    TrackEventType::kUndecided,        TrackEventType::kClutterRejected,
    TrackEventType::kJpdaApproximated, TrackEventType::kPlotCloud,
    TrackEventType::kOverload};

/// The name in the interchange formats ("initiated", "branch_created", ...); "" for kOther.
std::string_view to_string(TrackEventType type);
/// The type of a known name; nullopt for any other text (kOther is never parsed).
std::optional<TrackEventType> parse_track_event_type(std::string_view text);

/// A track-management decision (initiated, confirmed, branch_created, ...).
struct TrackEvent {
  TrackEventType type = TrackEventType::kOther;
  std::int64_t track = 0;
  std::string detail;
  // kOther only: the name it was read with, so that a line from a newer or foreign writer
  // is written back unchanged (the readers' round trip).
  std::string other_type;

  bool operator==(const TrackEvent&) const = default;
};

/// The event's name as the edges write it: its type's, or the name it was read with.
std::string_view type_name(const TrackEvent& event);
/// The event an edge reads: a known name gives its type, any other is kept as kOther.
TrackEvent event_from_name(std::string_view name, std::int64_t track, std::string detail);

}  // namespace skytrack
