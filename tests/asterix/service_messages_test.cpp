// CAT002 and CAT034 service messages: north markers, sector crossings, rotation period, radar
// position; the items that are only skipped, compound and repetitive ones included.
#include <gtest/gtest.h>

#include "asterix_test_support.hpp"

namespace skytrack::asterix::test {
namespace {

constexpr double kTwoPi = 6.283185307179586;

TEST(Cat002, NorthMarkerSectorCrossingAndSouthMarker) {
  const Bytes north = record({{1, {20, 130}}, {2, {1}}, {4, tod(100.0)}, {5, u16(513)}});
  const Bytes sector = record({{1, {20, 130}}, {2, {2}}, {3, {64}}, {4, tod(101.0)}});
  const Bytes south = record({{1, {20, 130}}, {2, {3}}, {4, tod(102.0)}});
  const Bytes blind = record({{1, {20, 130}}, {2, {8}}, {4, tod(103.0)}});
  const Collected out = decode(block(2, {north, sector, south, blind}));
  ASSERT_TRUE(out.errors.empty());
  ASSERT_EQ(out.services.size(), 4u);
  EXPECT_EQ(out.services[0].kind, ServiceKind::kNorthMarker);
  EXPECT_EQ(*out.services[0].azimuth, 0.0);
  EXPECT_DOUBLE_EQ(*out.services[0].rotation_period, 513.0 / 128.0);
  EXPECT_DOUBLE_EQ(*out.services[0].time, 100.0);
  EXPECT_EQ(out.services[1].kind, ServiceKind::kSectorCrossing);
  EXPECT_DOUBLE_EQ(*out.services[1].azimuth, kTwoPi / 4.0);
  EXPECT_EQ(out.services[2].kind, ServiceKind::kSouthMarker);
  EXPECT_DOUBLE_EQ(*out.services[2].azimuth, kTwoPi / 2.0);
  EXPECT_EQ(out.services[3].kind, ServiceKind::kOther);
  EXPECT_EQ(out.services[3].message_type, 8);
}

TEST(Cat002, SkippedItemsAreWalked) {
  const Bytes full = record({{1, {20, 130}},
                             {2, {1}},
                             {3, {0}},
                             {4, tod(5.0)},
                             {5, u16(512)},
                             {6, {0x01, 0x00}},
                             {7, {0x00}},
                             {8, {2, 0, 1, 0, 2}},
                             {9, Bytes(8, 0)},
                             {10, u16(0)},
                             {11, {0x00}},
                             {13, {2, 0}}});
  Decoder decoder;
  Collected out;
  decoder.decode(block(2, {full, full}), {}, std::nullopt, out);
  ASSERT_TRUE(out.errors.empty()) << to_string(out.errors.front());
  EXPECT_EQ(out.services.size(), 2u);
  EXPECT_EQ(decoder.counters().items_skipped, 2u * 7u);
}

TEST(Cat002, UnknownMessageTypeIsOutOfRange) {
  const Collected out = decode(block(2, {record({{1, {20, 130}}, {2, {99}}, {4, tod(5.0)}})}));
  EXPECT_TRUE(out.services.empty());
  ASSERT_EQ(out.errors.size(), 1u);
  EXPECT_EQ(out.errors[0].reason, ErrorReason::kValueOutOfRange);
}

TEST(Cat034, NorthMarkerSectorAndRadarPosition) {
  // I034/120: height 250 m, latitude 45 deg (2^21 * 180 / 2^23 = 45), longitude -15 deg.
  const unsigned lat = 1u << 21;
  const unsigned lon = (1u << 24) - (1u << 21) / 3u;  // -2^21 / 3 steps
  const Bytes north = record({{1, {20, 4}},
                              {2, {1}},
                              {3, tod(30017.359375)},
                              {5, u16(637)},
                              {11, concat({u16(250), u24(lat), u24(lon)})}});
  const Bytes sector = record({{1, {20, 4}}, {2, {2}}, {3, tod(30017.5)}, {4, {128}}});
  const Collected out = decode(block(34, {north, sector}));
  ASSERT_TRUE(out.errors.empty());
  ASSERT_EQ(out.services.size(), 2u);
  const ServiceMessage& n = out.services[0];
  EXPECT_EQ(n.category, 34);
  EXPECT_EQ(n.kind, ServiceKind::kNorthMarker);
  EXPECT_DOUBLE_EQ(*n.time, 30017.359375);
  EXPECT_DOUBLE_EQ(*n.rotation_period, 637.0 / 128.0);
  ASSERT_TRUE(n.position);
  EXPECT_DOUBLE_EQ((*n.position)[0], 45.0);
  EXPECT_NEAR((*n.position)[1], -15.0, 1e-4);
  EXPECT_DOUBLE_EQ((*n.position)[2], 250.0);
  EXPECT_DOUBLE_EQ(*out.services[1].azimuth, kTwoPi / 2.0);
}

TEST(Cat034, CompoundAndRepetitiveItemsAreSkipped) {
  const Bytes full = record({{1, {20, 4}},
                             {2, {1}},
                             {3, tod(1.0)},
                             {4, {0}},
                             {5, u16(640)},
                             {6, {0x9C, 1, 2, 3, 4, 5}},  // 050: COM, PSR, SSR, MDS (2)
                             {7, {0x9C, 1, 2, 3, 4}},     // 060: COM, PSR, SSR, MDS
                             {8, {3, 0, 1, 0, 2, 0, 3}},  // 070: three counters
                             {9, Bytes(8, 0)},
                             {10, {0}},
                             {12, u16(0)},
                             {13, {3, 0, 0}},
                             {14, {1}}});
  Decoder decoder;
  Collected out;
  decoder.decode(block(34, {full}), {}, std::nullopt, out);
  ASSERT_TRUE(out.errors.empty()) << to_string(out.errors.front());
  EXPECT_EQ(out.services.size(), 1u);
  EXPECT_EQ(decoder.counters().items_skipped, 8u);
}

TEST(Cat034, SpareSubfieldOfACompoundItemIsUndefined) {
  const Collected out =
      decode(block(34, {record({{1, {20, 4}}, {2, {1}}, {6, {0x40, 0}}})}));  // 050 bit 7
  ASSERT_EQ(out.errors.size(), 1u);
  EXPECT_EQ(out.errors[0].reason, ErrorReason::kUndefinedItem);
}

TEST(Cat034, SectorCrossingWithoutSectorAndZeroRotationPeriodAreErrors) {
  const Collected out =
      decode(block(34, {record({{1, {20, 4}}, {2, {2}}, {3, tod(1.0)}}),
                        record({{1, {20, 4}}, {2, {1}}, {3, tod(1.0)}, {5, u16(0)}})}));
  ASSERT_EQ(out.errors.size(), 2u);
  EXPECT_EQ(out.errors[0].reason, ErrorReason::kMissingItem);
  EXPECT_EQ(out.errors[1].reason, ErrorReason::kValueOutOfRange);
}

}  // namespace
}  // namespace skytrack::asterix::test
