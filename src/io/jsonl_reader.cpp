#include "skytrack/io/jsonl_reader.hpp"

#include <array>
#include <filesystem>
#include <limits>
#include <system_error>

#include "json_parser.hpp"

namespace skytrack::io {
namespace {

// Record-specific parse of one DOM line; plot scans also report their rejected plots.
Expected<PlotScan> parse_record(const simdjson::dom::element& root, PlotScan*,
                                std::vector<std::string>& rejected_plots) {
  auto parsed = parse_plot_scan(root);
  if (!parsed) return unexpected(parsed.error());
  rejected_plots = std::move(parsed->rejected_plots);
  return std::move(parsed->scan);
}

Expected<TruthFrame> parse_record(const simdjson::dom::element& root, TruthFrame*,
                                  std::vector<std::string>&) {
  return parse_truth_frame(root);
}

Expected<TrackFrame> parse_record(const simdjson::dom::element& root, TrackFrame*,
                                  std::vector<std::string>&) {
  return parse_track_frame(root);
}

}  // namespace

std::string to_string(const LineError& error) {
  return error.file + ":" + std::to_string(error.line) + ": " + error.reason;
}

template <class Record>
Expected<JsonLinesReader<Record>> JsonLinesReader<Record>::open(const std::string& path,
                                                                ErrorSink on_error,
                                                                std::size_t max_line) {
  JsonLinesReader reader;
  reader.path_ = path;
  reader.on_error_ = std::move(on_error);
  reader.max_line_ = max_line;
  std::error_code directory;
  if (std::filesystem::is_directory(path, directory)) {
    return make_error(path + ": is a directory, not a JSON Lines file");
  }
  reader.in_ = std::make_unique<std::ifstream>(path, std::ios::binary);
  if (!*reader.in_) return make_error(path + ": cannot open for reading");
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  reader.file_size_ = ec ? 0 : static_cast<std::size_t>(size);
  return reader;
}

template <class Record>
bool JsonLinesReader<Record>::read_line(bool& too_long) {
  // In chunks, so that a line longer than max_line_ is skipped without being held whole.
  too_long = false;
  line_.clear();
  std::array<char, 1 << 16> chunk;
  bool any = false;
  for (;;) {
    in_->getline(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    const auto got = static_cast<std::size_t>(in_->gcount());
    if (in_->bad()) {
      read_error_ = path_ + ": read error after " + std::to_string(bytes_read_) + " bytes";
      return false;
    }
    bytes_read_ += got;
    any = any || got > 0;
    if (in_->eof()) {  // the last line, without a newline (or nothing left)
      line_.append(chunk.data(), got);
      return any;
    }
    if (!in_->fail()) {  // the newline was taken out, not stored
      line_.append(chunk.data(), got - 1);
      return true;
    }
    // The chunk filled before the newline: more of this line follows.
    in_->clear();
    line_.append(chunk.data(), got);
    if (line_.size() > max_line_) {
      too_long = true;
      line_.clear();
      in_->ignore(std::numeric_limits<std::streamsize>::max(), '\n');
      bytes_read_ += static_cast<std::size_t>(in_->gcount());
      if (in_->bad()) {
        read_error_ = path_ + ": read error after " + std::to_string(bytes_read_) + " bytes";
        return false;
      }
      return true;
    }
  }
}

template <class Record>
std::optional<Record> JsonLinesReader<Record>::next() {
  std::vector<std::string> rejected_plots;
  std::size_t line_number = counts_.lines + counts_.blank_lines;
  bool too_long = false;
  while (read_line(too_long)) {
    ++line_number;
    if (too_long) {
      ++counts_.lines;
      ++counts_.rejected_lines;
      if (on_error_) {
        on_error_(
            LineError{path_, line_number,
                      "line longer than " + std::to_string(max_line_) + " bytes: skipped unread"});
      }
      continue;
    }
    if (!line_.empty() && line_.back() == '\r') line_.pop_back();
    if (line_.find_first_not_of(" \t") == std::string::npos) {
      ++counts_.blank_lines;
      continue;
    }
    ++counts_.lines;
    // Reserve simdjson's padding so the line is parsed in place, without a copy.
    line_.reserve(line_.size() + simdjson::SIMDJSON_PADDING);
    auto root = parse_json_line(line_, line_.capacity());
    Expected<Record> record =
        root ? parse_record(*root, static_cast<Record*>(nullptr), rejected_plots)
             : unexpected(root.error());
    if (!record) {
      ++counts_.rejected_lines;
      if (on_error_) on_error_(LineError{path_, line_number, record.error().message});
      continue;
    }
    counts_.rejected_plots += rejected_plots.size();
    if (on_error_) {
      for (auto& reason : rejected_plots) {
        on_error_(LineError{path_, line_number, "plot rejected: " + reason});
      }
    }
    ++counts_.records;
    return std::move(*record);
  }
  return std::nullopt;
}

template class JsonLinesReader<PlotScan>;
template class JsonLinesReader<TruthFrame>;
template class JsonLinesReader<TrackFrame>;

}  // namespace skytrack::io
