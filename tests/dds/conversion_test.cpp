// Round trips core -> DDS sample -> core for PlotScan, TrackFrame and TrackerStatusReport,
// errors for malformed samples, and one real write/take through Cyclone DDS on loopback.
#include "skytrack/dds/conversion.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/test_domain.hpp"

namespace skytrack::dds {
namespace {

using ::testing::HasSubstr;

MeasurementSigma full_sigma() {
  return {.range = 15.0,
          .azimuth = 0.002,
          .elevation = 0.004,
          .range_rate = 1.0,
          .x = 2.5,
          .y = 3.5,
          .z = 4.5};
}

Plot polar_plot(std::int64_t id, bool with_optionals) {
  Plot plot;
  plot.id = id;
  plot.form = PlotForm::kPolar;
  plot.range = 35120.5 + static_cast<double>(id);
  plot.azimuth = 1.2034;
  if (with_optionals) {
    plot.time = 420.125;
    plot.elevation = -0.21;
    plot.range_rate = -180.2;
    plot.snr_db = 14.2;
    plot.amplitude = 0.75;
    plot.sigma = full_sigma();
  }
  return plot;
}

Plot cartesian_plot(std::int64_t id, std::optional<double> z) {
  Plot plot;
  plot.id = id;
  plot.form = PlotForm::kCartesian;
  plot.x = 1200.0 + static_cast<double>(id);
  plot.y = -340.0;
  plot.z = z;
  return plot;
}

PlotScan scan_with(std::vector<Plot> plots) {
  PlotScan scan;
  scan.sensor = 7;
  scan.scan = 42;
  scan.time = 420.0;
  scan.platform.position = {1.0, 2.0, 8000.0};
  scan.platform.velocity = {220.0, -1.0, 0.5};
  scan.platform.attitude = {0.1, 0.02, -0.03};
  scan.sigma.range = 15.0;
  scan.sigma.azimuth = 0.002;
  scan.coverage = AzimuthSector{-0.5, 0.2};
  scan.plots = std::move(plots);
  return scan;
}

PlotScan round_trip(const PlotScan& scan) {
  auto sample = to_dds(scan);
  EXPECT_TRUE(sample) << sample.error().message;
  auto back = from_dds(sample->get());
  EXPECT_TRUE(back) << back.error().message;
  return back ? *back : PlotScan{};
}

TEST(PlotBatchConversion, PolarPlotsRoundTripWithAndWithoutOptionalValues) {
  // GIVEN one bare polar plot and one with every optional value and a per-plot sigma
  Plot partial = polar_plot(2, false);
  partial.elevation = 0.05;  // AND one with only some optionals
  partial.sigma.azimuth = 0.001;
  const PlotScan scan = scan_with({polar_plot(0, false), polar_plot(1, true), partial});
  EXPECT_EQ(round_trip(scan), scan);  // THEN the round trip is exact
}

TEST(PlotBatchConversion, TransponderAttributesRoundTripWhereSomePlotsCarryThem) {
  // GIVEN secondary-radar plots: one with every attribute, one with a code only, one bare
  Plot full = polar_plot(0, false), code_only = polar_plot(1, false);
  full.mode3a = 02270;
  full.mode_s = 0xFFFFFF;
  full.flight_level = 221.0;
  code_only.mode3a = 0;
  const PlotScan scan = scan_with({full, code_only, polar_plot(2, false)});
  EXPECT_EQ(round_trip(scan), scan);  // THEN the round trip is exact
  // AND a batch without them sends empty sequences
  auto bare = to_dds(scan_with({polar_plot(0, false)}));
  ASSERT_TRUE(bare);
  EXPECT_EQ(bare->get().plot_mode3a._length, 0u);
  EXPECT_EQ(bare->get().plot_flight_level._length, 0u);
}

TEST(PlotBatchConversion, TransponderSequencesOfTheWrongLengthOrRangeAreErrors) {
  Plot plot = polar_plot(0, false);
  plot.mode3a = 01234;
  auto sample = to_dds(scan_with({plot, polar_plot(1, false)}));
  ASSERT_TRUE(sample);
  skytrack_dds_PlotBatch& b = sample->get();
  b.plot_mode3a._buffer[1] = 010000;  // 13 bits
  auto range = from_dds(b);
  ASSERT_FALSE(range);
  EXPECT_THAT(range.error().message, HasSubstr("plot_mode3a[1]: out of range"));
  b.plot_mode3a._buffer[1] = -1;
  b.plot_mode3a._length = 1;
  auto length = from_dds(b);
  ASSERT_FALSE(length);
  EXPECT_THAT(length.error().message, HasSubstr("transponder"));
}

TEST(PlotBatchConversion, CartesianPlotsRoundTripWithAndWithoutZ) {
  Plot with_sigma = cartesian_plot(3, 120.0);
  with_sigma.sigma.x = 2.5;
  with_sigma.sigma.y = 2.5;
  with_sigma.snr_db = 9.0;
  const PlotScan scan =
      scan_with({cartesian_plot(0, std::nullopt), cartesian_plot(1, 80.0), with_sigma});
  EXPECT_EQ(round_trip(scan), scan);
}

TEST(PlotBatchConversion, ScanSigmaPartiallyPresentRoundTrips) {
  PlotScan scan = scan_with({polar_plot(0, false), cartesian_plot(1, std::nullopt)});
  scan.sigma = {};
  scan.sigma.elevation = 0.004;
  scan.sigma.z = 30.0;
  EXPECT_EQ(round_trip(scan), scan);
  scan.sigma = full_sigma();
  EXPECT_EQ(round_trip(scan), scan);
  scan.sigma = {};
  EXPECT_EQ(round_trip(scan), scan);
}

TEST(PlotBatchConversion, EmptyPlotListRoundTrips) {
  const PlotScan scan = scan_with({});
  auto sample = to_dds(scan);
  ASSERT_TRUE(sample);
  EXPECT_EQ(sample->get().plot_ids._length, 0u);
  EXPECT_EQ(sample->get().plot_values._length, 0u);
  EXPECT_EQ(round_trip(scan), scan);
}

TEST(PlotBatchConversion, FlagsAndValuesFollowTheIdlLayout) {
  const PlotScan scan = scan_with({polar_plot(10, false), cartesian_plot(11, 80.0)});
  auto sample = to_dds(scan);
  ASSERT_TRUE(sample);
  const skytrack_dds_PlotBatch& b = sample->get();
  EXPECT_EQ(b.sigma_flags, 0b11u);  // range and azimuth
  EXPECT_EQ(b.plot_ids._buffer[1], 11);
  EXPECT_EQ(b.plot_flags._buffer[0], (1u << kPlotRange) | (1u << kPlotAzimuth));
  EXPECT_EQ(b.plot_flags._buffer[1],
            kPlotFlagCartesian | (1u << kPlotX) | (1u << kPlotY) | (1u << kPlotZ));
  EXPECT_EQ(b.plot_values._buffer[kPlotRange], 35130.5);
  EXPECT_EQ(b.plot_values._buffer[kPlotStride + kPlotZ], 80.0);
  EXPECT_EQ(b.plot_values._buffer[kPlotStride + kPlotRange], 0.0);  // absent -> 0
}

TEST(PlotBatchConversion, ReusedSampleAndScanKeepRoundTripping) {
  // GIVEN a sample and a scan reused for a large, a small and a large batch
  PlotBatchSample sample;
  PlotScan back;
  for (const std::size_t n : {300u, 2u, 500u}) {
    std::vector<Plot> plots;
    for (std::size_t i = 0; i < n; ++i) {
      const auto id = static_cast<std::int64_t>(i);
      plots.push_back(i % 2 ? polar_plot(id, i % 3 == 0) : cartesian_plot(id, 1.0 * i));
    }
    const PlotScan scan = scan_with(std::move(plots));
    ASSERT_TRUE(to_dds(scan, sample));
    ASSERT_TRUE(from_dds(sample.get(), back));
    EXPECT_EQ(back, scan);  // THEN every batch round-trips
  }
}

TEST(PlotBatchConversion, PlotMissingItsFormValuesGetsNaNForThePipelineToReject) {
  auto sample = to_dds(scan_with({polar_plot(0, false), cartesian_plot(1, std::nullopt)}));
  ASSERT_TRUE(sample);
  sample->get().plot_flags._buffer[0] = 0;                   // polar, no range/azimuth
  sample->get().plot_flags._buffer[1] = kPlotFlagCartesian;  // Cartesian, no x/y
  auto back = from_dds(sample->get());
  ASSERT_TRUE(back);
  EXPECT_TRUE(std::isnan(back->plots[0].range) && std::isnan(back->plots[0].azimuth));
  EXPECT_TRUE(std::isnan(back->plots[1].x) && std::isnan(back->plots[1].y));
}

TEST(PlotBatchConversion, WrongSequenceLengthsAreErrorsNamingTheField) {
  auto sample = to_dds(scan_with({polar_plot(0, true), polar_plot(1, false)}));
  ASSERT_TRUE(sample);
  skytrack_dds_PlotBatch& b = sample->get();
  b.plot_values._length -= 1;
  auto values = from_dds(b);
  ASSERT_FALSE(values);
  EXPECT_THAT(values.error().message, HasSubstr("plot_values"));
  b.plot_values._length += 1;
  b.plot_flags._length -= 1;
  auto flags = from_dds(b);
  ASSERT_FALSE(flags);
  EXPECT_THAT(flags.error().message, HasSubstr("plot_flags"));
  b.plot_flags._length += 1;
  EXPECT_TRUE(from_dds(b));
}

TEST(PlotBatchConversion, LengthWithoutBufferIsAnErrorNamingTheField) {
  skytrack_dds_PlotBatch b{};
  b.plot_ids._length = 2;
  auto back = from_dds(b);
  ASSERT_FALSE(back);
  EXPECT_THAT(back.error().message, HasSubstr("plot_ids"));
}

// ---- tracks ---------------------------------------------------------------------------------

TrackReport track_2d() {
  TrackReport t;
  t.id = 12;
  t.status = TrackStatus::kConfirmed;
  t.kind = ObjectKind::kPoint;
  t.dims = 2;
  t.position = {1003.1, 1996.2, 0.0};
  t.velocity = {248.7, 1.2, 0.0};
  for (int i = 0; i < 16; ++i) t.covariance.push_back(i % 5 == 0 ? 100.0 : 0.5 * i);
  t.modes = {{"cv", 0.91}, {"ct_left", 0.06}, {"ct_right", 0.03}};
  t.quality = 0.97;
  return t;
}

TrackReport track_3d() {
  TrackReport t;
  t.id = 13;
  t.status = TrackStatus::kTentative;
  t.kind = ObjectKind::kPoint;
  t.dims = 3;
  t.position = {1.0, 2.0, 8010.0};
  t.velocity = {3.0, 4.0, -5.0};
  for (int i = 0; i < 36; ++i) t.covariance.push_back(1.0 + i);
  t.modes = {{"cv", 0.5}, {"ct_left", 0.25}, {"ct_right", 0.25}};
  return t;
}

TrackReport group_track() {
  TrackReport t;
  t.id = 20;
  t.status = TrackStatus::kCoasting;
  t.kind = ObjectKind::kGroup;
  t.dims = 2;
  t.position = {-500.0, 300.0, 0.0};
  t.velocity = {40.0, -40.0, 0.0};
  Eigen::Matrix2d extent;
  extent << 400.0, 10.0, 10.0, 300.0;
  t.extent = extent;
  t.members = 15;
  return t;  // no covariance, no modes, no quality
}

TrackFrame frame_with(std::vector<TrackReport> tracks) {
  TrackFrame frame;
  frame.sensor = 1;
  frame.scan = 42;
  frame.time = 420.0;
  frame.tracks = std::move(tracks);
  frame.associations = {{12, 3, 0.93, std::nullopt}, {13, 4, 1.0, 41}};
  frame.events = {{TrackEventType::kBranchCreated, 12, "son 2 from plot 5", {}},
                  {TrackEventType::kDeleted, 14, "", {}},
                  {TrackEventType::kInitiated, 13, "UTF-8 d\xC3\xA9tail \xE2\x9C\x93", {}}};
  return frame;
}

TrackFrame round_trip(const TrackFrame& frame) {
  auto sample = to_dds(frame);
  EXPECT_TRUE(sample) << sample.error().message;
  if (!sample) return {};
  auto back = from_dds(sample->get());
  EXPECT_TRUE(back) << back.error().message;
  return back ? *back : TrackFrame{};
}

TEST(TrackBatchConversion, TracksAssociationsAndEventsRoundTrip) {
  TrackReport extended = group_track();
  extended.id = 21;
  extended.kind = ObjectKind::kExtended;
  extended.status = TrackStatus::kDeleted;
  extended.members.reset();
  extended.quality = 0.0;
  const TrackFrame frame = frame_with({track_2d(), track_3d(), group_track(), extended});
  EXPECT_EQ(round_trip(frame), frame);
}

TEST(TrackBatchConversion, FusedTracksKeepTheirSources) {
  TrackReport fused = track_2d();
  fused.sources = {{1, 12}, {2, 7}};
  TrackReport single = group_track();
  single.sources = {{3, 1099511627776}};
  const TrackFrame frame = frame_with({track_3d(), fused, single});
  const TrackFrame back = round_trip(frame);
  EXPECT_EQ(back, frame);
  EXPECT_TRUE(back.tracks[0].sources.empty());
}

TEST(TrackBatchConversion, SourceNamingNoTrackIsRefused) {
  TrackReport fused = track_2d();
  fused.sources = {{1, 12}};
  auto sample = to_dds(frame_with({fused}));
  ASSERT_TRUE(sample);
  sample->get().track_sources._buffer[0].track_index = 5;
  const auto back = from_dds(sample->get());
  ASSERT_FALSE(back);
  EXPECT_THAT(back.error().message,
              HasSubstr("track_sources[0].track_index: 5 is not a track index"));
}

TEST(TrackBatchConversion, ThreeDimensionalTrackWithoutCovarianceRoundTrips) {
  TrackReport t = track_3d();
  t.covariance.clear();
  t.modes.clear();
  const TrackFrame frame = frame_with({t});
  auto sample = to_dds(frame);
  ASSERT_TRUE(sample);
  EXPECT_EQ(sample->get().tracks._buffer[0].covariance_dim, 0);
  EXPECT_EQ(sample->get().mode_names._length, 0u);
  EXPECT_EQ(round_trip(frame), frame);
}

TEST(TrackBatchConversion, EmptyFrameRoundTrips) {
  TrackFrame frame;
  frame.sensor = 3;
  frame.scan = 1;
  frame.time = 0.5;
  EXPECT_EQ(round_trip(frame), frame);
}

TEST(TrackBatchConversion, ModesAreSentOnceAndReorderedToTheBatchOrder) {
  TrackReport reordered = track_3d();
  reordered.modes = {{"ct_right", 0.2}, {"cv", 0.7}, {"ct_left", 0.1}};
  auto sample = to_dds(frame_with({track_2d(), reordered}));
  ASSERT_TRUE(sample);
  ASSERT_EQ(sample->get().mode_names._length, 3u);
  EXPECT_STREQ(sample->get().mode_names._buffer[2], "ct_right");
  auto back = from_dds(sample->get());
  ASSERT_TRUE(back);
  const std::vector<std::pair<std::string, double>> expected = {
      {"cv", 0.7}, {"ct_left", 0.1}, {"ct_right", 0.2}};
  EXPECT_EQ(back->tracks[1].modes, expected);
}

TEST(TrackBatchConversion, CoreValuesTheIdlCannotCarryAreErrorsNamingTheField) {
  const auto error_of = [](TrackFrame frame) {
    auto sample = to_dds(frame);
    return sample ? std::string("no error") : sample.error().message;
  };
  TrackReport bad_dims = track_2d();
  bad_dims.dims = 4;
  EXPECT_THAT(error_of(frame_with({bad_dims})), HasSubstr("tracks[0].dims"));
  TrackReport bad_cov = track_3d();
  bad_cov.covariance.resize(16);  // a 2-D covariance on a 3-D track
  EXPECT_THAT(error_of(frame_with({track_2d(), bad_cov})), HasSubstr("tracks[1].covariance"));
  TrackReport other_models = track_3d();
  other_models.modes = {{"cv", 0.5}, {"ca", 0.25}, {"ct_right", 0.25}};
  EXPECT_THAT(error_of(frame_with({track_2d(), other_models})), HasSubstr("tracks[1].modes"));
  TrackReport negative = group_track();
  negative.members = -2;
  EXPECT_THAT(error_of(frame_with({negative})), HasSubstr("tracks[0].members"));
  TrackFrame nul = frame_with({});
  nul.events[1].detail = std::string("a\0b", 3);
  EXPECT_THAT(error_of(nul), HasSubstr("events[1].detail"));
}

TEST(TrackBatchConversion, MalformedSamplesAreErrorsNamingTheField) {
  // GIVEN a valid sample, WHEN one field is corrupted, THEN the error names it
  auto sample = to_dds(frame_with({track_2d(), track_3d()}));
  ASSERT_TRUE(sample);
  skytrack_dds_Track& t = sample->get().tracks._buffer[1];
  const auto error_of = [&] {
    auto back = from_dds(sample->get());
    return back ? std::string("no error") : back.error().message;
  };
  t.dims = 5;
  EXPECT_THAT(error_of(), HasSubstr("tracks[1].dims"));
  t.dims = 3;
  t.covariance_dim = 5;
  EXPECT_THAT(error_of(), HasSubstr("tracks[1].covariance_dim"));
  t.covariance_dim = 4;  // a 4x4 covariance on a 3-D track
  EXPECT_THAT(error_of(), HasSubstr("tracks[1].covariance_dim"));
  t.covariance_dim = 6;
  t.mode_probabilities._length = 2;
  EXPECT_THAT(error_of(), HasSubstr("tracks[1].mode_probabilities"));
  t.mode_probabilities._length = 3;
  const std::uint32_t bad_status = 9;
  std::memcpy(&t.status, &bad_status, sizeof bad_status);
  EXPECT_THAT(error_of(), HasSubstr("tracks[1].status"));
  t.status = skytrack_dds_TRACK_DELETED;
  std::memcpy(&t.kind, &bad_status, sizeof bad_status);
  EXPECT_THAT(error_of(), HasSubstr("tracks[1].kind"));
  t.kind = skytrack_dds_OBJECT_POINT;
  t.members = -3;
  EXPECT_THAT(error_of(), HasSubstr("tracks[1].members"));
  t.members = -1;
  EXPECT_EQ(error_of(), "no error");
}

// ---- status ---------------------------------------------------------------------------------

TrackerStatusReport status_report() {
  return {.instance = "skytrackd-1",
          .profile_name = "airspace_jpda",
          .profile_version = "3.1",
          .uptime = 3600.5,
          .scans_processed = 14400,
          .plots_processed = 1234567,
          .plots_rejected = {{"non_finite_range", 3}, {"no_form", 1}},
          .scans_rejected = {{"time_backwards", 2}},
          .scans_dropped = 5,
          .queue_depth = 2,
          .latency_p50 = 0.004,
          .latency_p99 = 0.020,
          .latency_max = 0.150,
          .tracks_tentative = 7,
          .tracks_confirmed = 31,
          .tracks_coasting = 4,
          .numeric_failures = 9};
}

TEST(TrackerStatusConversion, RoundTrips) {
  for (const TrackerStatusReport& status : {status_report(), TrackerStatusReport{}}) {
    auto sample = to_dds(status);
    ASSERT_TRUE(sample) << sample.error().message;
    auto back = from_dds(sample->get());
    ASSERT_TRUE(back) << back.error().message;
    EXPECT_EQ(*back, status);
  }
}

TEST(TrackerStatusConversion, LengthWithoutBufferIsAnErrorNamingTheField) {
  skytrack_dds_TrackerStatus s{};
  s.scans_rejected._length = 1;
  auto back = from_dds(s);
  ASSERT_FALSE(back);
  EXPECT_THAT(back.error().message, HasSubstr("scans_rejected"));
}

TEST(OwnedSample, MoveTransfersOwnership) {
  auto sample = to_dds(status_report());
  ASSERT_TRUE(sample);
  TrackerStatusSample moved = std::move(*sample);
  EXPECT_EQ(sample->get().instance, nullptr);
  EXPECT_STREQ(moved->instance, "skytrackd-1");
  TrackerStatusSample assigned;
  assigned = std::move(moved);
  EXPECT_STREQ(assigned->instance, "skytrackd-1");
  assigned.reset();
  EXPECT_EQ(assigned->plots_rejected._buffer, nullptr);
}

// ---- through Cyclone DDS --------------------------------------------------------------------

// The loopback configuration of DDS-NOTES.md without the CycloneDDS/Domain wrapper.
constexpr char kLoopbackXml[] =
    "<General><Interfaces><NetworkInterface name=\"lo\"/></Interfaces>"
    "<AllowMulticast>false</AllowMulticast></General>"
    "<Discovery><ParticipantIndex>auto</ParticipantIndex>"
    "<MaxAutoParticipantIndex>32</MaxAutoParticipantIndex>"
    "<Peers><Peer address=\"127.0.0.1\"/></Peers></Discovery>";

/// A domain and participant on loopback, deleted on scope exit (also after a failed ASSERT).
struct LoopbackDomain {
  explicit LoopbackDomain(dds_domainid_t id)
      : domain(dds_create_domain(id, kLoopbackXml)),
        participant(domain > 0 ? dds_create_participant(id, nullptr, nullptr) : domain) {}
  ~LoopbackDomain() {
    if (participant > 0) dds_delete(participant);
    if (domain > 0) dds_delete(domain);
  }
  LoopbackDomain(const LoopbackDomain&) = delete;
  LoopbackDomain& operator=(const LoopbackDomain&) = delete;
  dds_entity_t domain;
  dds_entity_t participant;
};

/// A reliable KEEP_ALL writer and reader on one topic, matched before returning.
struct Endpoints {
  dds_entity_t writer = 0;
  dds_entity_t reader = 0;
  dds_entity_t waitset = 0;
  dds_entity_t readable = 0;
};

Endpoints make_endpoints(dds_entity_t participant, const dds_topic_descriptor_t* desc,
                         const std::string& topic_name) {
  Endpoints e;
  const dds_entity_t topic =
      dds_create_topic(participant, desc, topic_name.c_str(), nullptr, nullptr);
  if (topic < 0) return e;
  dds_qos_t* qos = dds_create_qos();
  dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
  dds_qset_history(qos, DDS_HISTORY_KEEP_ALL, 0);
  e.reader = dds_create_reader(participant, topic, qos, nullptr);
  e.writer = dds_create_writer(participant, topic, qos, nullptr);
  dds_delete_qos(qos);
  e.waitset = dds_create_waitset(participant);
  e.readable = dds_create_readcondition(e.reader, DDS_ANY_STATE);
  dds_waitset_attach(e.waitset, e.readable, e.readable);
  // Wait (bounded) until the writer has matched the reader, so the volatile sample is not lost.
  dds_set_status_mask(e.writer, DDS_PUBLICATION_MATCHED_STATUS);
  dds_waitset_attach(e.waitset, e.writer, e.writer);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  dds_publication_matched_status_t matched{};
  while (dds_get_publication_matched_status(e.writer, &matched) == DDS_RETCODE_OK &&
         matched.current_count == 0 && std::chrono::steady_clock::now() < deadline) {
    dds_waitset_wait(e.waitset, nullptr, 0, DDS_MSECS(100));
  }
  dds_waitset_detach(e.waitset, e.writer);
  if (matched.current_count == 0) e.writer = 0;
  return e;
}

/// Waits up to 5 s for data on the endpoints' reader.
bool wait_readable(const Endpoints& e) {
  dds_attach_t triggered = 0;
  return dds_waitset_wait(e.waitset, &triggered, 1, DDS_SECS(5)) > 0 &&
         triggered == static_cast<dds_attach_t>(e.readable);
}

TEST(DdsLoopback, PlotBatchAndTrackBatchTravelThroughCyclone) {
  // GIVEN a loopback domain whose id and topic names are unique to this process
  const int pid = static_cast<int>(getpid());
  const test::TestDomain lease;
  LoopbackDomain dds(static_cast<dds_domainid_t>(lease.id()));
  ASSERT_GT(dds.domain, 0) << dds_strretcode(dds.domain);
  ASSERT_GT(dds.participant, 0) << dds_strretcode(dds.participant);
  const std::string suffix = "_conversion_test_" + std::to_string(pid);

  // WHEN a converted PlotScan is written and taken as a loan
  const Endpoints plots =
      make_endpoints(dds.participant, &skytrack_dds_PlotBatch_desc, "skytrack_plots" + suffix);
  ASSERT_GT(plots.reader, 0);
  ASSERT_GT(plots.writer, 0) << "writer did not match the reader";
  std::vector<Plot> plot_list;
  for (std::int64_t i = 0; i < 200; ++i) {
    plot_list.push_back(i % 2 ? polar_plot(i, i % 3 == 0) : cartesian_plot(i, 10.0 * i));
  }
  const PlotScan scan = scan_with(std::move(plot_list));
  auto plot_sample = to_dds(scan);
  ASSERT_TRUE(plot_sample);
  ASSERT_EQ(dds_write(plots.writer, plot_sample->data()), DDS_RETCODE_OK);
  ASSERT_TRUE(wait_readable(plots));
  void* loaned[1] = {nullptr};
  dds_sample_info_t info{};
  const dds_return_t taken = dds_take(plots.reader, loaned, &info, 1, 1);
  ASSERT_EQ(taken, 1);
  const bool valid = info.valid_data;
  auto scan_back = from_dds(*static_cast<const skytrack_dds_PlotBatch*>(loaned[0]));
  ASSERT_EQ(dds_return_loan(plots.reader, loaned, taken), DDS_RETCODE_OK);
  // THEN it converts back to the same scan
  ASSERT_TRUE(valid);
  ASSERT_TRUE(scan_back) << scan_back.error().message;
  EXPECT_EQ(*scan_back, scan);

  // WHEN a converted TrackFrame is written and taken into our own sample
  const Endpoints tracks =
      make_endpoints(dds.participant, &skytrack_dds_TrackBatch_desc, "skytrack_tracks" + suffix);
  ASSERT_GT(tracks.reader, 0);
  ASSERT_GT(tracks.writer, 0) << "writer did not match the reader";
  const TrackFrame frame = frame_with({track_2d(), track_3d(), group_track()});
  auto track_sample = to_dds(frame);
  ASSERT_TRUE(track_sample);
  ASSERT_EQ(dds_write(tracks.writer, track_sample->data()), DDS_RETCODE_OK);
  ASSERT_TRUE(wait_readable(tracks));
  TrackBatchSample received;  // Cyclone allocates its contents; the destructor frees them
  void* buffers[1] = {received.data()};
  ASSERT_EQ(dds_take(tracks.reader, buffers, &info, 1, 1), 1);
  ASSERT_TRUE(info.valid_data);
  auto frame_back = from_dds(received.get());
  ASSERT_TRUE(frame_back) << frame_back.error().message;
  EXPECT_EQ(*frame_back, frame);  // THEN it converts back to the same frame
}

}  // namespace
}  // namespace skytrack::dds
