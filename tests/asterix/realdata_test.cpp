// The real captures of ../shared/realdata/asterix (third-party recordings, not committed):
// record and plot counts, field-by-field agreement with Wireshark's ASTERIX dissector when
// `tshark` is installed (else a few committed values taken from it), and canalA's import
// against the independent decoder's plot stream (../shared/realdata/contract).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <tuple>

#include "asterix_test_support.hpp"
#include "skytrack/asterix/feed.hpp"
#include "skytrack/io/jsonl_reader.hpp"

namespace skytrack::asterix::test {
namespace {

constexpr double kNm = 1852.0;
constexpr double kDeg = 3.14159265358979323846 / 180.0;
const std::string kRealdata = SKYTRACK_REALDATA_DIR;

std::string capture(const std::string& name) {
  return kRealdata + "/asterix/" + name;
}

#define SKIP_WITHOUT(path)                \
  if (!std::filesystem::exists(path))     \
  GTEST_SKIP() << (path)                  \
               << " is absent: the real " \
                  "recordings are not in this checkout"

struct Decoded {
  Collected out;
  DecodeCounters counters;
  std::vector<std::uint64_t> report_frames, service_frames;
};

Decoded decode_file(const std::string& path) {
  Decoded d;
  auto reader = CaptureReader::open(path);
  EXPECT_TRUE(reader) << reader.error().message;
  if (!reader) return d;
  Decoder decoder;
  while (auto datagram = reader->next()) {
    decoder.decode(datagram->payload, datagram->where, datagram->reception_time, d.out);
    d.report_frames.resize(d.out.reports.size(), datagram->where.datagram);
    d.service_frames.resize(d.out.services.size(), datagram->where.datagram);
  }
  d.counters = decoder.counters();
  return d;
}

TEST(RealCaptures, CanalACounts) {
  SKIP_WITHOUT(capture("canalA_cat001_cat002.pcap"));
  const Decoded d = decode_file(capture("canalA_cat001_cat002.pcap"));
  EXPECT_EQ(d.counters.blocks, 28645u);
  EXPECT_EQ(d.counters.records_by_category[1], 30651u);
  EXPECT_EQ(d.counters.records_by_category[2], 716u);
  EXPECT_EQ(d.out.reports.size(), 30651u);
  EXPECT_EQ(d.counters.services[static_cast<int>(ServiceKind::kNorthMarker)], 716u);
  EXPECT_EQ(d.counters.total_errors(), 0u);
  EXPECT_EQ(d.counters.total_dropped(), 0u);
}

TEST(RealCaptures, Bds30Counts) {
  SKIP_WITHOUT(capture("bds30_cat048_cat034.pcap"));
  const Decoded d = decode_file(capture("bds30_cat048_cat034.pcap"));
  EXPECT_EQ(d.counters.records_by_category[48], 1830u);
  EXPECT_EQ(d.counters.records_by_category[34], 951u);
  EXPECT_EQ(d.out.reports.size(), 1830u);
  EXPECT_EQ(d.out.services.size(), 951u);
  EXPECT_EQ(d.counters.total_errors(), 0u);
}

TEST(RealCaptures, CroatiaCounts) {
  SKIP_WITHOUT(capture("croatia_cat034_cat048.pcap"));
  const Decoded d = decode_file(capture("croatia_cat034_cat048.pcap"));
  EXPECT_EQ(d.counters.blocks_by_category[48], 86u);
  EXPECT_EQ(d.counters.blocks_by_category[34], 34u);
  EXPECT_EQ(d.counters.records_by_category[48], 128u);
  EXPECT_EQ(d.out.reports.size(), 126u);
  EXPECT_EQ(d.counters.dropped[static_cast<int>(DropReason::kNoDetection)], 2u);
  EXPECT_EQ(d.counters.total_errors(), 0u);
}

/// One ASTERIX record as Wireshark's dissector shows it (PDML "show" values by field name).
struct TsharkRecord {
  std::uint64_t frame = 0;
  int category = 0;
  std::map<std::string, std::string> fields;
  bool has(const std::string& f) const { return fields.count(f) != 0; }
  double number(const std::string& f) const { return std::strtod(fields.at(f).c_str(), nullptr); }
};

bool have_tshark() {
  return std::system("command -v tshark >/dev/null 2>&1") == 0;
}

/// Runs tshark on `path` (UDP port 8600 as ASTERIX) and returns its records, in order.
std::vector<TsharkRecord> tshark_records(const std::string& path) {
  std::vector<TsharkRecord> out;
  const std::string command =
      "tshark -r '" + path + "' -d udp.port==8600,asterix -T pdml -J asterix 2>/dev/null";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) return out;
  std::uint64_t frame = 0;
  int category = 0;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe.get()) != nullptr) {
    const std::string line(buffer);
    if (line.find("<packet>") != std::string::npos) ++frame;
    const auto name_at = line.find("name=\"asterix.");
    if (name_at == std::string::npos) continue;
    const auto name_end = line.find('"', name_at + 6);
    const std::string name = line.substr(name_at + 6, name_end - name_at - 6);
    const auto show_at = line.find("show=\"");
    const std::string show =
        show_at == std::string::npos
            ? ""
            : line.substr(show_at + 6, line.find('"', show_at + 6) - show_at - 6);
    if (name == "asterix.category") category = std::atoi(show.c_str());
    if (name == "asterix.message") out.push_back({frame, category, {}});
    if (!out.empty() && name.size() > 12 && name[8] == '0') out.back().fields[name] = show;
  }
  return out;
}

