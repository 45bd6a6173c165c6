#pragma once
// One reusable simdjson DOM parser per thread, and the record parsers working on its output.
// The element returned stays valid until the next parse on the same thread.
#include <string_view>

#include <simdjson.h>

#include "skytrack/core/expected.hpp"
#include "skytrack/io/jsonl_reader.hpp"

namespace skytrack::io {

/// Parses one line. `capacity` > size + SIMDJSON_PADDING lets simdjson read in place.
Expected<simdjson::dom::element> parse_json_line(std::string_view line, std::size_t capacity = 0);

Expected<ParsedPlotScan> parse_plot_scan(const simdjson::dom::element& root);
Expected<TruthFrame> parse_truth_frame(const simdjson::dom::element& root);
Expected<TrackFrame> parse_track_frame(const simdjson::dom::element& root);

}  // namespace skytrack::io
