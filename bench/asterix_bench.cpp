// ASTERIX decode speed [bytes of ASTERIX per second, one core]: the decoder alone on datagrams
// held in memory (canalA CAT001/002, bds30 CAT048/034 when ../shared/realdata is present, and a
// synthetic CAT048 stream that is always there), and the whole file path (mapped pcap ->
// decoder -> batcher -> PlotScans). Target: at least 50 MB/s (issue 25).
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>
#include <vector>

#include "skytrack/asterix/feed.hpp"

namespace {

using namespace skytrack::asterix;

const std::string kRealdata = SKYTRACK_REALDATA_DIR;

struct NullSink final : RecordSink {
  std::size_t n = 0;
  void on_report(const TargetReport& r) override { n += r.mode3a.has_value(); }
  void on_service(const ServiceMessage&) override { ++n; }
  void on_error(const DecodeError&) override {}
};

struct Held {
  std::vector<std::vector<std::uint8_t>> payloads;
  std::vector<double> times;
  std::size_t bytes = 0;
};

Held hold(const std::string& path) {
  Held h;
  auto reader = CaptureReader::open(path);
  if (!reader) return h;
  while (auto d = reader->next()) {
    h.payloads.emplace_back(d->payload.begin(), d->payload.end());
    h.times.push_back(d->reception_time.value_or(0.0));
    h.bytes += d->payload.size();
  }
  return h;
}

/// Blocks of 20 CAT048 Mode S reports with the usual items (010 140 020 040 070 090 130 220
/// 240 161 042 200 170): about 1 kB per datagram, as a Mode S radar sends them.
Held synthetic_cat048() {
  Held h;
  for (int b = 0; b < 2000; ++b) {
    std::vector<std::uint8_t> block{48, 0, 0};
    for (int i = 0; i < 20; ++i) {
      const unsigned t = static_cast<unsigned>((1000.0 + b * 0.2) * 128.0);
      const std::uint8_t rec[] = {0xFF,
                                  0xDE,
                                  20,
                                  4,  // FSPEC: FRN 1-7, 8 9 11 12 13 14
                                  static_cast<std::uint8_t>(t >> 16),
                                  static_cast<std::uint8_t>(t >> 8),
                                  static_cast<std::uint8_t>(t),
                                  0xA0,
                                  0x12,
                                  static_cast<std::uint8_t>(i),
                                  0x40,
                                  static_cast<std::uint8_t>(b),
                                  0x0A,
                                  0xB8,
                                  0x01,
                                  0x18,
                                  0x60,
                                  0x50,
                                  0x90,  // 070 090 130
                                  0x34,
                                  0x30,
                                  static_cast<std::uint8_t>(i),  // 220
                                  1,
                                  2,
                                  3,
                                  4,
                                  5,
                                  6,  // 240
                                  0,
                                  static_cast<std::uint8_t>(i),  // 161
                                  0,
                                  1,
                                  0,
                                  2,
                                  0,
                                  3,
                                  0,
                                  4,      // 042 200
                                  0x40};  // 170
      block.insert(block.end(), std::begin(rec), std::end(rec));
    }
    block[1] = static_cast<std::uint8_t>(block.size() >> 8);
    block[2] = static_cast<std::uint8_t>(block.size());
    h.bytes += block.size();
    h.payloads.push_back(std::move(block));
    h.times.push_back(0.0);
  }
  return h;
}

void decode_held(benchmark::State& state, const Held& h) {
  if (h.payloads.empty()) {
    state.SkipWithError("capture not found (../shared/realdata)");
    return;
  }
  for (auto _ : state) {
    Decoder decoder;
    NullSink sink;
    std::uint64_t n = 0;
    for (std::size_t i = 0; i < h.payloads.size(); ++i) {
      decoder.decode(h.payloads[i], Origin{0, ++n}, h.times[i], sink);
    }
    benchmark::DoNotOptimize(sink.n);
    if (decoder.counters().total_errors() != 0) state.SkipWithError("decode errors");
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * h.bytes));
}

void BM_DecodeCanalA(benchmark::State& state) {
  static const Held h = hold(kRealdata + "/asterix/canalA_cat001_cat002.pcap");
  decode_held(state, h);
}
void BM_DecodeBds30(benchmark::State& state) {
  static const Held h = hold(kRealdata + "/asterix/bds30_cat048_cat034.pcap");
  decode_held(state, h);
}
void BM_DecodeSyntheticCat048(benchmark::State& state) {
  static const Held h = synthetic_cat048();
  decode_held(state, h);
}

/// The whole path of `import-asterix` short of writing JSON: map, walk pcap, decode, batch.
void BM_ImportCanalAToPlotScans(benchmark::State& state) {
  const std::string path = kRealdata + "/asterix/canalA_cat001_cat002.pcap";
  if (!std::filesystem::exists(path)) {
    state.SkipWithError("capture not found (../shared/realdata)");
    return;
  }
  std::size_t bytes = 0;
  for (auto _ : state) {
    std::size_t plots = 0;
    Feed feed({}, [&](skytrack::PlotScan&& s) { plots += s.plots.size(); });
    auto reader = CaptureReader::open(path);
    run_capture(*reader, feed);
    bytes = feed.decoder().counters().bytes;
    benchmark::DoNotOptimize(plots);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes));
}

BENCHMARK(BM_DecodeCanalA)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DecodeBds30)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DecodeSyntheticCat048)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ImportCanalAToPlotScans)->Unit(benchmark::kMillisecond);

}  // namespace