/// Every target report and service message against tshark's record: time, range, azimuth,
/// Mode 3/A, flight level, Mode S address; returns the number of plots compared.
std::size_t compare_with_tshark(const std::string& path) {
  const Decoded d = decode_file(path);
  const std::vector<TsharkRecord> records = tshark_records(path);
  std::size_t plot = 0, service = 0;
  for (const TsharkRecord& t : records) {
    const std::string c = t.category == 1 ? "asterix.001_" : "asterix.048_";
    if (t.category == 2 || t.category == 34) {
      EXPECT_LT(service, d.out.services.size());
      if (service >= d.out.services.size()) return plot;
      const ServiceMessage& m = d.out.services[service];
      EXPECT_EQ(d.service_frames[service++], t.frame);
      const std::string time = t.category == 2 ? "asterix.002_030_VALUE" : "asterix.034_030_VALUE";
      EXPECT_NEAR(std::fmod(*m.time, 86400.0), t.number(time), 1e-9) << "frame " << t.frame;
      continue;
    }
    EXPECT_LT(plot, d.out.reports.size());
    if (plot >= d.out.reports.size()) return plot;
    const TargetReport& r = d.out.reports[plot];
    EXPECT_EQ(d.report_frames[plot++], t.frame);
    EXPECT_NEAR(r.range / kNm, t.number(c + "040_RHO"), 1e-9) << "frame " << t.frame;
    EXPECT_NEAR(r.azimuth / kDeg, t.number(c + "040_THETA"), 1e-9) << "frame " << t.frame;
    if (t.category == 1) {
      EXPECT_NEAR(std::fmod(r.time, 512.0), t.number("asterix.001_141_VALUE"), 1e-9);
    } else {
      EXPECT_NEAR(std::fmod(r.time, 86400.0), t.number("asterix.048_140_VALUE"), 1e-9);
    }
    const bool code_valid = t.has(c + "070_V") && t.fields.at(c + "070_V") == "0";
    EXPECT_EQ(r.mode3a.has_value(), code_valid) << "frame " << t.frame;
    if (code_valid && r.mode3a) {
      EXPECT_EQ(*r.mode3a, t.number(c + "070_MODE3A"));
    }
    const std::string fl = t.category == 1 ? "asterix.001_090_HGT" : "asterix.048_090_FL";
    const bool fl_valid = t.has(c + "090_V") && t.fields.at(c + "090_V") == "0";
    EXPECT_EQ(r.flight_level.has_value(), fl_valid) << "frame " << t.frame;
    if (fl_valid && r.flight_level) {
      EXPECT_EQ(*r.flight_level, t.number(fl));
    }
    EXPECT_EQ(r.mode_s.has_value(), t.has("asterix.048_220_VALUE")) << "frame " << t.frame;
    if (r.mode_s && t.has("asterix.048_220_VALUE")) {
      EXPECT_EQ(*r.mode_s, std::strtoul(t.fields.at("asterix.048_220_VALUE").c_str(), nullptr, 0));
    }
  }
  EXPECT_EQ(plot, d.out.reports.size());
  EXPECT_EQ(service, d.out.services.size());
  return plot;
}

