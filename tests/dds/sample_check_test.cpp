// check_serialized over bytes written by the test's own XCDR2 encoder (xcdr2_samples.hpp, laid
// out member by member from idl/skytrack.idl; checked_take_test.cpp shows it writes Cyclone's
// bytes): valid samples of every type in both byte orders pass, and truncations, over-long
// lengths and DHEADERs, strings without room or NUL, other encapsulations, illegal booleans and
// enumerators, and the crafted samples of issue 30, finding 7, are refused with the place named.
#include "skytrack/dds/sample_check.hpp"

#include <functional>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "skytrack/dds/conversion.hpp"
#include "xcdr2_samples.hpp"

namespace skytrack::dds {
namespace {

namespace x = test::xcdr2;
using ::testing::HasSubstr;

PlotScan plot_scan() {
  PlotScan scan;
  scan.sensor = 7;
  scan.scan = 42;
  scan.time = 420.0;
  scan.platform.position = {1.0, 2.0, 8000.0};
  scan.sigma.range = 15.0;
  scan.coverage = AzimuthSector{-0.5, 0.2};
  for (std::int64_t i = 0; i < 5; ++i) {
    Plot p;
    p.id = 100 + i;
    p.form = i % 2 ? PlotForm::kCartesian : PlotForm::kPolar;
    p.range = 30000.0 + 10.0 * i;
    p.azimuth = 0.1 * i;
    p.x = 10.0 * i;
    p.y = -5.0 * i;
    p.snr_db = 12.0;
    if (i == 2) {
      p.mode3a = 01234;
      p.mode_s = 0xabcdef;
      p.flight_level = 350.0;
    }
    scan.plots.push_back(p);
  }
  return scan;
}

TrackFrame track_frame() {
  TrackFrame frame;
  frame.sensor = 1;
  frame.scan = 42;
  frame.time = 420.0;
  TrackReport point;
  point.id = 12;
  point.status = TrackStatus::kConfirmed;
  point.dims = 2;
  point.position = {1003.1, 1996.2, 0.0};
  point.velocity = {248.7, 1.2, 0.0};
  point.covariance.assign(16, 0.5);
  point.modes = {{"cv", 0.91}, {"ct_left", 0.06}, {"ct_right", 0.03}};
  point.quality = 0.97;
  TrackReport group = point;
  group.id = 20;
  group.status = TrackStatus::kCoasting;
  group.kind = ObjectKind::kGroup;
  group.covariance.clear();
  group.modes.clear();
  group.quality.reset();
  group.extent = Eigen::Matrix2d{{400.0, 10.0}, {10.0, 300.0}};
  group.members = 15;
  frame.tracks = {point, group};
  frame.associations = {{12, 3, 0.93, std::nullopt}, {20, 4, 1.0, 41}};
  frame.events = {{TrackEventType::kInitiated, 12, "UTF-8 d\xC3\xA9tail", {}},
                  {TrackEventType::kDeleted, 14, "", {}}};
  return frame;
}

TrackerStatusReport status_report() {
  return {.instance = "skytrackd-1",
          .profile_name = "airspace",
          .profile_version = "3.1",
          .uptime = 3600.5,
          .scans_processed = 14400,
          .plots_processed = 1234567,
          .plots_rejected = {{"negative range", 3}, {"clutter", 100}},
          .scans_rejected = {{"malformed sample", 2}},
          .queue_depth = 2,
          .latency_p50 = 0.004};
}

struct Case {
  std::string name;
  const dds_topic_descriptor_t* type;
  std::function<x::Writer(bool)> encode;
};

/// Every type, full and empty.
std::vector<Case> cases() {
  TrackerStatusReport empty_status;
  empty_status.instance = "i";
  const auto plots = [](const PlotScan& s) {
    return [sample = std::make_shared<PlotBatchSample>(std::move(*to_dds(s)))](bool big) {
      return x::encode(sample->get(), big);
    };
  };
  const auto tracks = [](const TrackFrame& f) {
    return [sample = std::make_shared<TrackBatchSample>(std::move(*to_dds(f)))](bool big) {
      return x::encode(sample->get(), big);
    };
  };
  const auto status = [](const TrackerStatusReport& r) {
    return [sample = std::make_shared<TrackerStatusSample>(std::move(*to_dds(r)))](bool big) {
      return x::encode(sample->get(), big);
    };
  };
  return {{"PlotBatch", &skytrack_dds_PlotBatch_desc, plots(plot_scan())},
          {"empty PlotBatch", &skytrack_dds_PlotBatch_desc, plots(PlotScan{})},
          {"TrackBatch", &skytrack_dds_TrackBatch_desc, tracks(track_frame())},
          {"empty TrackBatch", &skytrack_dds_TrackBatch_desc, tracks(TrackFrame{})},
          {"TrackerStatus", &skytrack_dds_TrackerStatus_desc, status(status_report())},
          {"empty TrackerStatus", &skytrack_dds_TrackerStatus_desc, status(empty_status)}};
}

Expected<void> check(const dds_topic_descriptor_t* type, const std::vector<std::byte>& bytes) {
  return check_serialized(*type, bytes);
}

std::string message(const Expected<void>& result) {
  return result ? std::string("accepted") : result.error().message;
}

TEST(SampleCheck, AcceptsValidSamplesOfEveryTypeInBothByteOrders) {
  for (const Case& c : cases()) {
    for (bool big : {false, true}) {
      const auto result = check(c.type, c.encode(big).bytes());
      EXPECT_TRUE(result) << c.name << (big ? " BE: " : " LE: ") << message(result);
    }
  }
}

TEST(SampleCheck, RefusesEveryTruncation) {
  for (const Case& c : cases()) {
    for (bool big : {false, true}) {
      const std::vector<std::byte> full = c.encode(big).bytes();
      for (std::size_t n = 0; n < full.size(); ++n) {
        const std::vector<std::byte> cut(full.begin(), full.begin() + static_cast<long>(n));
        EXPECT_FALSE(check(c.type, cut)) << c.name << " cut to " << n << " bytes";
      }
    }
  }
}

TEST(SampleCheck, RefusesEveryLengthAndDheaderLongerThanTheBytesLeft) {
  // GIVEN every sequence count, string length and DHEADER of every type, in both byte orders
  for (const Case& c : cases()) {
    for (bool big : {false, true}) {
      x::Writer w = c.encode(big);
      const std::vector<std::byte> original = w.bytes();
      std::vector<std::size_t> fields = w.lengths();
      fields.insert(fields.end(), w.dheaders().begin(), w.dheaders().end());
      for (std::size_t at : fields) {
        // WHEN it claims more than the whole sample, or everything
        for (std::uint32_t claim : {static_cast<std::uint32_t>(original.size()), 0xffffffffu}) {
          x::Writer tampered = c.encode(big);
          tampered.patch(at, claim);
          // THEN the sample is refused
          EXPECT_FALSE(check(c.type, tampered.bytes()))
              << c.name << (big ? " BE" : " LE") << ": field at byte " << at << " = " << claim;
        }
      }
    }
  }
}

TEST(SampleCheck, RefusesHalfPresentEightByteSequencesOfFinding7a) {
  for (bool big : {false, true}) {
    // plot_ids (member 9, its count at body byte 156) claims 1000 ids with 4000 bytes
    const auto ids = check(&skytrack_dds_PlotBatch_desc,
                           x::half_present_plot_batch(x::HalfPresent::kPlotIds, 1000, big).bytes());
    ASSERT_FALSE(ids);
    EXPECT_THAT(ids.error().message,
                HasSubstr("PlotBatch #9 at byte 156 of 4160: 1000 elements of 8 bytes, needs "
                          "8000 bytes, 4000 left"));
    // plot_values (member 11) claims 17 x 64 doubles with half their bytes; ids and flags fit
    const auto values =
        check(&skytrack_dds_PlotBatch_desc,
              x::half_present_plot_batch(x::HalfPresent::kPlotValues, 64, big).bytes());
    ASSERT_FALSE(values);
    EXPECT_THAT(values.error().message, HasSubstr("#11 at byte 932"));
    EXPECT_THAT(values.error().message, HasSubstr("1088 elements of 8 bytes, needs 8704 bytes"));
  }
}

TEST(SampleCheck, RefusesTheTrackBatchOfFinding7bThatShiftsCyclonesRead) {
  for (bool big : {false, true}) {
    const std::vector<std::byte> bytes =
        x::shifted_track_batch(x::kShiftedAssociations, big).bytes();
    ASSERT_EQ(bytes.size(), 1568u);
    const auto result = check(&skytrack_dds_TrackBatch_desc, bytes);
    ASSERT_FALSE(result);
    // tracks (member 5), element 0, mode_probabilities (member 14)
    EXPECT_THAT(result.error().message, HasSubstr("TrackBatch #5[0].#14 at byte"));
    EXPECT_THAT(result.error().message,
                HasSubstr("4 elements of 8 bytes, needs 32 bytes, 16 left"));
  }
}

TEST(SampleCheck, RefusesStringsWithoutTheirNulOrOfLengthZero) {
  // GIVEN a TrackerStatus whose first member, `instance`, is "i" (length 2 at body byte 4)
  TrackerStatusReport report;
  report.instance = "i";
  auto sample = to_dds(report);
  ASSERT_TRUE(sample);
  for (bool big : {false, true}) {
    x::Writer w = x::encode(sample->get(), big);
    ASSERT_EQ(w.lengths().front(), 8u);
    x::Writer zero = w;
    zero.patch(8, 0);
    EXPECT_THAT(message(check(&skytrack_dds_TrackerStatus_desc, zero.bytes())),
                HasSubstr("#1 at byte 4 of"));
    std::vector<std::byte> no_nul = w.bytes();
    no_nul[13] = std::byte{'!'};  // the NUL after "i"
    EXPECT_THAT(message(check(&skytrack_dds_TrackerStatus_desc, no_nul)),
                HasSubstr("string not NUL-terminated"));
  }
}

TEST(SampleCheck, RefusesEveryOtherEncapsulation) {
  const std::vector<std::byte> valid = x::encode(to_dds(plot_scan())->get(), false).bytes();
  // XCDR1 (CDR, PL_CDR), plain and parameter-list XCDR2, and nonsense, in both byte orders
  for (unsigned id :
       {0x0000u, 0x0001u, 0x0002u, 0x0003u, 0x0006u, 0x0007u, 0x000au, 0x000bu, 0x0108u, 0x0900u}) {
    std::vector<std::byte> bytes = valid;
    bytes[0] = std::byte{static_cast<std::uint8_t>(id >> 8)};
    bytes[1] = std::byte{static_cast<std::uint8_t>(id)};
    EXPECT_THAT(message(check(&skytrack_dds_PlotBatch_desc, bytes)), HasSubstr("encapsulation"))
        << id;
  }
  // a little-endian body under the big-endian identifier: its DHEADER reads as ~2^30
  std::vector<std::byte> swapped = valid;
  swapped[1] = std::byte{8};
  EXPECT_FALSE(check(&skytrack_dds_PlotBatch_desc, swapped));
  // less than the header; padding longer than the body
  EXPECT_FALSE(check(&skytrack_dds_PlotBatch_desc, {valid.begin(), valid.begin() + 3}));
  std::vector<std::byte> padded(valid.begin(), valid.begin() + 6);
  padded[3] = std::byte{3};
  EXPECT_THAT(message(check(&skytrack_dds_PlotBatch_desc, padded)), HasSubstr("padding"));
}

TEST(SampleCheck, RefusesBooleansAndEnumeratorsOutsideTheirValues) {
  // has_coverage (member 12) of an empty PlotBatch: header 4, DHEADER 4, sensor 4, scan 8,
  // time 8, platform 72, sigma 56, sigma_flags 4, three empty sequences 12 -> byte 172
  std::vector<std::byte> plots = x::encode(to_dds(PlotScan{})->get(), false).bytes();
  ASSERT_EQ(plots[172], std::byte{0});
  plots[172] = std::byte{2};
  EXPECT_THAT(message(check(&skytrack_dds_PlotBatch_desc, plots)),
              HasSubstr("#12 at byte 168 of 200: boolean 2"));
  // status and kind of the only Track: header 4, DHEADER 4, sensor, scan, time 20, two
  // sequence headers 16 (mode_names empty, tracks count 1), Track DHEADER 4, id 8 -> 56, 60
  TrackFrame frame;
  frame.tracks.resize(1);
  frame.tracks[0].status = TrackStatus::kConfirmed;
  const std::vector<std::byte> tracks = x::encode(to_dds(frame)->get(), false).bytes();
  ASSERT_EQ(tracks[56], std::byte{1});
  std::vector<std::byte> status = tracks;
  status[56] = std::byte{4};  // TRACK_DELETED is 3
  EXPECT_THAT(message(check(&skytrack_dds_TrackBatch_desc, status)),
              HasSubstr("#5[0].#2 at byte 52 of 488: enumerator 4, at most 3"));
  std::vector<std::byte> kind = tracks;
  kind[60] = std::byte{3};  // OBJECT_EXTENDED is 2
  EXPECT_THAT(message(check(&skytrack_dds_TrackBatch_desc, kind)),
              HasSubstr("#5[0].#3 at byte 56 of 488: enumerator 3, at most 2"));
}

TEST(SampleCheck, FollowsAppendableTypesAcrossIdlVersions) {
  const std::vector<std::byte> full = x::encode(to_dds(plot_scan())->get(), false).bytes();
  // GIVEN a writer of an older IDL: its PlotBatch ends after sigma_flags (body byte 156)
  std::vector<std::byte> older(full.begin(), full.begin() + 4 + 156);
  x::Writer header(false);
  header.u32(152);
  std::copy(header.bytes().begin() + 4, header.bytes().end(), older.begin() + 4);
  EXPECT_TRUE(check(&skytrack_dds_PlotBatch_desc, older)) << "absent members read as defaults";
  // GIVEN a writer of a newer IDL: 8 more bytes inside the top-level DHEADER
  std::vector<std::byte> newer = full;
  newer.resize(full.size() + 8, std::byte{0x5a});
  x::Writer grown(false);
  grown.u32(static_cast<std::uint32_t>(newer.size() - 8));
  std::copy(grown.bytes().begin() + 4, grown.bytes().end(), newer.begin() + 4);
  EXPECT_TRUE(check(&skytrack_dds_PlotBatch_desc, newer)) << "unknown members are skipped";
  // BUT a member may not straddle the end: the DHEADER ending 2 bytes into plot_ids' count
  std::vector<std::byte> straddling = older;
  straddling.resize(older.size() + 4, std::byte{0});
  x::Writer cut(false);
  cut.u32(154);
  std::copy(cut.bytes().begin() + 4, cut.bytes().end(), straddling.begin() + 4);
  EXPECT_THAT(message(check(&skytrack_dds_PlotBatch_desc, straddling)),
              HasSubstr("#9 at byte 156 of 160: a 4-byte length or header, needs 4 bytes, 2 left"));
}

TEST(SampleCheck, RefusesASequenceWhoseElementsDoNotFillItsDheader) {
  // Cyclone's read ignores a sequence's DHEADER: slack in it would shift every later member.
  TrackFrame frame;
  frame.tracks.resize(1);
  frame.tracks[0].modes = {{"cv", 1.0}};
  x::Writer w = x::encode(to_dds(frame)->get(), false);
  const std::size_t names = w.dheaders()[1];  // after the top-level one
  std::vector<std::byte> bytes = w.bytes();
  bytes[names] = std::byte{static_cast<std::uint8_t>(std::to_integer<unsigned>(bytes[names]) + 4)};
  EXPECT_THAT(message(check(&skytrack_dds_TrackBatch_desc, bytes)),
              HasSubstr("the elements end 4 bytes before the sequence's DHEADER says"));
}

}  // namespace
}  // namespace skytrack::dds
