#include "asterix_options.hpp"

#include <fmt/format.h>

namespace skytrack::tool {

void add_asterix_options(CLI::App& cmd, AsterixOptions& o) {
  cmd.add_option("--batch", o.batch,
                 "sector: by the radar's north-marker / sector messages (else by revolution); "
                 "revolution: fitted from the plots' azimuths and times; block:N: every N plots")
      ->default_val("sector");
  cmd.add_option("--sensor", o.sensor, "Only this radar, as SAC/SIC (e.g. 20/130)");
  cmd.add_flag("--keep-tests", o.keep_tests, "Keep test (TST) and simulated (SIM) reports");
  cmd.add_option("--port", o.port, "Captures: only UDP datagrams to this port");
  cmd.add_option("--source", o.source, "Captures: only datagrams from this address[:port]");
}

Expected<ResolvedAsterixOptions> resolve(const AsterixOptions& o) {
  ResolvedAsterixOptions r;
  auto batch = asterix::parse_batch_mode(o.batch);
  if (!batch) return unexpected(batch.error());
  r.feed.batch = *batch;
  r.feed.decoder.keep_tests = o.keep_tests;
  if (!o.sensor.empty()) {
    r.feed.decoder.sensor = asterix::parse_sac_sic(o.sensor);
    if (!r.feed.decoder.sensor) {
      return make_error("--sensor: expected SAC/SIC (two numbers 0..255), got '" + o.sensor + "'");
    }
  }
  auto filter = asterix::parse_capture_filter(o.port, o.source);
  if (!filter) return unexpected(filter.error());
  r.filter = *filter;
  return r;
}

void ErrorPrinter::operator()(const asterix::DecodeError& error) {
  if (shown_++ < limit_) fmt::print(stderr, "\n{}: {}", file_, asterix::to_string(error));
  if (shown_ == limit_ + 1) fmt::print(stderr, "\n{}: (further errors counted, not shown)", file_);
}

void ErrorPrinter::operator()(const asterix::CaptureProblem& problem) {
  if (shown_++ < limit_)
    fmt::print(stderr, "\n{}: byte {}: {}", file_, problem.offset, problem.message);
}

void print_summary(std::FILE* out, const asterix::Feed& feed,
                   const asterix::CaptureCounts& capture) {
  const asterix::DecodeCounters& c = feed.decoder().counters();
  fmt::print(out, "  capture: {} frames, {} datagrams ({} not UDP, {} filtered out, {} damaged",
             capture.frames, capture.datagrams, capture.not_udp, capture.filtered, capture.damaged);
  if (capture.skipped_bytes > 0) fmt::print(out, ", {} bytes skipped", capture.skipped_bytes);
  fmt::print(out, "), {} bytes of ASTERIX\n", c.bytes);
  fmt::print(out, "  blocks: {}", c.blocks);
  std::string records;
  for (std::size_t cat = 0; cat < 256; ++cat) {
    if (c.blocks_by_category[cat] == 0) continue;
    fmt::print(out, "; CAT{:03d} {}", cat, c.blocks_by_category[cat]);
    records += fmt::format("; CAT{:03d} {}", cat, c.records_by_category[cat]);
  }
  fmt::print(out, " ({} of unknown categories skipped)\n", c.unknown_category_blocks);
  fmt::print(out, "  records{}; {} items skipped (not interpreted)\n",
             records.empty() ? std::string(": 0") : records.substr(1), c.items_skipped);
  fmt::print(out,
             "  plots: {}; service messages: {} north markers, {} sector crossings, {} south "
             "markers, {} other\n",
             c.plots, c.services[0], c.services[1], c.services[2], c.services[3]);
  fmt::print(out, "  dropped: {}", c.total_dropped());
  for (std::size_t i = 0; i < c.dropped.size(); ++i) {
    if (c.dropped[i] > 0) {
      fmt::print(out, "; {} {}", asterix::to_string(static_cast<asterix::DropReason>(i)),
                 c.dropped[i]);
    }
  }
  fmt::print(out, "\n  errors: {}", c.total_errors());
  for (std::size_t i = 0; i < c.errors.size(); ++i) {
    if (c.errors[i] > 0) {
      fmt::print(out, "; {} {}", asterix::to_string(static_cast<asterix::ErrorReason>(i)),
                 c.errors[i]);
    }
  }
  fmt::print(out, "\n  batches: {} ({})\n", feed.batcher().batches(),
             asterix::to_string(feed.batcher().options()));
}

}  // namespace skytrack::tool
