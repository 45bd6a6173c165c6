// Bad input never stops the decoder: each case is reported with its origin, counted by reason
// and skipped, and what the structure still allows is decoded.
#include <gtest/gtest.h>

#include "asterix_test_support.hpp"

namespace skytrack::asterix::test {
namespace {

Bytes good_plot() {
  return record({{1, {20, 4}}, {2, tod(10.0)}, {3, {0x20}}, {4, polar(10, 10, 256)}});
}

/// Decodes and returns the single error's reason (failing the test if there is not one).
struct Result {
  Collected out;
  DecodeCounters counters;
};
Result run(const Bytes& bytes, Origin where = {0, 7}) {
  Decoder decoder;
  Result r;
  decoder.decode(bytes, where, 100.0, r.out);
  r.counters = decoder.counters();
  return r;
}

TEST(BadInput, TruncatedBlockHeader) {
  const Result r = run(concat({block(48, {good_plot()}), {48, 0}}));
  EXPECT_EQ(r.out.reports.size(), 1u);  // the block before it is decoded
  ASSERT_EQ(r.out.errors.size(), 1u);
  EXPECT_EQ(r.out.errors[0].reason, ErrorReason::kTruncatedBlock);
  EXPECT_EQ(r.out.errors[0].where.datagram, 7u);
  EXPECT_EQ(r.counters.errors[static_cast<int>(ErrorReason::kTruncatedBlock)], 1u);
}

TEST(BadInput, BlockLengthBelowHeader) {
  const Result r = run(Bytes{48, 0, 2, 0x80, 1});
  ASSERT_EQ(r.out.errors.size(), 1u);
  EXPECT_EQ(r.out.errors[0].reason, ErrorReason::kBadBlockLength);
}

TEST(BadInput, LengthPastTheEndOfTheDatagram) {
  Bytes b = block(48, {good_plot()});
  b[2] = static_cast<std::uint8_t>(b[2] + 10);
  const Result r = run(concat({block(48, {good_plot()}), b}), Origin{1000, 3});
  EXPECT_EQ(r.out.reports.size(), 1u);
  ASSERT_EQ(r.out.errors.size(), 1u);
  EXPECT_EQ(r.out.errors[0].reason, ErrorReason::kLengthPastEnd);
  EXPECT_EQ(r.out.errors[0].where.offset, 1000u + block(48, {good_plot()}).size());
  EXPECT_NE(to_string(r.out.errors[0]).find("datagram 3"), std::string::npos);
}

TEST(BadInput, FspecRunningPastTheBlock) {
  const Result r = run(Bytes{48, 0, 5, 0xFF, 0xFF});
  ASSERT_EQ(r.out.errors.size(), 1u);
  EXPECT_EQ(r.out.errors[0].reason, ErrorReason::kFspecPastEnd);
}

TEST(BadInput, EndlessFspec) {
  // FX set on all of CAT048's four FSPEC octets, and on more.
  const Result r = run(concat({Bytes{48, 0, 13}, Bytes(10, 0xFF)}));
  ASSERT_EQ(r.out.errors.size(), 1u);
  EXPECT_EQ(r.out.errors[0].reason, ErrorReason::kFspecTooLong);
}

TEST(BadInput, ItemRunningPastTheBlock) {
  // I048/040 announced, 1 of its 4 bytes present.
  const Result r = run(Bytes{48, 0, 11, 0xF0, 20, 4, 0, 0, 1, 0x20, 0});
  ASSERT_EQ(r.out.errors.size(), 1u);
  EXPECT_EQ(r.out.errors[0].reason, ErrorReason::kItemPastEnd);
  EXPECT_NE(r.out.errors[0].detail.find("I048/040"), std::string::npos);
}

TEST(BadInput, AbsurdRepetitionCount) {
  // I048/250 with REP 200 (1600 bytes) in a short block.
  const Bytes r250 = record({{1, {20, 4}}, {2, tod(1.0)}, {10, concat({{200}, Bytes(8, 0)})}});
  const Result r = run(block(48, {r250, good_plot()}));
  EXPECT_TRUE(r.out.reports.empty());
  ASSERT_EQ(r.out.errors.size(), 1u);
  EXPECT_EQ(r.out.errors[0].reason, ErrorReason::kRepetitionPastEnd);
}

TEST(BadInput, ExplicitLengthZeroOrPastTheEnd) {
  const Result zero = run(block(48, {record({{1, {20, 4}}, {27, {0}}})}));
  ASSERT_EQ(zero.out.errors.size(), 1u);
  EXPECT_EQ(zero.out.errors[0].reason, ErrorReason::kRepetitionPastEnd);
  const Result past = run(block(48, {record({{1, {20, 4}}, {28, {50, 1}}})}));
  ASSERT_EQ(past.out.errors.size(), 1u);
  EXPECT_EQ(past.out.errors[0].reason, ErrorReason::kRepetitionPastEnd);
}

TEST(BadInput, EmptyFspecStopsTheBlock) {
  const Result r = run(block(48, {good_plot(), Bytes{0, 0, 0}}));
  EXPECT_EQ(r.out.reports.size(), 1u);
  ASSERT_EQ(r.out.errors.size(), 1u);
  EXPECT_EQ(r.out.errors[0].reason, ErrorReason::kMissingItem);
}

TEST(BadInput, UnknownCategoryIsSkippedByLength) {
  const Bytes cat62 = concat({Bytes{62, 0, 8}, Bytes(5, 0xFF)});
  const Result r = run(concat({cat62, block(48, {good_plot()})}));
  EXPECT_TRUE(r.out.errors.empty());
  EXPECT_EQ(r.out.reports.size(), 1u);
  EXPECT_EQ(r.counters.unknown_category_blocks, 1u);
  EXPECT_EQ(r.counters.blocks_by_category[62], 1u);
  EXPECT_EQ(r.counters.blocks, 2u);
}

TEST(BadInput, ErrorsAreCountedByReasonAcrossDatagrams) {
  Decoder decoder;
  Collected out;
  decoder.decode(Bytes{48, 0, 2}, {0, 1}, std::nullopt, out);
  decoder.decode(Bytes{48, 0, 2}, {0, 2}, std::nullopt, out);
  decoder.decode(Bytes{48}, {0, 3}, std::nullopt, out);
  EXPECT_EQ(decoder.counters().errors[static_cast<int>(ErrorReason::kBadBlockLength)], 2u);
  EXPECT_EQ(decoder.counters().errors[static_cast<int>(ErrorReason::kTruncatedBlock)], 1u);
  EXPECT_EQ(decoder.counters().total_errors(), 3u);
  EXPECT_EQ(decoder.counters().datagrams, 3u);
}

TEST(BadInput, EveryTruncationOfARealBlockIsSurvived) {
  // Every prefix of a valid two-record block, with LEN patched to fit: never a crash, and
  // never more reports than records.
  const Bytes full = block(48, {good_plot(), good_plot()});
  for (std::size_t n = 0; n < full.size(); ++n) {
    Bytes cut(full.begin(), full.begin() + static_cast<std::ptrdiff_t>(n));
    if (n >= 3) cut[2] = static_cast<std::uint8_t>(n);
    const Result r = run(cut);
    EXPECT_LE(r.out.reports.size(), 1u) << n;
  }
}

}  // namespace
}  // namespace skytrack::asterix::test
