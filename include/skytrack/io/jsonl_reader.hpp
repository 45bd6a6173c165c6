#pragma once
// Streaming readers for the JSON Lines formats of CONTRACTS.md. A file is read one line at
// a time (a 1 GB plot file is never held whole); a line that fails to parse or validate is
// reported through the error callback with file and line number, counted, and skipped.
#include <cstddef>
#include <fstream>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "skytrack/core/expected.hpp"
#include "skytrack/core/plot.hpp"
#include "skytrack/core/track_report.hpp"
#include "skytrack/core/truth.hpp"

namespace skytrack::io {

/// Where and why a line (or one plot of a line) was rejected.
struct LineError {
  std::string file;
  std::size_t line = 0;
  std::string reason;
};
std::string to_string(const LineError& error);  // "file:line: reason"

/// A scan parsed from one line, with the plots that were rejected and kept out of it.
struct ParsedPlotScan {
  PlotScan scan;
  std::vector<std::string> rejected_plots;  // one reason per rejected plot
};

// Parsers for a single line (also used by tests and by tools reading other sources).
Expected<ParsedPlotScan> parse_plot_scan(std::string_view line);
Expected<TruthFrame> parse_truth_frame(std::string_view line);
Expected<TrackFrame> parse_track_frame(std::string_view line);

/// Counters of one reader.
struct ReadCounts {
  std::size_t lines = 0;           // non-blank lines seen
  std::size_t blank_lines = 0;     // skipped silently
  std::size_t records = 0;         // lines accepted
  std::size_t rejected_lines = 0;  // lines skipped
  std::size_t rejected_plots = 0;  // plots dropped from accepted plot-stream lines
};

using ErrorSink = std::function<void(const LineError&)>;

/// The longest line a reader takes [bytes]: 16 MiB, a batch of about 250 000 plots (the
/// daemon's own limit is 100 000). A longer line is rejected with its number, unread.
inline constexpr std::size_t kMaxLineBytes = std::size_t{16} << 20;

/// Reads records of type Record from a JSON Lines file, line by line.
template <class Record>
class JsonLinesReader {
 public:
  /// Opens `path`; fails with a message naming the file if it cannot be read (a directory
  /// cannot).
  static Expected<JsonLinesReader> open(const std::string& path, ErrorSink on_error = {},
                                        std::size_t max_line = kMaxLineBytes);

  /// The next valid record, or nullopt at the end of the file or at a read error
  /// (read_error() tells). Bad lines go to the error sink.
  std::optional<Record> next();
  /// Why reading stopped before the end of the file, if it did.
  const std::optional<std::string>& read_error() const { return read_error_; }

  const ReadCounts& counts() const { return counts_; }
  const std::string& path() const { return path_; }
  /// Bytes consumed so far and the file size, for progress bars.
  std::size_t bytes_read() const { return bytes_read_; }
  std::size_t file_size() const { return file_size_; }

 private:
  JsonLinesReader() = default;
  std::string path_;
  std::unique_ptr<std::ifstream> in_;
  std::string line_;
  ErrorSink on_error_;
  ReadCounts counts_;
  std::size_t bytes_read_ = 0;
  std::size_t file_size_ = 0;
  std::size_t max_line_ = kMaxLineBytes;
  std::optional<std::string> read_error_;
  /// Reads one line into line_ (at most max_line_ bytes); false at the end or on an error.
  /// `too_long`: the line was longer and was skipped.
  bool read_line(bool& too_long);
};

using PlotStreamReader = JsonLinesReader<PlotScan>;
using TruthReader = JsonLinesReader<TruthFrame>;
using TrackReader = JsonLinesReader<TrackFrame>;

}  // namespace skytrack::io
