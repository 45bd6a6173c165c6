#pragma once
// Track output of one processed scan (CONTRACTS.md §3).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "skytrack/core/track_event.hpp"
#include "skytrack/core/truth.hpp"

namespace skytrack {

enum class TrackStatus : std::uint8_t { kTentative, kConfirmed, kCoasting, kDeleted };

std::string_view to_string(TrackStatus status);
std::optional<TrackStatus> parse_track_status(std::string_view text);

/// True for the statuses an evaluator scores (confirmed or coasting).
inline bool is_reported_as_firm(TrackStatus status) {
  return status == TrackStatus::kConfirmed || status == TrackStatus::kCoasting;
}

/// Provisional numbers (tentative tracks, branches) start here, clear of any number a
/// confirmed track is given.
inline constexpr std::int64_t kProvisionalNumber = std::int64_t{1} << 40;

/// A local track a fused system track is made of: the sensor (tracker) and its track number.
struct TrackSource {
  std::uint32_t sensor = 0;
  std::int64_t track = 0;

  bool operator==(const TrackSource&) const = default;
};

struct TrackReport {
  std::int64_t id = 0;
  TrackStatus status = TrackStatus::kTentative;
  ObjectKind kind = ObjectKind::kPoint;
  int dims = 2;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  /// Row-major over [x, vx, y, vy] (dims 2) or [x, vx, y, vy, z, vz] (dims 3); empty if unknown.
  std::vector<double> covariance;
  std::vector<std::pair<std::string, double>> modes;  // model name -> probability
  std::optional<double> quality;
  std::optional<Eigen::Matrix2d> extent;
  std::optional<int> members;
  /// Fusion output only: the local tracks this system track fuses (empty elsewhere).
  std::vector<TrackSource> sources;

  bool operator==(const TrackReport&) const = default;
};

/// One association decision: plot -> track with its probability (JPDA beta, or 1).
struct Association {
  std::int64_t track = 0;
  std::int64_t plot = 0;
  double probability = 1.0;
  // The batch the plot arrived in, when it is not this frame's: a rotating antenna's plot
  // held over to a later look (its id is unique within that batch only).
  std::optional<std::uint64_t> scan;

  bool operator==(const Association&) const = default;
};

struct TrackFrame {
  std::uint32_t sensor = 0;
  std::uint64_t scan = 0;
  double time = 0.0;
  std::vector<TrackReport> tracks;
  std::vector<Association> associations;
  std::vector<TrackEvent> events;

  bool operator==(const TrackFrame&) const = default;
};

}  // namespace skytrack
