#pragma once
// Offline replay for `skytrack display --plots --tracks [--truth]`: the files are read at
// start, then played into the Picture at `rate` times their own time, one track frame at a
// time, with play, pause, step and restart from the page.
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <string>
#include <vector>

#include "skytrack/core/expected.hpp"
#include "skytrack/core/plot.hpp"
#include "skytrack/core/track_report.hpp"
#include "skytrack/core/truth.hpp"
#include "skytrack/display/picture.hpp"

namespace skytrack::tool {

struct ReplayFiles {
  std::vector<PlotScan> plots;
  std::vector<TrackFrame> tracks;
  std::vector<TruthFrame> truth;
};
/// Reads the three files (truth optional); bad lines are reported on stderr and skipped.
Expected<ReplayFiles> load_replay_files(const std::string& plots, const std::string& tracks,
                                        const std::string& truth);

class DisplayReplay {
 public:
  DisplayReplay(display::Picture& picture, ReplayFiles files, double rate);

  /// Plays until `stop()` returns true (polled every 100 ms); pauses at the end.
  template <class StopFn>
  void run(StopFn stop) {
    while (!stop()) tick();
  }
  /// "play", "pause", "step" (one track frame, then paused), "restart"; `rate` > 0 sets it.
  Expected<std::string> control(const std::string& cmd, double rate);

 private:
  void tick();
  void advance();        // shows the next track frame; mutex_ held
  void publish_state();  // mutex_ held
  double frame_time(std::size_t i) const;

  display::Picture& picture_;
  const ReplayFiles files_;
  std::mutex mutex_;
  std::condition_variable wake_;
  double rate_;
  bool playing_ = true;
  std::size_t next_frame_ = 0;  // the next track frame to show
  std::size_t next_plots_ = 0;
  std::size_t next_truth_ = 0;
};

}  // namespace skytrack::tool
