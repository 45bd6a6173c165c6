// take_checked through Cyclone DDS on loopback: valid samples of every type arrive unchanged,
// the test encoder writes exactly Cyclone's bytes, and the crafted samples of issue 30,
// finding 7, put on the topic with dds_writecdr, are reported as malformed while the valid
// sample after them arrives. Also pins the defect itself: Cyclone 0.10.2's own validation
// accepts the crafted samples (skipped where a fixed Cyclone refuses them).
#include "skytrack/dds/checked_take.hpp"

#include <dds/ddsi/ddsi_serdata.h>

#include <unistd.h>

#include <random>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "raw_cdr_writer.hpp"
#include "skytrack/dds/sample_check.hpp"
#include "support/test_domain.hpp"
#include "xcdr2_samples.hpp"

namespace skytrack::dds {
namespace {

namespace x = test::xcdr2;
using ::testing::HasSubstr;

constexpr char kLoopbackXml[] =
    "<General><Interfaces><NetworkInterface name=\"lo\"/></Interfaces>"
    "<AllowMulticast>false</AllowMulticast></General>"
    "<Discovery><ParticipantIndex>auto</ParticipantIndex>"
    "<MaxAutoParticipantIndex>32</MaxAutoParticipantIndex>"
    "<Peers><Peer address=\"127.0.0.1\"/></Peers></Discovery>";

/// A loopback domain (an id leased to this process) with a reliable keep-all writer and
/// reader of one type on a topic named after the process.
class Loopback {
 public:
  explicit Loopback(const dds_topic_descriptor_t* type) {
    const auto id = static_cast<dds_domainid_t>(lease_.id());
    domain_ = dds_create_domain(id, kLoopbackXml);
    participant_ = dds_create_participant(id, nullptr, nullptr);
    const std::string name = "skytrack_checked_take_" + std::to_string(getpid());
    const dds_entity_t topic = dds_create_topic(participant_, type, name.c_str(), nullptr, nullptr);
    dds_qos_t* qos = dds_create_qos();
    dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
    dds_qset_history(qos, DDS_HISTORY_KEEP_ALL, 0);
    reader = dds_create_reader(participant_, topic, qos, nullptr);
    writer = dds_create_writer(participant_, topic, qos, nullptr);
    dds_delete_qos(qos);
  }
  ~Loopback() {
    if (participant_ > 0) dds_delete(participant_);
    if (domain_ > 0) dds_delete(domain_);
  }
  Loopback(const Loopback&) = delete;
  Loopback& operator=(const Loopback&) = delete;
  dds_entity_t participant() const { return participant_; }

  dds_entity_t reader = 0;
  dds_entity_t writer = 0;

