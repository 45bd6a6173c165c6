#include "display_replay.hpp"

#include <chrono>

#include <fmt/format.h>

#include "skytrack/io/jsonl_reader.hpp"

namespace skytrack::tool {
namespace {

template <class Record>
Expected<std::vector<Record>> read_all(const std::string& path) {
  std::size_t shown = 0;
  auto reader = io::JsonLinesReader<Record>::open(path, [&](const io::LineError& e) {
    if (shown++ < 20) fmt::print(stderr, "{}\n", io::to_string(e));
  });
  if (!reader) return unexpected(reader.error());
  std::vector<Record> out;
  while (auto record = reader->next()) out.push_back(std::move(*record));
  if (reader->read_error()) return make_error(path + ": " + *reader->read_error());
  return out;
}

}  // namespace

Expected<ReplayFiles> load_replay_files(const std::string& plots, const std::string& tracks,
                                        const std::string& truth) {
  ReplayFiles files;
  auto p = read_all<PlotScan>(plots);
  if (!p) return unexpected(p.error());
  files.plots = std::move(*p);
  auto k = read_all<TrackFrame>(tracks);
  if (!k) return unexpected(k.error());
  files.tracks = std::move(*k);
  if (!truth.empty()) {
    auto t = read_all<TruthFrame>(truth);
    if (!t) return unexpected(t.error());
    files.truth = std::move(*t);
  }
  if (files.tracks.empty()) return make_error(tracks + ": no track frames");
  return files;
}

DisplayReplay::DisplayReplay(display::Picture& picture, ReplayFiles files, double rate)
    : picture_(picture), files_(std::move(files)), rate_(rate > 0.0 ? rate : 1.0) {
  picture_.set_mode("replay");
  std::lock_guard lock(mutex_);
  advance();  // the first frame at once, so the page has something to show
}

double DisplayReplay::frame_time(std::size_t i) const {
  return files_.tracks[i].time;
}

void DisplayReplay::advance() {
  if (next_frame_ >= files_.tracks.size()) return;
  const TrackFrame& frame = files_.tracks[next_frame_++];
  // The plots and truth up to this frame's time (files are in time order per sensor).
  while (next_plots_ < files_.plots.size() && files_.plots[next_plots_].time <= frame.time) {
    picture_.add_plots(files_.plots[next_plots_++]);
  }
  while (next_truth_ < files_.truth.size() && files_.truth[next_truth_].time <= frame.time) {
    ++next_truth_;
  }
  if (next_truth_ > 0) picture_.set_truth(files_.truth[next_truth_ - 1]);
  picture_.add_tracks(frame);
  if (next_frame_ >= files_.tracks.size()) playing_ = false;
  publish_state();
}

void DisplayReplay::publish_state() {
  picture_.set_replay(fmt::format(
      "{{\"playing\":{},\"rate\":{},\"frame\":{},\"frames\":{},\"time\":{}}}", playing_, rate_,
      next_frame_, files_.tracks.size(), next_frame_ > 0 ? frame_time(next_frame_ - 1) : 0.0));
}

void DisplayReplay::tick() {
  std::unique_lock lock(mutex_);
  if (!playing_ || next_frame_ >= files_.tracks.size()) {
    wake_.wait_for(lock, std::chrono::milliseconds(100));
    return;
  }
  // Waits the data's own time between frames, scaled by the rate; a control wakes it early.
  const double gap = next_frame_ > 0 ? frame_time(next_frame_) - frame_time(next_frame_ - 1) : 0;
  const auto wait = std::chrono::duration<double>(std::max(0.0, gap) / rate_);
  const std::size_t before = next_frame_;
  if (wake_.wait_for(lock, wait, [&] { return !playing_ || next_frame_ != before; })) return;
  advance();
}

Expected<std::string> DisplayReplay::control(const std::string& cmd, double rate) {
  std::lock_guard lock(mutex_);
  if (rate > 0.0) rate_ = rate;
  if (cmd == "play") {
    if (next_frame_ >= files_.tracks.size()) return make_error("at the end: restart first");
    playing_ = true;
  } else if (cmd == "pause") {
    playing_ = false;
  } else if (cmd == "step") {
    playing_ = false;
    advance();
  } else if (cmd == "restart") {
    picture_.clear();
    next_frame_ = next_plots_ = next_truth_ = 0;
    playing_ = true;
    advance();
  } else if (!cmd.empty()) {
    return make_error("unknown command '" + cmd + "' (play, pause, step, restart)");
  }
  publish_state();
  wake_.notify_all();
  return fmt::format("{{\"playing\":{},\"rate\":{},\"frame\":{},\"frames\":{}}}", playing_, rate_,
                     next_frame_, files_.tracks.size());
}

}  // namespace skytrack::tool