TEST(RealCaptures, CanalAEqualsTsharkFieldByField) {
  SKIP_WITHOUT(capture("canalA_cat001_cat002.pcap"));
  if (!have_tshark()) GTEST_SKIP() << "tshark not installed (Debian package tshark)";
  EXPECT_EQ(compare_with_tshark(capture("canalA_cat001_cat002.pcap")), 30651u);
}

TEST(RealCaptures, Bds30EqualsTsharkFieldByField) {
  SKIP_WITHOUT(capture("bds30_cat048_cat034.pcap"));
  if (!have_tshark()) GTEST_SKIP() << "tshark not installed (Debian package tshark)";
  EXPECT_EQ(compare_with_tshark(capture("bds30_cat048_cat034.pcap")), 1830u);
}

// Values printed by tshark 4.0.17 (`tshark -r FILE -d udp.port==8600,asterix -V`), for when it
// is not installed.
TEST(RealCaptures, FirstRecordsEqualCommittedTsharkValues) {
  SKIP_WITHOUT(capture("canalA_cat001_cat002.pcap"));
  const Decoded a = decode_file(capture("canalA_cat001_cat002.pcap"));
  ASSERT_GE(a.out.reports.size(), 6u);
  struct Expect {
    double rho, theta;
    int code;
    double fl, t141;
  };
  const Expect canal[] = {{5.28125, 175.84716796875, 1208, 221, 383.578125},
                          {147.25, 208.1689453125, 2813, 380, 383.9375},
                          {109.703125, 208.6962890625, 2035, 380, 383.9453125},
                          {32.265625, 231.333618164062, 1988, 361, 384.1953125},
                          {145.25, 286.528930664062, 3338, 360, 384.8125},
                          {147.6015625, 286.265258789062, 2052, 370, 384.8125}};
  for (std::size_t i = 0; i < 6; ++i) {
    const TargetReport& r = a.out.reports[i];
    EXPECT_NEAR(r.range / kNm, canal[i].rho, 1e-9);
    EXPECT_NEAR(r.azimuth / kDeg, canal[i].theta, 1e-9);
    EXPECT_EQ(r.mode3a, canal[i].code);
    EXPECT_EQ(r.flight_level, canal[i].fl);
    EXPECT_NEAR(std::fmod(r.time, 512.0), canal[i].t141, 1e-9);
  }
  EXPECT_DOUBLE_EQ(a.out.reports[0].time, 66431.578125);
  SKIP_WITHOUT(capture("bds30_cat048_cat034.pcap"));
  const Decoded b = decode_file(capture("bds30_cat048_cat034.pcap"));
  ASSERT_GE(b.out.reports.size(), 2u);
  EXPECT_NEAR(b.out.reports[0].range / kNm, 80.5625, 1e-9);
  EXPECT_NEAR(b.out.reports[0].azimuth / kDeg, 233.959350585938, 1e-9);
  EXPECT_EQ(b.out.reports[0].mode3a, 2600);
  EXPECT_EQ(b.out.reports[0].flight_level, 71.0);
  EXPECT_DOUBLE_EQ(b.out.reports[0].time, 30015.609375);
  EXPECT_EQ(b.out.reports[0].mode_s, 0x343085u);
  EXPECT_NEAR(b.out.reports[1].range / kNm, 80.79296875, 1e-9);
  EXPECT_DOUBLE_EQ(b.out.reports[1].time, 30020.6015625);
  ASSERT_GE(b.out.services.size(), 1u);
  EXPECT_DOUBLE_EQ(*b.out.services[0].time, 30017.359375);
}

