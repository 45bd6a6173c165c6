// CAT048 target reports, hand-built item by item (EUROCONTROL CAT048 UAP).
#include <gtest/gtest.h>

#include <cmath>

#include "asterix_test_support.hpp"

namespace skytrack::asterix::test {
namespace {

constexpr double kNm = 1852.0;
constexpr double kDeg = 3.14159265358979323846 / 180.0;

/// I048/010, 140, 020 (SSR + PSR), 040, 070, 090, 220: a plain Mode S plot.
Bytes plain_record(double tod_s = 30015.609375, std::uint8_t descriptor = 0x60) {
  return record({{1, {20, 4}},
                 {2, tod(tod_s)},
                 {3, {descriptor}},
                 {4, polar(80.5625, 233.959350585938, 256.0)},
                 {5, u16(02600)},
                 {6, u16(71 * 4)},
                 {8, u24(0x343085)}});
}

TEST(Cat048, ReadsTheInterpretedItems) {
  const Collected out = decode(block(48, {plain_record()}));
  ASSERT_TRUE(out.errors.empty());
  ASSERT_EQ(out.reports.size(), 1u);
  const TargetReport& r = out.reports[0];
  EXPECT_EQ(r.category, 48);
  EXPECT_EQ(r.sensor, 20u * 256u + 4u);
  EXPECT_DOUBLE_EQ(r.time, 30015.609375);
  EXPECT_DOUBLE_EQ(r.range, 80.5625 * kNm);
  EXPECT_NEAR(r.azimuth, 233.959350585938 * kDeg, 1e-12);
  EXPECT_EQ(r.mode3a, 02600);
  EXPECT_EQ(r.flight_level, 71.0);
  EXPECT_EQ(r.mode_s, 0x343085u);
  EXPECT_EQ(r.where.datagram, 1u);
  EXPECT_EQ(r.where.offset, 3u);  // after the block header
}

TEST(Cat048, SkipsEveryOtherItemByItsLength) {
  // GIVEN a record with all 28 items of the UAP, compound and repetitive ones included
  const Bytes all = record({{1, {20, 4}},
                            {2, tod(100.0)},
                            {3, {0xA1, 0x00}},  // TYP 5, extension without TST
                            {4, polar(10.0, 90.0, 256.0)},
                            {5, u16(01234)},
                            {6, u16(static_cast<unsigned>(-8) & 0x3FFFu)},  // FL -2
                            {7, {0xFE, 1, 2, 3, 4, 5, 6, 7}},               // 130: 7 subfields
                            {8, u24(0xABCDEF)},
                            {9, {1, 2, 3, 4, 5, 6}},
                            {10, concat({{2}, Bytes(16, 0x55)})},  // 250: two BDS registers
                            {11, u16(77)},
                            {12, {0, 1, 0, 2}},
                            {13, {0, 1, 0, 2}},
                            {14, {0x01, 0x00}},  // 170 with one extension
                            {15, {1, 2, 3, 4}},
                            {16, {0x03, 0x02}},  // 030 extended
                            {17, u16(0)},
                            {18, {0, 0, 0, 0}},
                            {19, u16(0)},
                            {20, {0xC0, 0, 5, 2, 1, 2, 3, 4, 5, 6, 1, 2, 3, 4, 5, 6}},  // 120
                            {21, u16(0)},
                            {22, Bytes(7, 0)},
                            {23, {0}},
                            {24, u16(0)},
                            {25, {0}},
                            {26, u16(0)},
                            {27, {3, 9, 9}},  // SP: length 3
                            {28, {2, 7}}});   // RE: length 2
  Decoder decoder;
  Collected out;
  decoder.decode(block(48, {all, plain_record()}), Origin{0, 1}, std::nullopt, out);
  // THEN both records decode, the first with its interpreted values
  ASSERT_TRUE(out.errors.empty()) << to_string(out.errors.front());
  ASSERT_EQ(out.reports.size(), 2u);
  EXPECT_EQ(out.reports[0].mode3a, 01234);
  EXPECT_EQ(out.reports[0].flight_level, -2.0);
  EXPECT_EQ(out.reports[0].mode_s, 0xABCDEFu);
  EXPECT_DOUBLE_EQ(out.reports[0].range, 10.0 * kNm);
  EXPECT_EQ(out.reports[1].mode_s, 0x343085u);
  EXPECT_EQ(decoder.counters().items_skipped, 21u);
  EXPECT_EQ(decoder.counters().records_by_category[48], 2u);
}

TEST(Cat048, NoDetectionIsNotAPlot) {
  Decoder decoder;
  Collected out;
  decoder.decode(block(48, {plain_record(100.0, 0x00)}), {}, std::nullopt, out);
  EXPECT_TRUE(out.reports.empty());
  EXPECT_EQ(decoder.counters().dropped[static_cast<int>(DropReason::kNoDetection)], 1u);
}

TEST(Cat048, SimulatedAndTestReportsAreDroppedUnlessKept) {
  const Bytes sim = record({{1, {20, 4}}, {2, tod(1.0)}, {3, {0x50}}, {4, polar(1, 1, 256)}});
  const Bytes tst = record({{1, {20, 4}}, {2, tod(1.0)}, {3, {0x41, 0x80}}, {4, polar(1, 1, 256)}});
  Decoder decoder;
  Collected out;
  decoder.decode(block(48, {sim, tst}), {}, std::nullopt, out);
  EXPECT_TRUE(out.reports.empty());
  EXPECT_EQ(decoder.counters().dropped[static_cast<int>(DropReason::kSimulated)], 1u);
  EXPECT_EQ(decoder.counters().dropped[static_cast<int>(DropReason::kTest)], 1u);
  DecoderOptions keep;
  keep.keep_tests = true;
  const Collected kept = decode(block(48, {sim, tst}), std::nullopt, keep);
  ASSERT_EQ(kept.reports.size(), 2u);
  EXPECT_TRUE(kept.reports[0].simulated);
  EXPECT_TRUE(kept.reports[1].test);
}

TEST(Cat048, FieldMonitorIsKeptAndMarked) {
  const Collected out = decode(block(48, {plain_record(1.0, 0x42)}));
  ASSERT_EQ(out.reports.size(), 1u);
  EXPECT_TRUE(out.reports[0].fixed_transponder);
}

TEST(Cat048, ReportWithoutPositionIsDropped) {
  Decoder decoder;
  Collected out;
  decoder.decode(block(48, {record({{1, {20, 4}}, {2, tod(1.0)}, {3, {0x20}}})}), {}, std::nullopt,
                 out);
  EXPECT_TRUE(out.reports.empty());
  EXPECT_EQ(decoder.counters().dropped[static_cast<int>(DropReason::kNoPosition)], 1u);
}

TEST(Cat048, UnvalidatedCodesAreLeftOut) {
  const Collected out = decode(block(48, {record({{1, {20, 4}},
                                                  {2, tod(1.0)},
                                                  {4, polar(1, 1, 256)},
                                                  {5, u16(0x8000 | 01234)},
                                                  {6, u16(0x8000 | 400)}})}));
  ASSERT_EQ(out.reports.size(), 1u);
  EXPECT_FALSE(out.reports[0].mode3a);
  EXPECT_FALSE(out.reports[0].flight_level);
}

TEST(Cat048, FlightLevelOutOfRangeIsReportedAndTheRestOfThePlotKept) {
  // 14-bit FL 2000 (8000 quarters) is beyond any transponder's range.
  const Collected out = decode(
      block(48, {record({{1, {20, 4}}, {2, tod(1.0)}, {4, polar(1, 1, 256)}, {6, u16(8000)}})}));
  ASSERT_EQ(out.reports.size(), 1u);
  EXPECT_FALSE(out.reports[0].flight_level);
  ASSERT_EQ(out.errors.size(), 1u);
  EXPECT_EQ(out.errors[0].reason, ErrorReason::kValueOutOfRange);
}

TEST(Cat048, TimeOfDayPastMidnightValueIsRejectedAndTheNextRecordDecoded) {
  const Bytes bad = record({{1, {20, 4}}, {2, u24(86400u * 128u)}, {4, polar(1, 1, 256)}});
  const Collected out = decode(block(48, {bad, plain_record()}));
  ASSERT_EQ(out.errors.size(), 1u);
  EXPECT_EQ(out.errors[0].reason, ErrorReason::kValueOutOfRange);
  EXPECT_EQ(out.errors[0].where.offset, 3u);
  EXPECT_EQ(out.reports.size(), 1u);
}

TEST(Cat048, TimeContinuesPastMidnight) {
  Decoder decoder;
  Collected out;
  decoder.decode(block(48, {plain_record(86399.5)}), {}, std::nullopt, out);
  decoder.decode(block(48, {plain_record(0.5)}), {}, std::nullopt, out);
  decoder.decode(block(48, {plain_record(86399.9)}), {}, std::nullopt, out);  // late, from before
  ASSERT_EQ(out.reports.size(), 3u);
  EXPECT_DOUBLE_EQ(out.reports[1].time, 86400.5);
  EXPECT_NEAR(out.reports[2].time, 86399.9, 1e-2);
}

TEST(Cat048, MissingDataSourceOrTimeIsAnError) {
  const Collected out = decode(block(48, {record({{2, tod(1.0)}, {4, polar(1, 1, 256)}}),
                                          record({{1, {1, 2}}, {4, polar(1, 1, 256)}})}));
  ASSERT_EQ(out.errors.size(), 2u);
  EXPECT_EQ(out.errors[0].reason, ErrorReason::kMissingItem);
  EXPECT_EQ(out.errors[1].reason, ErrorReason::kMissingItem);
}

TEST(Cat048, SensorSelectionDropsOtherRadars) {
  DecoderOptions options;
  options.sensor = sensor_id(20, 5);
  Decoder decoder(options);
  Collected out;
  decoder.decode(block(48, {plain_record()}), {}, std::nullopt, out);
  EXPECT_TRUE(out.reports.empty());
  EXPECT_EQ(decoder.counters().dropped[static_cast<int>(DropReason::kOtherSensor)], 1u);
}

}  // namespace
}  // namespace skytrack::asterix::test
