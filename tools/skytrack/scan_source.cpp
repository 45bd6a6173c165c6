#include "scan_source.hpp"

#include <deque>
#include <vector>

#include <fmt/format.h>

#include "skytrack/io/jsonl_reader.hpp"

namespace skytrack::tool {
namespace {

class PlotStreamSource final : public ScanSource {
 public:
  explicit PlotStreamSource(io::PlotStreamReader reader) : reader_(std::move(reader)) {}
  std::optional<PlotScan> next() override { return reader_.next(); }
  std::size_t bytes_read() const override { return reader_.bytes_read(); }
  std::size_t file_size() const override { return reader_.file_size(); }
  std::size_t rejected() const override { return reader_.counts().rejected_lines; }
  std::optional<std::string> read_error() const override { return reader_.read_error(); }

 private:
  io::PlotStreamReader reader_;
};

class AsterixSource final : public ScanSource {
 public:
  AsterixSource(const std::string& path, const ResolvedAsterixOptions& options)
      : errors_(path),
        feed_(
            options.feed, [this](PlotScan&& s) { ready_.push_back(std::move(s)); },
            [this](const asterix::DecodeError& e) { errors_(e); }) {}

  Expected<void> open(const std::string& path, const asterix::CaptureFilter& filter) {
    auto reader = asterix::CaptureReader::open(
        path, filter, [this](const asterix::CaptureProblem& p) { errors_(p); });
    if (!reader) return unexpected(reader.error());
    reader_.emplace(std::move(*reader));
    return {};
  }

  std::optional<PlotScan> next() override {
    while (ready_.empty() && !finished_) {
      if (auto d = reader_->next()) {
        feed_.feed(*d);
      } else {
        feed_.finish();
        finished_ = true;
      }
    }
    if (ready_.empty()) return std::nullopt;
    PlotScan scan = std::move(ready_.front());
    ready_.pop_front();
    return scan;
  }
  std::size_t bytes_read() const override { return reader_->bytes_read(); }
  std::size_t file_size() const override { return reader_->file_size(); }
  std::size_t rejected() const override {
    return feed_.decoder().counters().total_errors() + reader_->counts().damaged;
  }

 private:
  ErrorPrinter errors_;
  asterix::Feed feed_;
  std::optional<asterix::CaptureReader> reader_;
  std::deque<PlotScan> ready_;
  bool finished_ = false;
};

/// Several plot streams (each a sensor's recording) as one, in time order; at equal times the
/// earlier stream first, so a merge is deterministic.
class MergedSource final : public ScanSource {
 public:
  explicit MergedSource(std::vector<std::unique_ptr<ScanSource>> sources)
      : sources_(std::move(sources)), heads_(sources_.size()) {
    for (std::size_t i = 0; i < sources_.size(); ++i) heads_[i] = sources_[i]->next();
  }
  std::optional<PlotScan> next() override {
    std::size_t first = sources_.size();
    for (std::size_t i = 0; i < heads_.size(); ++i) {
      if (heads_[i] && (first == sources_.size() || heads_[i]->time < heads_[first]->time)) {
        first = i;
      }
    }
    if (first == sources_.size()) return std::nullopt;
    std::optional<PlotScan> out = std::move(heads_[first]);
    heads_[first] = sources_[first]->next();
    return out;
  }
  std::size_t bytes_read() const override { return sum(&ScanSource::bytes_read); }
  std::size_t file_size() const override { return sum(&ScanSource::file_size); }
  std::size_t rejected() const override { return sum(&ScanSource::rejected); }
  std::optional<std::string> read_error() const override {
    for (const auto& source : sources_) {
      if (auto error = source->read_error()) return error;
    }
    return std::nullopt;
  }

 private:
  std::size_t sum(std::size_t (ScanSource::*count)() const) const {
    std::size_t total = 0;
    for (const auto& source : sources_) total += (*source.*count)();
    return total;
  }
  std::vector<std::unique_ptr<ScanSource>> sources_;
  std::vector<std::optional<PlotScan>> heads_;
};

}  // namespace

Expected<std::unique_ptr<ScanSource>> open_plot_streams(const std::vector<std::string>& paths) {
  if (paths.size() == 1) return open_plot_stream(paths.front());
  std::vector<std::unique_ptr<ScanSource>> sources;
  for (const std::string& path : paths) {
    auto source = open_plot_stream(path);
    if (!source) return unexpected(source.error());
    sources.push_back(std::move(*source));
  }
  return std::unique_ptr<ScanSource>(new MergedSource(std::move(sources)));
}

Expected<std::unique_ptr<ScanSource>> open_plot_stream(const std::string& path) {
  auto shown = std::make_shared<std::size_t>(0);
  auto reader = io::PlotStreamReader::open(path, [shown](const io::LineError& e) {
    if ((*shown)++ < 20) fmt::print(stderr, "{}\n", io::to_string(e));
  });
  if (!reader) return unexpected(reader.error());
  return std::unique_ptr<ScanSource>(new PlotStreamSource(std::move(*reader)));
}

Expected<std::unique_ptr<ScanSource>> open_asterix_recording(const std::string& path,
                                                             const AsterixOptions& options) {
  auto resolved = resolve(options);
  if (!resolved) return unexpected(resolved.error());
  auto source = std::make_unique<AsterixSource>(path, *resolved);
  if (auto ok = source->open(path, resolved->filter); !ok) return unexpected(ok.error());
  return std::unique_ptr<ScanSource>(std::move(source));
}

}  // namespace skytrack::tool
