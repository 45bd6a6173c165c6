#pragma once
// Options that `import-asterix` and `replay --asterix` share: batching, sensor selection, test
// targets, capture filter; and the summary both print of what they read.
#include <cstdio>
#include <string>

#include <CLI/CLI.hpp>

#include "skytrack/asterix/feed.hpp"
#include "skytrack/core/expected.hpp"

namespace skytrack::tool {

struct AsterixOptions {
  std::string batch = "sector";
  std::string sensor;  // SAC/SIC
  bool keep_tests = false;
  std::string port;    // UDP destination port
  std::string source;  // source address[:port]
};

void add_asterix_options(CLI::App& cmd, AsterixOptions& options);

struct ResolvedAsterixOptions {
  asterix::FeedOptions feed;
  asterix::CaptureFilter filter;
};
Expected<ResolvedAsterixOptions> resolve(const AsterixOptions& options);

/// Prints an error line for the first `limit` errors, then counts the rest.
class ErrorPrinter {
 public:
  explicit ErrorPrinter(std::string file, std::size_t limit = 20)
      : file_(std::move(file)), limit_(limit) {}
  void set_file(std::string file) { file_ = std::move(file); }
  void operator()(const asterix::DecodeError& error);
  void operator()(const asterix::CaptureProblem& problem);
  std::size_t shown() const { return shown_; }

 private:
  std::string file_;
  std::size_t limit_;
  std::size_t shown_ = 0;
};

/// What was read: blocks and records per category, plots, service messages, drops and errors
/// by reason, capture counts.
void print_summary(std::FILE* out, const asterix::Feed& feed,
                   const asterix::CaptureCounts& capture);

}  // namespace skytrack::tool
