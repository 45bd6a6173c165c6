#pragma once
// The display's frame document (docs/display.md "Frame"): compact JSON the page draws from.
// Positions are rounded to 0.1 m and covariances to 3 significant digits: the page draws
// pixels, and a 1000-track, 20000-plot frame must stay a few hundred kilobytes.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "skytrack/core/track_report.hpp"
#include "skytrack/core/tracker_status.hpp"
#include "skytrack/core/truth.hpp"
#include "skytrack/display/picture.hpp"

namespace skytrack::display {

struct PictureSnapshot {
  struct Sensor {
    std::uint32_t id = 0;
    std::vector<std::shared_ptr<const PlotLayer>> plots;  // newest first
    std::shared_ptr<const TrackFrame> tracks;
  };
  std::uint64_t version = 0;
  std::string mode;
  std::string replay_json;
  std::vector<Sensor> sensors;
  std::vector<std::shared_ptr<const TrackerStatusReport>> status;
  std::shared_ptr<const TruthFrame> truth;
};

std::string to_json(const PictureSnapshot& snapshot);
/// One daemon's status (the fields of `skytrack status`, rejections by reason).
std::string to_json(const TrackerStatusReport& status);

}  // namespace skytrack::display
