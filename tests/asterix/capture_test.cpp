// Capture containers: raw blocks (with resynchronisation after damage), pcap and pcapng on each
// link type, and the UDP port / source filter.
#include <gtest/gtest.h>

#include "asterix_test_support.hpp"
#include "skytrack/asterix/capture.hpp"

namespace skytrack::asterix::test {
namespace {

Bytes plot_block(double t) {
  return block(48, {record({{1, {20, 4}}, {2, tod(t)}, {3, {0x20}}, {4, polar(10, 10, 256)}})});
}

std::vector<Datagram> read_all(CaptureReader& reader) {
  std::vector<Datagram> out;
  while (auto d = reader.next()) out.push_back(*d);
  return out;
}

TEST(Capture, RawBlocksAreReadOneByOne) {
  const Bytes file = concat({plot_block(1), plot_block(2), plot_block(3)});
  CaptureReader reader = CaptureReader::from_memory(file);
  EXPECT_EQ(reader.format(), CaptureFormat::kRaw);
  const auto all = read_all(reader);
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all[1].where.offset, plot_block(1).size());
  EXPECT_EQ(all[1].where.datagram, 0u);
  EXPECT_FALSE(all[1].reception_time);
}

TEST(Capture, RawFileResynchronisesAfterABadLength) {
  Bytes damaged = plot_block(2);
  damaged[1] = 0xFF;  // LEN far past the end of the file
  std::vector<CaptureProblem> problems;
  const Bytes file = concat({plot_block(1), damaged, plot_block(3), plot_block(4)});
  CaptureReader reader =
      CaptureReader::from_memory(file, {}, [&](const CaptureProblem& p) { problems.push_back(p); });
  const auto all = read_all(reader);
  ASSERT_EQ(all.size(), 3u);  // blocks 1, 3 and 4
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].offset, plot_block(1).size());
  EXPECT_EQ(reader.counts().skipped_bytes, damaged.size());
}

TEST(Capture, RawFileCutShortEndsWithAProblem) {
  const Bytes whole = concat({plot_block(1), plot_block(2)});
  const Bytes file(whole.begin(), whole.end() - 3);
  std::size_t problems = 0;
  CaptureReader reader =
      CaptureReader::from_memory(file, {}, [&](const CaptureProblem&) { ++problems; });
  EXPECT_EQ(read_all(reader).size(), 1u);
  EXPECT_EQ(problems, 1u);
}

TEST(Capture, PcapOnEveryLinkType) {
  const Bytes payload = plot_block(1);
  const Bytes ip = ipv4_udp(payload, 8600, 8600);
  Bytes sll(16, 0);
  sll[14] = 0x08;
  sll.insert(sll.end(), ip.begin(), ip.end());
  Bytes sll2(20, 0);
  sll2[0] = 0x08;
  sll2.insert(sll2.end(), ip.begin(), ip.end());
  Bytes null_link{2, 0, 0, 0};
  null_link.insert(null_link.end(), ip.begin(), ip.end());
  const std::vector<std::pair<std::uint32_t, Bytes>> cases{
      {1, ethernet_udp(payload, 8600, 8600)},
      {1, ethernet_udp(payload, 8600, 8600, {10, 0, 0, 1}, true)},  // VLAN
      {101, ip},
      {228, ip},
      {113, sll},
      {276, sll2},
      {0, null_link}};
  for (const auto& [link, frame] : cases) {
    const Bytes file = pcap_file(link, {{66431.5, frame}});
    CaptureReader reader = CaptureReader::from_memory(file);
    EXPECT_EQ(reader.format(), CaptureFormat::kPcap);
    const auto all = read_all(reader);
    ASSERT_EQ(all.size(), 1u) << "link type " << link;
    EXPECT_EQ(all[0].payload.size(), payload.size());
    EXPECT_TRUE(std::equal(payload.begin(), payload.end(), all[0].payload.begin()));
    EXPECT_NEAR(*all[0].reception_time, 66431.5, 1e-6);
    EXPECT_EQ(all[0].where.datagram, 1u);
    EXPECT_EQ(file[all[0].where.offset], 48);  // the offset points at the payload
  }
}

