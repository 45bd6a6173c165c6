#include "skytrack/pipeline/sensor_feed.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "skytrack/geometry/frames.hpp"

namespace skytrack {
namespace {

// While the antenna is learnt, at most this many batches or seconds of plots wait; then its
// batches are tracked as they come until the rotation is known.
constexpr std::size_t kMaxWaiting = 64;
constexpr double kMaxWaitTime = 5.0;  // [s]

}  // namespace

void SensorFeed::look(const PlotScan& scan, const LookSources* sources, EstimatorStages& tracker) {
  if (!looked_) {
    tracker.process(scan, sources, *frame_, *report_);
    looked_ = true;
    return;
  }
  // A batch that completes several looks gives one frame: every look's decisions (plots of
  // earlier batches named by their batch), the tracks after the last, and the tracks deleted
  // on the way.
  ScanReport next;
  tracker.process(scan, sources, look_frame_, next);
  for (TrackReport& track : frame_->tracks) {
    if (track.status == TrackStatus::kDeleted) look_frame_.tracks.push_back(std::move(track));
  }
  frame_->tracks.swap(look_frame_.tracks);
  for (Association a : look_frame_.associations) {
    if (!a.scan && look_frame_.scan != frame_->scan) a.scan = look_frame_.scan;
    frame_->associations.push_back(a);
  }
  frame_->events.insert(frame_->events.end(), look_frame_.events.begin(), look_frame_.events.end());
  report_->add_later_look(next);
}

void SensorFeed::snapshot(const PlotScan& scan, EstimatorStages& tracker) {
  clock_ += 2.0 * std::numbers::pi;
  own_.assign(scan.plots.size(), -1);
  sweeps_.assign(scan.plots.size(), clock_);
  const LookSources sources{{}, own_, sweeps_, clock_, true};
  look(scan, &sources, tracker);
}

void SensorFeed::feed(const PlotScan& batch, EstimatorStages& tracker, TrackFrame& frame,
                      ScanReport& report) {
  frame_ = &frame;
  report_ = &report;
  looked_ = false;
  frame.scan = batch.scan;  // the first look's frame is this batch's
  const std::size_t samples = antenna_.samples();
  AntennaSweep::Kind kind = antenna_.read(batch);
  if (kind == AntennaSweep::Kind::kUndecided) {
    // While the batches teach the rotation (their plots' times and azimuths advance
    // together), they wait, so that a sector feed's first batches are not taken for looks at
    // everything; a batch that teaches nothing (one plot a revolution) is tracked as it is.
    const bool learning = antenna_.samples() > samples;
    if (learning && !waited_out_ && waiting_.size() < kMaxWaiting &&
        (waiting_.empty() || batch.time - waiting_.front().time < kMaxWaitTime)) {
      waiting_.push_back(batch);
      tracker.report_only(batch, frame, report);
      return;
    }
    waited_out_ = waited_out_ || learning;
  }
  if (kind != AntennaSweep::Kind::kRotating) {
    for (const PlotScan& waited : waiting_) snapshot(waited, tracker);
    waiting_.clear();
    snapshot(batch, tracker);
  } else {
    for (const PlotScan& waited : waiting_) feed_rotating(waited, tracker);
    waiting_.clear();
    feed_rotating(batch, tracker);
    if (!looked_) tracker.report_only(batch, frame, report);
  }
  // The frame belongs to the batch that arrived.
  frame.scan = batch.scan;
  frame.time = batch.time;
}

void SensorFeed::feed_rotating(const PlotScan& batch, EstimatorStages& tracker) {
  antenna_.place(batch, clock_, sweeps_);
  // How far the beam is known to have swept: to the latest plot, to the batch's time when
  // that is later (a batch stamped when its sweep ended), to the end of its coverage.
  double time = batch.time;
  for (const Plot& plot : batch.plots) time = std::max(time, plot_time(plot, batch));
  double reached = std::max(antenna_.latest(), antenna_.sweep_at(batch.time));
  if (batch.coverage) {
    const double end = antenna_.sense() > 0 ? batch.coverage->to : batch.coverage->from;
    reached =
        std::max(reached, antenna_.sweep_of(end, antenna_.sweep_at(batch.time) - std::numbers::pi));
  }
  // A batch that swept three quarters of a revolution or more by itself comes from a feed that
  // delivers revolutions: it is one look at everything, as it came (and the plots still held go
  // with it).
  double before = looks_.reached();
  if (!looks_.started()) {  // the first batch: from its first plot on
    before = reached;
    for (const double sweep : sweeps_) before = std::min(before, sweep);
  }
  const bool revolution = reached - before >= 1.5 * std::numbers::pi;
  looks_.add(batch, sweeps_, reached);
  if (revolution) {
    looks_.take_all(look_);
    const LookSources sources = look_.sources();
    look(look_.scan, &sources, tracker);
    clock_ = std::max(clock_, look_.sweep_to);
    return;
  }
  for (;;) {
    // Each search region as the beam sees it, from the tracks as they are now.
    tracker.search_regions(batch, time, regions_);
    spans_.clear();
    for (const SearchRegion& region : regions_) {
      const PolarPoint polar = enu_to_polar(region.centre, batch.platform);
      const double half =
          region.radius < polar.range ? std::asin(region.radius / polar.range) : std::numbers::pi;
      spans_.push_back({polar.azimuth, half});
    }
    if (!looks_.take(spans_, antenna_, look_)) break;
    const LookSources sources = look_.sources();
    look(look_.scan, &sources, tracker);
    clock_ = std::max(clock_, look_.sweep_to);
  }
}

}  // namespace skytrack
