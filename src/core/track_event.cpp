#include "skytrack/core/track_event.hpp"

#include <utility>

namespace skytrack {

std::string_view to_string(TrackEventType type) {
  switch (type) {
    case TrackEventType::kInitiated:
      return "initiated";
    case TrackEventType::kConfirmed:
      return "confirmed";
    case TrackEventType::kCoasting:
      return "coasting";
    case TrackEventType::kDeleted:
      return "deleted";
    case TrackEventType::kBranchCreated:
      return "branch_created";
    case TrackEventType::kBranchPromoted:
      return "branch_promoted";
    case TrackEventType::kBranchPruned:
      return "branch_pruned";
    case TrackEventType::kSuspended:
      return "suspended";
    case TrackEventType::kUndecided:
      return "undecided";
    case TrackEventType::kClutterRejected:
      return "clutter_rejected";
    case TrackEventType::kJpdaApproximated:
      return "jpda_approximated";
    case TrackEventType::kPlotCloud:
      return "plot_cloud";
    case TrackEventType::kOverload:
      return "overload";
    case TrackEventType::kOther:
      break;
  }
  return "";
}

std::optional<TrackEventType> parse_track_event_type(std::string_view text) {
  for (const TrackEventType type : kTrackEventTypes) {
    if (to_string(type) == text) return type;
  }
  return std::nullopt;
}

std::string_view type_name(const TrackEvent& event) {
  return event.type == TrackEventType::kOther ? std::string_view(event.other_type)
                                              : to_string(event.type);
}

TrackEvent event_from_name(std::string_view name, std::int64_t track, std::string detail) {
  TrackEvent event{TrackEventType::kOther, track, std::move(detail), {}};
  if (const auto type = parse_track_event_type(name)) {
    event.type = *type;
  } else {
    event.other_type = name;
  }
  return event;
}

}  // namespace skytrack