TEST(RealCaptures, CanalAImportEqualsTheIndependentDecodersPlotStream) {
  const std::string contract = kRealdata + "/contract/canalA.plots.jsonl";
  SKIP_WITHOUT(capture("canalA_cat001_cat002.pcap"));
  SKIP_WITHOUT(contract);
  std::vector<PlotScan> ours;
  Feed feed({}, [&](PlotScan&& s) { ours.push_back(std::move(s)); });
  auto reader = CaptureReader::open(capture("canalA_cat001_cat002.pcap"));
  ASSERT_TRUE(reader);
  run_capture(*reader, feed);
  auto theirs = io::PlotStreamReader::open(contract);
  ASSERT_TRUE(theirs);
  // The contract counts time from 18:27:11 (66 431 s) and rounds to its printed digits.
  constexpr double kOffset = 66431.0;
  std::size_t batches = 0, plots = 0;
  while (auto scan = theirs->next()) {
    ASSERT_LT(batches, ours.size());
    PlotScan& mine = ours[batches++];
    ASSERT_EQ(mine.plots.size(), scan->plots.size()) << "batch " << batches - 1;
    const auto order = [](const Plot& a, const Plot& b) {
      // In steps of I001/141 (1/128 s) and I001/040, which the printed digits still resolve.
      const auto key = [](const Plot& p) {
        return std::make_tuple(std::round(*p.time * 128.0),
                               std::round(p.azimuth * 65536.0 / (2 * 3.14159265358979)),
                               std::round(p.range * 128.0 / kNm));
      };
      return key(a) < key(b);
    };
    for (Plot& p : mine.plots) *p.time -= kOffset;
    std::sort(mine.plots.begin(), mine.plots.end(), order);
    std::sort(scan->plots.begin(), scan->plots.end(), order);
    for (std::size_t i = 0; i < mine.plots.size(); ++i, ++plots) {
      const Plot& a = mine.plots[i];
      const Plot& b = scan->plots[i];
      EXPECT_NEAR(*a.time, *b.time, 5.1e-5);
      EXPECT_NEAR(a.range, b.range, 0.0051);
      EXPECT_NEAR(a.azimuth, b.azimuth, 2e-7);
      EXPECT_EQ(a.mode3a, b.mode3a);
      EXPECT_EQ(a.flight_level, b.flight_level);
    }
  }
  EXPECT_EQ(batches, ours.size());
  EXPECT_EQ(plots, 30651u);
}

}  // namespace
}  // namespace skytrack::asterix::test

namespace skytrack::asterix::test {
namespace {

std::vector<PlotScan> import(const std::string& path, BatchMode mode) {
  std::vector<PlotScan> out;
  FeedOptions options;
  options.batch.mode = mode;
  Feed feed(options, [&](PlotScan&& s) { out.push_back(std::move(s)); });
  auto reader = CaptureReader::open(path);
  if (reader) run_capture(*reader, feed);
  return out;
}

TEST(RealCaptures, RevolutionsFittedFromThePlotsAreTheNorthMarkersRevolutions) {
  for (const char* name : {"canalA_cat001_cat002.pcap", "bds30_cat048_cat034.pcap"}) {
    SKIP_WITHOUT(capture(name));
    // GIVEN the capture batched by its north markers, and by revolutions fitted from the plots
    const auto markers = import(capture(name), BatchMode::kSector);
    const auto fitted = import(capture(name), BatchMode::kRevolution);
    // THEN the batches hold the same plots and end within 20 ms of the north marker
    ASSERT_EQ(fitted.size(), markers.size()) << name;
    for (std::size_t i = 0; i < fitted.size(); ++i) {
      ASSERT_EQ(fitted[i].plots.size(), markers[i].plots.size()) << name << " batch " << i;
      if (i > 0 && i + 1 < fitted.size()) {
        EXPECT_NEAR(fitted[i].time, markers[i].time, 0.02) << name << " batch " << i;
      }
    }
  }
}

}  // namespace
}  // namespace skytrack::asterix::test
