#pragma once
// Where `replay` takes its batches from: a JSON Lines plot stream, or an ASTERIX recording
// decoded and batched on the fly (import-asterix without the file in between).
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "asterix_options.hpp"
#include "skytrack/core/expected.hpp"
#include "skytrack/core/plot.hpp"

namespace skytrack::tool {

class ScanSource {
 public:
  virtual ~ScanSource() = default;
  virtual std::optional<PlotScan> next() = 0;
  virtual std::size_t bytes_read() const = 0;
  virtual std::size_t file_size() const = 0;
  /// Lines (JSON Lines) or records and datagrams (ASTERIX) rejected so far.
  virtual std::size_t rejected() const = 0;
  /// Why reading stopped before the end of the input (a read error), if it did.
  virtual std::optional<std::string> read_error() const { return std::nullopt; }
};

/// A plot stream; bad lines are printed (the first 20) and counted.
Expected<std::unique_ptr<ScanSource>> open_plot_stream(const std::string& path);
/// Several plot streams (one per sensor, say) merged in time order, ties in the given order.
Expected<std::unique_ptr<ScanSource>> open_plot_streams(const std::vector<std::string>& paths);
/// An ASTERIX recording; errors are printed with their offsets (the first 20) and counted.
Expected<std::unique_ptr<ScanSource>> open_asterix_recording(const std::string& path,
                                                             const AsterixOptions& options);

}  // namespace skytrack::tool
