#include "skytrack/display/picture.hpp"

#include <utility>

#include "picture_json.hpp"
#include "skytrack/geometry/frames.hpp"
#include "skytrack/io/jsonl_writer.hpp"

namespace skytrack::display {

PlotLayer to_plot_layer(const PlotScan& scan) {
  PlotLayer layer;
  layer.scan = scan.scan;
  layer.time = scan.time;
  layer.platform_x = scan.platform.position.x();
  layer.platform_y = scan.platform.position.y();
  layer.xy.reserve(2 * scan.plots.size());
  for (const Plot& plot : scan.plots) {
    const Eigen::Vector3d p = plot_position_enu(plot, scan.platform);
    layer.xy.push_back(static_cast<float>(p.x()));
    layer.xy.push_back(static_cast<float>(p.y()));
  }
  return layer;
}

Picture::Picture(int plot_scans) : plot_scans_(plot_scans > 0 ? plot_scans : 1) {}

void Picture::touch() {
  ++version_;
  changed_.notify_all();
}

void Picture::add_plots(const PlotScan& scan) {
  // The conversion runs outside the lock: only the pointer swap is shared.
  auto layer = std::make_shared<const PlotLayer>(to_plot_layer(scan));
  std::lock_guard lock(mutex_);
  auto& plots = sensors_[scan.sensor].plots;
  plots.push_front(std::move(layer));
  while (plots.size() > plot_scans_) plots.pop_back();
  touch();
}

void Picture::add_tracks(TrackFrame frame) {
  auto tracks = std::make_shared<const TrackFrame>(std::move(frame));
  std::lock_guard lock(mutex_);
  sensors_[tracks->sensor].tracks = std::move(tracks);
  touch();
}

void Picture::add_status(TrackerStatusReport status) {
  auto report = std::make_shared<const TrackerStatusReport>(std::move(status));
  std::lock_guard lock(mutex_);
  status_[report->instance] = std::move(report);
  touch();
}

void Picture::set_truth(TruthFrame truth) {
  auto frame = std::make_shared<const TruthFrame>(std::move(truth));
  std::lock_guard lock(mutex_);
  truth_ = std::move(frame);
  touch();
}

void Picture::set_mode(std::string mode) {
  std::lock_guard lock(mutex_);
  mode_ = std::move(mode);
  touch();
}

void Picture::set_replay(std::string replay_json) {
  std::lock_guard lock(mutex_);
  replay_json_ = std::move(replay_json);
  touch();
}

void Picture::clear() {
  std::lock_guard lock(mutex_);
  sensors_.clear();
  truth_.reset();
  touch();
}

std::uint64_t Picture::version() const {
  std::lock_guard lock(mutex_);
  return version_;
}

std::uint64_t Picture::wait_for_change(std::uint64_t seen,
                                       std::chrono::milliseconds timeout) const {
  std::unique_lock lock(mutex_);
  changed_.wait_for(lock, timeout, [&] { return stopped_ || version_ != seen; });
  return version_;
}

void Picture::stop() {
  std::lock_guard lock(mutex_);
  stopped_ = true;
  changed_.notify_all();
}

bool Picture::stopped() const {
  std::lock_guard lock(mutex_);
  return stopped_;
}

std::shared_ptr<const FrameDocument> Picture::frame_json() {
  // One builder at a time: the others wait and share its result instead of repeating it.
  std::lock_guard cache(cache_mutex_);
  PictureSnapshot snap;
  {
    std::lock_guard lock(mutex_);
    if (cached_ && cached_->version == version_) return cached_;
    snap.version = version_;
    snap.mode = mode_;
    snap.replay_json = replay_json_;
    snap.truth = truth_;
    for (const auto& [id, sensor] : sensors_) {
      snap.sensors.push_back({id, {sensor.plots.begin(), sensor.plots.end()}, sensor.tracks});
    }
    for (const auto& [name, status] : status_) snap.status.push_back(status);
  }
  cached_ = std::make_shared<const FrameDocument>(FrameDocument{snap.version, to_json(snap)});
  return cached_;
}

std::optional<std::string> Picture::track_json(std::uint32_t sensor, std::int64_t id) const {
  std::shared_ptr<const TrackFrame> frame;
  {
    std::lock_guard lock(mutex_);
    const auto it = sensors_.find(sensor);
    if (it == sensors_.end() || !it->second.tracks) return std::nullopt;
    frame = it->second.tracks;
  }
  TrackFrame one{frame->sensor, frame->scan, frame->time, {}, {}, {}};
  for (const TrackReport& t : frame->tracks) {
    if (t.id == id) one.tracks.push_back(t);
  }
  if (one.tracks.empty()) return std::nullopt;
  for (const Association& a : frame->associations) {
    if (a.track == id) one.associations.push_back(a);
  }
  for (const TrackEvent& e : frame->events) {
    if (e.track == id) one.events.push_back(e);
  }
  return io::to_json(one);
}

}  // namespace skytrack::display
