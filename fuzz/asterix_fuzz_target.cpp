// The ASTERIX fuzz target: any bytes, taken both as one UDP datagram and as a capture file
// (raw blocks, pcap or pcapng), through the decoder and the sector batcher. Besides not
// crashing (ASan, UBSan), what comes out must make sense: finite times, azimuths in [0, 2 pi),
// ranges not negative, batch times that never go backwards, no more plots than records.
// libFuzzer calls it from asterix_fuzz_main.cpp; the regular test suite runs it over the
// committed corpus (tests/asterix/fuzz_corpus_test.cpp).
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <map>

#include "skytrack/asterix/feed.hpp"

namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;

void check(bool ok) {
  if (!ok) std::abort();
}

void check_scan(const skytrack::PlotScan& scan, std::map<std::uint32_t, double>& last_time) {
  check(std::isfinite(scan.time));
  const auto [it, fresh] = last_time.emplace(scan.sensor, scan.time);
  check(fresh || scan.time >= it->second);
  it->second = scan.time;
  for (const skytrack::Plot& p : scan.plots) {
    check(p.time && std::isfinite(*p.time));
    check(p.range >= 0.0 && std::isfinite(p.range));
    check(p.azimuth >= 0.0 && p.azimuth < kTwoPi);
    check(!p.mode3a || *p.mode3a <= 07777);
    check(!p.mode_s || *p.mode_s <= 0xFFFFFF);
  }
}

void run(skytrack::asterix::CaptureReader* reader, std::span<const std::uint8_t> datagram) {
  using namespace skytrack::asterix;
  std::map<std::uint32_t, double> last_time;
  std::size_t plots = 0;
  FeedOptions options;
  options.decoder.keep_tests = true;
  Feed feed(options, [&](skytrack::PlotScan&& s) {
    plots += s.plots.size();
    check_scan(s, last_time);
  });
  if (reader != nullptr) {
    run_capture(*reader, feed);
  } else {
    feed.feed(Datagram{datagram, Origin{0, 1}, 66431.5});
    feed.finish();
  }
  const DecodeCounters& c = feed.decoder().counters();
  std::uint64_t records = 0;
  for (const auto r : c.records_by_category) records += r;
  check(plots == c.plots && c.plots <= records);
}

}  // namespace

int skytrack_asterix_fuzz_one(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> bytes(data, size);
  run(nullptr, bytes);
  auto reader = skytrack::asterix::CaptureReader::from_memory(bytes);
  run(&reader, {});
  return 0;
}
