// Converted PlotBatch and TrackBatch samples written and taken through Cyclone DDS on loopback.
#include "skytrack/dds/conversion.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "conversion_test_support.hpp"
#include "support/test_domain.hpp"

namespace skytrack::dds {
namespace {

using test::cartesian_plot;
using test::frame_with;
using test::group_track;
using test::polar_plot;
using test::scan_with;
using test::track_2d;
using test::track_3d;

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
