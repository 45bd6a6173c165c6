#pragma once
// One sensor's batches on their way to the tracker. A snapshot sensor's batch is one look. A
// rotating antenna's plots are regrouped into looks by the azimuth swept (antenna_sweep.hpp,
// look_assembler.hpp), so the same plots give the same tracks however the feed batches them.
// While the sensor's kind is being learnt (its first plots), its batches wait and their
// frames report the tracks as they are.
#include <vector>

#include "skytrack/core/plot.hpp"
#include "skytrack/core/track_report.hpp"
#include "skytrack/pipeline/antenna_sweep.hpp"
#include "skytrack/pipeline/estimator_stages.hpp"
#include "skytrack/pipeline/look_assembler.hpp"

namespace skytrack {

class SensorFeed {
 public:
  explicit SensorFeed(const config::AntennaSpec& antenna) : antenna_(antenna) {}

  /// Gives the tracker the looks this batch completes; `frame` (at the batch's time) gets
  /// their decisions and the tracks after the last of them.
  void feed(const PlotScan& batch, EstimatorStages& tracker, TrackFrame& frame, ScanReport& report);

  const AntennaSweep& antenna() const { return antenna_; }

 private:
  void feed_rotating(const PlotScan& batch, EstimatorStages& tracker);
  /// One look into this batch's frame.
  void look(const PlotScan& scan, const LookSources* sources, EstimatorStages& tracker);
  /// A snapshot look: the whole batch, a revolution of sweep after the sensor's last look.
  void snapshot(const PlotScan& scan, EstimatorStages& tracker);

  AntennaSweep antenna_;
  LookAssembler looks_;
  std::vector<PlotScan> waiting_;  // while the antenna's kind is learnt
  bool waited_out_ = false;        // learning took too long: batches go on as they come
  // The sweep the sensor's looks have reached [rad]: a revolution per snapshot look, the
  // antenna's own once it is known to rotate (tracks compare the two).
  double clock_ = 0.0;
  std::vector<int> own_;  // workspace: every plot its batch's
  // This batch's frame and report while looks are added to it.
  TrackFrame* frame_ = nullptr;
  ScanReport* report_ = nullptr;
  bool looked_ = false;
  // Workspaces (reused).
  std::vector<double> sweeps_;
  std::vector<SearchRegion> regions_;
  std::vector<AzimuthSpan> spans_;
  Look look_;
  TrackFrame look_frame_;
};

}  // namespace skytrack
