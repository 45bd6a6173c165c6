// `skytrack eval`'s outputs: the summary (JSON or a table) and the per-scan records.
#pragma once

#include <cstdio>
#include <string>

#include "skytrack/metrics/scenario_evaluation.hpp"
#include "track_frame_matcher.hpp"

namespace skytrack::tool {

/// Writes the per-scan records: JSON Lines for a .jsonl file, CSV otherwise.
class PerScanWriter {
 public:
  PerScanWriter() = default;
  PerScanWriter(const PerScanWriter&) = delete;
  PerScanWriter& operator=(const PerScanWriter&) = delete;
  ~PerScanWriter() { close(); }

  /// Opens `path` (nothing to write when empty); false if it cannot be opened.
  bool open(const std::string& path);
  void write(const metrics::ScanRecord& r);
  /// Closes the file; false if any write failed.
  bool close();

 private:
  std::FILE* file_ = nullptr;
  bool jsonl_ = false;
};

/// The summary as one JSON object (`eval --json`).
std::string summary_json(const metrics::EvaluationSummary& s, double cutoff, double order,
                         const RunCounts& c);
/// The summary as a table on stdout, with the per-truth continuity for up to 50 truths.
void print_table(const metrics::EvaluationSummary& s, double cutoff, double order,
                 const RunCounts& c);

}  // namespace skytrack::tool
