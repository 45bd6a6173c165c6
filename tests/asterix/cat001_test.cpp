// CAT001 plots and tracks (both UAPs, chosen by I001/020 TYP) and the completion of the
// truncated time of day I001/141 from CAT002 or the reception time.
#include <gtest/gtest.h>

#include "asterix_test_support.hpp"

namespace skytrack::asterix::test {
namespace {

constexpr double kNm = 1852.0;

/// A plot-UAP record: 010, 020 (sole SSR), 040, 070, 090, 130, 141 (as canalA sends them).
Bytes plot_record(double truncated_s, std::uint8_t descriptor = 0x20) {
  return record({{1, {20, 130}},
                 {2, {descriptor}},
                 {3, polar(5.28125, 175.84716796875, 128.0)},
                 {4, u16(02270)},
                 {5, u16(221 * 4)},
                 {6, {0x0C}},
                 {7, u16(static_cast<unsigned>(truncated_s * 128.0))}});
}

Bytes north_marker(double tod_s) {
  return block(2, {record({{1, {20, 130}}, {2, {1}}, {4, tod(tod_s)}, {5, u16(513)}})});
}

TEST(Cat001, PlotUapGivesAPlotTimedByTheReceptionTime) {
  // GIVEN canalA's first record, received at 66431.664 s (truncated time 383.578125 s)
  const Collected out = decode(block(1, {plot_record(383.578125)}), 66431.664062);
  ASSERT_TRUE(out.errors.empty());
  ASSERT_EQ(out.reports.size(), 1u);
  const TargetReport& r = out.reports[0];
  EXPECT_EQ(r.category, 1);
  EXPECT_EQ(r.sensor, 20u * 256u + 130u);
  EXPECT_DOUBLE_EQ(r.time, 66431.578125);  // 129 * 512 + 383.578125
  EXPECT_DOUBLE_EQ(r.range, 5.28125 * kNm);
  EXPECT_EQ(r.mode3a, 02270);
  EXPECT_EQ(r.flight_level, 221.0);
}

TEST(Cat001, TrackUapIsChosenByTyp) {
  // 010, 020 (TYP 1), 161, 040, 042, 200, 070 | 090, 141, 130, 131, 120, 170, 210 | 050 ... 150
  const Bytes track = record({{1, {20, 130}},     {2, {0xA0}},
                              {3, u16(12)},       {4, polar(10.0, 45.0, 128.0)},
                              {5, {0, 1, 0, 1}},  {6, {0, 1, 0, 1}},
                              {7, u16(07777)},    {8, u16(100 * 4)},
                              {9, u16(10 * 128)}, {10, {0x02, 0x00}},
                              {11, {1}},          {12, {1}},
                              {13, {0x00}},       {14, {0x01, 0x00}},
                              {15, u16(0)},       {16, u16(0)},
                              {17, {0, 0, 0, 0}}, {18, u16(0)},
                              {19, {0x00}},       {20, {1}},  // SP: length 1, nothing else
                              {22, {0x80}}});                 // 150
  Decoder decoder;
  Collected out;
  decoder.decode(block(1, {track, plot_record(11.0)}), {}, 1000.0, out);
  ASSERT_TRUE(out.errors.empty()) << to_string(out.errors.front());
  ASSERT_EQ(out.reports.size(), 2u);
  EXPECT_DOUBLE_EQ(out.reports[0].range, 10.0 * kNm);
  EXPECT_EQ(out.reports[0].mode3a, 07777);
  EXPECT_EQ(out.reports[0].flight_level, 100.0);
  EXPECT_DOUBLE_EQ(out.reports[0].time, 1024.0 + 10.0);  // nearest to 1000 s: 2 * 512 + 10
  EXPECT_DOUBLE_EQ(out.reports[1].time, 1035.0);
  EXPECT_EQ(decoder.counters().items_skipped, 15u + 1u);  // track: 21 - 6; plot: I001/130
}

TEST(Cat001, RandomFieldSequencingIsWalked) {
  // RFS (FRN 21): two fields, I001/131 (FRN 10) and I001/120 (FRN 9), sent out of order.
  const Bytes r = record({{1, {20, 130}},
                          {2, {0x20}},
                          {3, polar(1, 1, 128)},
                          {7, u16(128)},
                          {21, {2, 10, 0x11, 9, 0x22}}});
  const Collected out = decode(block(1, {r, plot_record(2.0)}), 10.0);
  EXPECT_TRUE(out.errors.empty());
  EXPECT_EQ(out.reports.size(), 2u);
}

TEST(Cat001, TruncatedTimeIsCompletedFromTheLatestCat002) {
  Decoder decoder;
  Collected out;
  // GIVEN a north marker at 66 560 s (130 * 512) without reception times
  decoder.decode(north_marker(66560.0), {}, std::nullopt, out);
  // WHEN plots with truncated times just before and after the 512 s wrap follow
  decoder.decode(block(1, {plot_record(511.5), plot_record(1.0)}), {}, std::nullopt, out);
  ASSERT_EQ(out.reports.size(), 2u);
  EXPECT_DOUBLE_EQ(out.reports[0].time, 66559.5);
  EXPECT_DOUBLE_EQ(out.reports[1].time, 66561.0);
  ASSERT_EQ(out.services.size(), 1u);
  EXPECT_DOUBLE_EQ(*out.services[0].rotation_period, 513.0 / 128.0);
}

TEST(Cat001, Cat002ReferenceMovesOnWithTheReceptionTime) {
  Decoder decoder;
  Collected out;
  decoder.decode(north_marker(1000.0), {}, 5000.0, out);
  // 300 s later by the capture clock (more than half the 512 s span): 1300 s, not 788 s.
  decoder.decode(block(1, {plot_record(1300.0 - 1024.0)}), {}, 5300.0, out);
  ASSERT_EQ(out.reports.size(), 1u);
  EXPECT_DOUBLE_EQ(out.reports[0].time, 1300.0);
}

TEST(Cat001, TruncatedTimeWithoutAnyReferenceIsAnError) {
  const Collected out = decode(block(1, {plot_record(1.0)}));
  EXPECT_TRUE(out.reports.empty());
  ASSERT_EQ(out.errors.size(), 1u);
  EXPECT_EQ(out.errors[0].reason, ErrorReason::kNoTimeReference);
}

TEST(Cat001, NoDetectionAndTestTargetsAreDropped) {
  Decoder decoder;
  Collected out;
  const Bytes tst = record({{1, {20, 130}}, {2, {0x21, 0x80}}, {3, polar(1, 1, 128)}, {7, u16(1)}});
  decoder.decode(block(1, {plot_record(1.0, 0x00), tst}), {}, 10.0, out);
  EXPECT_TRUE(out.reports.empty());
  EXPECT_EQ(decoder.counters().dropped[static_cast<int>(DropReason::kNoDetection)], 1u);
  EXPECT_EQ(decoder.counters().dropped[static_cast<int>(DropReason::kTest)], 1u);
}

TEST(Cat001, SpareItemBitMakesTheRestOfTheBlockUnreadable) {
  const Bytes spare = record({{1, {20, 130}}, {2, {0x20}}, {16, {0}}});
  const Collected out = decode(block(1, {spare, plot_record(1.0)}), 10.0);
  EXPECT_TRUE(out.reports.empty());
  ASSERT_EQ(out.errors.size(), 1u);
  EXPECT_EQ(out.errors[0].reason, ErrorReason::kUndefinedItem);
}

}  // namespace
}  // namespace skytrack::asterix::test