TEST(Capture, PcapngInBothByteOrders) {
  for (const bool big : {false, true}) {
    const Bytes file = pcapng_file(1,
                                   {{10.25, ethernet_udp(plot_block(1), 1, 8600)},
                                    {11.5, ethernet_udp(plot_block(2), 1, 8600)}},
                                   big);
    CaptureReader reader = CaptureReader::from_memory(file);
    EXPECT_EQ(reader.format(), CaptureFormat::kPcapNg);
    const auto all = read_all(reader);
    ASSERT_EQ(all.size(), 2u) << big;
    EXPECT_NEAR(*all[1].reception_time, 11.5, 1e-6);
    EXPECT_EQ(file[all[1].where.offset], 48);
  }
}

TEST(Capture, FilterByPortAndSource) {
  const Bytes file = pcap_file(1, {{1, ethernet_udp(plot_block(1), 5000, 8600, {10, 0, 0, 1})},
                                   {2, ethernet_udp(plot_block(2), 5000, 8601, {10, 0, 0, 1})},
                                   {3, ethernet_udp(plot_block(3), 5001, 8600, {10, 0, 0, 2})}});
  const auto count = [&](const std::string& port, const std::string& source) {
    auto filter = parse_capture_filter(port, source);
    EXPECT_TRUE(filter) << filter.error().message;
    CaptureReader reader = CaptureReader::from_memory(file, *filter);
    return read_all(reader).size();
  };
  EXPECT_EQ(count("", ""), 3u);
  EXPECT_EQ(count("8600", ""), 2u);
  EXPECT_EQ(count("8600", "10.0.0.1"), 1u);
  EXPECT_EQ(count("", "10.0.0.2:5001"), 1u);
  EXPECT_EQ(count("", "10.0.0.2:5000"), 0u);
  EXPECT_FALSE(parse_capture_filter("99999", ""));
  EXPECT_FALSE(parse_capture_filter("", "not-an-address"));
}

TEST(Capture, NonUdpAndDamagedFramesAreCountedAndSkipped) {
  Bytes tcp = ethernet_udp(plot_block(1), 1, 8600);
  tcp[14 + 9] = 6;  // protocol TCP
  Bytes cut = ethernet_udp(plot_block(2), 1, 8600);
  cut.resize(30);
  Bytes fragment = ethernet_udp(plot_block(3), 1, 8600);
  fragment[14 + 6] = 0x20;  // more fragments
  const Bytes file =
      pcap_file(1, {{1, tcp}, {2, cut}, {3, fragment}, {4, ethernet_udp(plot_block(4), 1, 8600)}});
  CaptureReader reader = CaptureReader::from_memory(file);
  EXPECT_EQ(read_all(reader).size(), 1u);
  EXPECT_EQ(reader.counts().not_udp, 2u);
  EXPECT_EQ(reader.counts().damaged, 1u);
  EXPECT_EQ(reader.counts().frames, 4u);
}

TEST(Capture, PcapCutShortInARecordEndsWithAProblem) {
  const Bytes whole = pcap_file(
      1, {{1, ethernet_udp(plot_block(1), 1, 8600)}, {2, ethernet_udp(plot_block(2), 1, 8600)}});
  const Bytes file(whole.begin(), whole.end() - 5);
  std::vector<CaptureProblem> problems;
  CaptureReader reader =
      CaptureReader::from_memory(file, {}, [&](const CaptureProblem& p) { problems.push_back(p); });
  EXPECT_EQ(read_all(reader).size(), 1u);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].message.find("past the end"), std::string::npos);
}

TEST(Capture, MissingFileIsAnError) {
  auto reader = CaptureReader::open("/nonexistent/file.pcap");
  ASSERT_FALSE(reader);
  EXPECT_NE(reader.error().message.find("/nonexistent/file.pcap"), std::string::npos);
}

}  // namespace
}  // namespace skytrack::asterix::test