 private:
  test::TestDomain lease_;
  dds_entity_t domain_ = 0;
  dds_entity_t participant_ = 0;
};

/// What one take_checked call handed over.
template <class T>
struct Taken {
  std::vector<T> samples;  // converted back to core types
  std::vector<std::string> malformed;
};

template <class Dds, class Core = decltype(*from_dds(std::declval<const Dds&>()))>
Taken<std::decay_t<Core>> take_all(dds_entity_t reader) {
  Taken<std::decay_t<Core>> out;
  OwnedSample<Dds> scratch;
  take_checked(
      reader, scratch,
      [&](const Dds& sample, const dds_sample_info_t&) {
        auto core = from_dds(sample);
        EXPECT_TRUE(core) << core.error().message;
        if (core) out.samples.push_back(std::move(*core));
      },
      [&](const dds_sample_info_t&, const Error& e) { out.malformed.push_back(e.message); });
  return out;
}

PlotScan scan(std::uint64_t number, int plots) {
  PlotScan s;
  s.sensor = 3;
  s.scan = number;
  s.time = static_cast<double>(number);
  s.coverage = AzimuthSector{0.0, 1.0};
  for (int i = 0; i < plots; ++i) {
    Plot p;
    p.id = i;
    p.range = 1000.0 + i;
    p.azimuth = 0.01 * i;
    p.flight_level = i % 2 ? std::optional<double>(300.0) : std::nullopt;
    s.plots.push_back(p);
  }
  return s;
}

TrackFrame frame() {
  TrackFrame f;
  f.sensor = 3;
  f.scan = 9;
  TrackReport t;
  t.id = 5;
  t.dims = 2;
  t.covariance.assign(16, 1.0);
  t.modes = {{"cv", 0.8}, {"ct", 0.2}};
  f.tracks = {t, t};
  f.tracks[1].id = 6;
  f.associations = {{5, 1, 0.9, 8}, {6, 2, 0.4, std::nullopt}};
  f.events = {{TrackEventType::kInitiated, 6, "from plot 2", {}}};
  return f;
}

TrackerStatusReport status() {
  TrackerStatusReport r;
  r.instance = "i";
  r.profile_name = "p";
  r.plots_rejected = {{"clutter", 4}};
  return r;
}

TEST(CheckedTake, ValidSamplesOfEveryTypeArriveUnchanged) {
  Loopback plots(&skytrack_dds_PlotBatch_desc);
  const std::vector<PlotScan> scans = {scan(1, 0), scan(2, 300), scan(3, 7)};
  for (const auto& s : scans) ASSERT_EQ(dds_write(plots.writer, to_dds(s)->data()), 0);
  const auto got_plots = take_all<skytrack_dds_PlotBatch>(plots.reader);
  EXPECT_EQ(got_plots.samples, scans);
  EXPECT_TRUE(got_plots.malformed.empty());

  Loopback tracks(&skytrack_dds_TrackBatch_desc);
  ASSERT_EQ(dds_write(tracks.writer, to_dds(frame())->data()), 0);
  const auto got_tracks = take_all<skytrack_dds_TrackBatch>(tracks.reader);
  EXPECT_EQ(got_tracks.samples, std::vector<TrackFrame>{frame()});

  Loopback statuses(&skytrack_dds_TrackerStatus_desc);
  ASSERT_EQ(dds_write(statuses.writer, to_dds(status())->data()), 0);
  const auto got_status = take_all<skytrack_dds_TrackerStatus>(statuses.reader);
  EXPECT_EQ(got_status.samples, std::vector<TrackerStatusReport>{status()});
}

/// The bytes Cyclone serialises `sample` to, taken back from a local reader.
template <class Sample>
std::vector<std::byte> cyclone_bytes(const Loopback& e, const Sample& sample) {
  std::vector<std::byte> out;
  ddsi_serdata* data = nullptr;
  dds_sample_info_t info{};
  if (dds_write(e.writer, sample.data()) != 0 ||
      dds_takecdr(e.reader, &data, 1, &info, DDS_ANY_STATE) != 1) {
    return out;
  }
  out.resize(ddsi_serdata_size(data));
  ddsi_serdata_to_ser(data, 0, out.size(), out.data());
  ddsi_serdata_unref(data);
  return out;
}

TEST(CheckedTake, TheTestEncoderWritesCyclonesBytes) {
  Loopback plots(&skytrack_dds_PlotBatch_desc);
  auto plot_sample = to_dds(scan(4, 20));
  EXPECT_EQ(cyclone_bytes(plots, *plot_sample), x::encode(plot_sample->get(), false).bytes());
  Loopback tracks(&skytrack_dds_TrackBatch_desc);
  auto track_sample = to_dds(frame());
  EXPECT_EQ(cyclone_bytes(tracks, *track_sample), x::encode(track_sample->get(), false).bytes());
  Loopback statuses(&skytrack_dds_TrackerStatus_desc);
  auto status_sample = to_dds(status());
  EXPECT_EQ(cyclone_bytes(statuses, *status_sample),
            x::encode(status_sample->get(), false).bytes());
}

TEST(CheckedTake, CraftedSamplesAreReportedAndTheNextValidOneArrives) {
  // GIVEN a peer that writes raw bytes on the PlotBatch and TrackBatch topics
  Loopback plots(&skytrack_dds_PlotBatch_desc);
  const test::RawCdrWriter raw_plots(plots.participant(), plots.writer,
                                     &skytrack_dds_PlotBatch_desc, to_dds(scan(0, 1))->data());
  ASSERT_TRUE(raw_plots.ready());
  // WHEN it writes both half-present PlotBatches of finding 7(a), then a valid one
  for (auto which : {x::HalfPresent::kPlotIds, x::HalfPresent::kPlotValues}) {
    ASSERT_TRUE(raw_plots.write(x::half_present_plot_batch(which, 100, false).bytes()));
  }
  ASSERT_EQ(dds_write(plots.writer, to_dds(scan(5, 3))->data()), 0);
  // THEN the two are reported as malformed, naming the sequence, and the valid one arrives
  const auto got = take_all<skytrack_dds_PlotBatch>(plots.reader);
  ASSERT_EQ(got.malformed.size(), 2u);
  EXPECT_THAT(got.malformed[0], HasSubstr("PlotBatch #9 "));   // plot_ids
  EXPECT_THAT(got.malformed[1], HasSubstr("PlotBatch #11 "));  // plot_values
  EXPECT_EQ(got.samples, std::vector<PlotScan>{scan(5, 3)});

  // AND the same for the shifting TrackBatch of finding 7(b)
  Loopback tracks(&skytrack_dds_TrackBatch_desc);
  const test::RawCdrWriter raw_tracks(tracks.participant(), tracks.writer,
                                      &skytrack_dds_TrackBatch_desc, to_dds(frame())->data());
  ASSERT_TRUE(raw_tracks.write(x::shifted_track_batch(x::kShiftedAssociations, false).bytes()));
  ASSERT_EQ(dds_write(tracks.writer, to_dds(frame())->data()), 0);
  const auto got_tracks = take_all<skytrack_dds_TrackBatch>(tracks.reader);
  ASSERT_EQ(got_tracks.malformed.size(), 1u);
  EXPECT_THAT(got_tracks.malformed[0], HasSubstr("#5[0].#14"));
  EXPECT_EQ(got_tracks.samples, std::vector<TrackFrame>{frame()});
}

/// Seeded mutations of `base`: a few random bytes, half of them after setting a length or
/// DHEADER to a small random value.
std::vector<std::vector<std::byte>> mutants(const x::Writer& base, std::uint32_t seed, int n) {
  std::mt19937 rng(seed);
  std::vector<std::size_t> fields = base.lengths();
  fields.insert(fields.end(), base.dheaders().begin(), base.dheaders().end());
  std::vector<std::vector<std::byte>> out;
  for (int i = 0; i < n; ++i) {
    x::Writer w = base;
    if (i % 2 == 0) {
      const std::size_t at = fields[rng() % fields.size()];
      w.patch(at, static_cast<std::uint32_t>(rng() % 3 == 0 ? rng() : rng() % 64));
    }
    std::vector<std::byte> bytes = w.bytes();
    for (unsigned k = rng() % 6; k > 0; --k) {
      bytes[4 + rng() % (bytes.size() - 4)] = static_cast<std::byte>(rng());
    }
    out.push_back(std::move(bytes));
  }
  return out;
}

template <class Dds>
int accepted_mutants_read_back(const dds_topic_descriptor_t* type, const x::Writer& base,
                               const void* valid) {
  Loopback e(type);
  const test::RawCdrWriter raw(e.participant(), e.writer, type, valid);
  int accepted = 0;
  for (const auto& bytes : mutants(base, 7, 4000)) {
    if (!check_serialized(*type, bytes)) continue;
    ++accepted;
    // What the checker lets through, Cyclone's validation accepts and reads (an ASan build of
    // this test would flag any read outside the sample).
    ddsi_serdata* data = raw.serdata(bytes);
    EXPECT_NE(data, nullptr) << "the checker accepted what Cyclone refuses";
    if (data == nullptr) continue;
    OwnedSample<Dds> sample;
    EXPECT_TRUE(ddsi_serdata_to_sample(data, sample.data(), nullptr, nullptr));
    ddsi_serdata_unref(data);
  }
  return accepted;
}

TEST(CheckedTake, WhatTheCheckerAcceptsOfMutatedSamplesCycloneAlsoValidatesAndReads) {
  auto plots = to_dds(scan(6, 12));
  EXPECT_GT(accepted_mutants_read_back<skytrack_dds_PlotBatch>(
                &skytrack_dds_PlotBatch_desc, x::encode(plots->get(), false), plots->data()),
            100);
  auto tracks = to_dds(frame());
  EXPECT_GT(accepted_mutants_read_back<skytrack_dds_TrackBatch>(
                &skytrack_dds_TrackBatch_desc, x::encode(tracks->get(), false), tracks->data()),
            100);
  auto statuses = to_dds(status());
  EXPECT_GT(
      accepted_mutants_read_back<skytrack_dds_TrackerStatus>(
          &skytrack_dds_TrackerStatus_desc, x::encode(statuses->get(), false), statuses->data()),
      100);
}

TEST(CycloneDefect, ItsOwnValidationAcceptsTheCraftedSamples) {
  // Why the checker exists: Debian's Cyclone 0.10.2 builds a sample from these bytes, and its
  // read would then over-read (7a) or allocate 4.27 GB and read past the sample (7b).
  Loopback plots(&skytrack_dds_PlotBatch_desc);
  const test::RawCdrWriter raw_plots(plots.participant(), plots.writer,
                                     &skytrack_dds_PlotBatch_desc, to_dds(scan(0, 1))->data());
  Loopback tracks(&skytrack_dds_TrackBatch_desc);
  const test::RawCdrWriter raw_tracks(tracks.participant(), tracks.writer,
                                      &skytrack_dds_TrackBatch_desc, to_dds(frame())->data());
  ASSERT_TRUE(raw_plots.ready() && raw_tracks.ready());
  ddsi_serdata* a =
      raw_plots.serdata(x::half_present_plot_batch(x::HalfPresent::kPlotValues, 64, false).bytes());
  ddsi_serdata* b =
      raw_tracks.serdata(x::shifted_track_batch(x::kShiftedAssociations, false).bytes());
  const bool accepted = a != nullptr && b != nullptr;
  if (a != nullptr) ddsi_serdata_unref(a);
  if (b != nullptr) ddsi_serdata_unref(b);
  if (!accepted) GTEST_SKIP() << "this Cyclone refuses the crafted samples itself";
  EXPECT_TRUE(accepted);
}

}  // namespace
}  // namespace skytrack::dds
