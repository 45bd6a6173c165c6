#include "scan_source.hpp"

#include <deque>

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

}  // namespace

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
