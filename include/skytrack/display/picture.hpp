#pragma once
// The operator display's picture: the latest track frame per sensor, the plots of the last few
// scans per sensor, the latest status per daemon instance and (offline replay) the truth. DDS
// reception or the replay writes it; the web server's threads read it as one JSON document.
// Writers only swap shared pointers under a mutex, so a slow browser never holds up reception;
// the JSON is built outside the lock, once per version, whoever asks first.
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "skytrack/core/plot.hpp"
#include "skytrack/core/track_report.hpp"
#include "skytrack/core/tracker_status.hpp"
#include "skytrack/core/truth.hpp"

namespace skytrack::display {

/// One scan's plots in the tracking frame, as the page draws them.
struct PlotLayer {
  std::uint64_t scan = 0;
  double time = 0.0;                          // [s]
  double platform_x = 0.0, platform_y = 0.0;  // [m] sensor position (range rings)
  std::vector<float> xy;                      // [m] x0, y0, x1, y1, ... (float: a metre is plenty)
};

/// The picture as the page receives it, and the version it shows.
struct FrameDocument {
  std::uint64_t version = 0;
  std::string json;
};

/// A scan's plots converted to the tracking frame (polar plots with the scan's platform).
PlotLayer to_plot_layer(const PlotScan& scan);

class Picture {
 public:
  /// `plot_scans`: how many scans of plots are kept per sensor (the page fades the older).
  explicit Picture(int plot_scans = 4);

  void add_plots(const PlotScan& scan);
  void add_tracks(TrackFrame frame);
  void add_status(TrackerStatusReport status);
  void set_truth(TruthFrame truth);
  /// "live" or "replay"; `replay_json` is the replay's position and controls (a JSON object).
  void set_mode(std::string mode);
  void set_replay(std::string replay_json);
  /// Forgets plots, tracks and truth (a replay restarting); status and mode stay.
  void clear();

  std::uint64_t version() const;
  /// Blocks until the version differs from `seen`, stop() is called or `timeout` passes.
  std::uint64_t wait_for_change(std::uint64_t seen, std::chrono::milliseconds timeout) const;
  /// Wakes every waiter for good (server shutdown).
  void stop();
  bool stopped() const;

  /// The whole picture (docs/display.md "Frame"), built once per version.
  std::shared_ptr<const FrameDocument> frame_json();
  /// One track of `sensor`'s latest frame with its associations and events, as a track-output
  /// line (docs/formats.md); nullopt when that frame has no such track.
  std::optional<std::string> track_json(std::uint32_t sensor, std::int64_t id) const;

 private:
  struct Sensor {
    std::deque<std::shared_ptr<const PlotLayer>> plots;  // newest first
    std::shared_ptr<const TrackFrame> tracks;
  };
  void touch();  // bumps the version and wakes the waiters; mutex_ held

  const std::size_t plot_scans_;
  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  std::uint64_t version_ = 1;
  bool stopped_ = false;
  std::map<std::uint32_t, Sensor> sensors_;
  std::map<std::string, std::shared_ptr<const TrackerStatusReport>> status_;
  std::shared_ptr<const TruthFrame> truth_;
  std::string mode_ = "live";
  std::string replay_json_ = "null";

  std::mutex cache_mutex_;
  std::shared_ptr<const FrameDocument> cached_;
};

}  // namespace skytrack::display
