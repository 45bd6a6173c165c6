#pragma once
// Writers for the JSON Lines formats of CONTRACTS.md. Doubles are written in the shortest
// form that reads back bit-identical, so a file round trip loses nothing.
#include <cstdio>
#include <string>
#include <utility>

#include "skytrack/core/expected.hpp"
#include "skytrack/core/plot.hpp"
#include "skytrack/core/track_report.hpp"
#include "skytrack/core/truth.hpp"

namespace skytrack::io {

// One JSON object (no trailing newline) per record.
std::string to_json(const PlotScan& scan);
std::string to_json(const TruthFrame& frame);
std::string to_json(const TrackFrame& frame);

/// Appends one line per record to a file; flushes on close.
class JsonLinesWriter {
 public:
  static Expected<JsonLinesWriter> open(const std::string& path);
  JsonLinesWriter(JsonLinesWriter&& other) noexcept;
  JsonLinesWriter& operator=(JsonLinesWriter&& other) noexcept;
  JsonLinesWriter(const JsonLinesWriter&) = delete;
  JsonLinesWriter& operator=(const JsonLinesWriter&) = delete;
  ~JsonLinesWriter();

  template <class Record>
  bool write(const Record& record) {
    return write_line(to_json(record));
  }
  bool write_line(const std::string& json);
  /// Flushes and closes; false if any write failed.
  bool close();

 private:
  JsonLinesWriter(std::FILE* file, std::string path) : file_(file), path_(std::move(path)) {}
  std::FILE* file_ = nullptr;
  std::string path_;
  bool ok_ = true;
};

}  // namespace skytrack::io
