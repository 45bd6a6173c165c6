#pragma once
// A one-line progress bar on stderr, redrawn when the percentage changes.
#include <cstddef>
#include <cstdio>
#include <string>

#include <fmt/format.h>

namespace skytrack::tool {

class ProgressBar {
 public:
  explicit ProgressBar(bool enabled, std::string unit = "batches")
      : enabled_(enabled), unit_(std::move(unit)) {}
  void update(std::size_t done, std::size_t total, std::size_t count) {
    if (!enabled_ || total == 0) return;
    const int percent = static_cast<int>(100.0 * static_cast<double>(done) / total);
    if (percent == last_) return;
    last_ = percent;
    const int filled = percent * 30 / 100;
    fmt::print(stderr, "\r[{:<30}] {:3d}%  {} {}", std::string(filled, '#'), percent, count, unit_);
  }
  void finish() {
    if (enabled_ && last_ >= 0) fmt::print(stderr, "\n");
    last_ = -1;
  }

 private:
  bool enabled_;
  std::string unit_;
  int last_ = -1;
};

}  // namespace skytrack::tool
