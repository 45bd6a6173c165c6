// Issue 30, finding 7, end to end on a loopback domain: a peer writes the crafted samples
// (dds_writecdr) between valid ones. skytrackd must count the two PlotBatches as "malformed
// sample" and track every valid scan; `skytrack record` must refuse the TrackBatch (Cyclone's
// read of it asks for 4.27 GB and runs past the sample) and record the rest. Before the
// checker, skytrackd tracked the half-present plot_values batch (with heap memory for values)
// and record died with SIGSEGV.
#include <filesystem>
#include <fstream>
#include <map>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <simdjson.h>

#include "../dds/raw_cdr_writer.hpp"
#include "../dds/xcdr2_samples.hpp"
#include "process_helpers.hpp"
#include "skytrack/daemon/dds_session.hpp"
#include "skytrack/dds/conversion.hpp"
#include "skytrack/io/jsonl_reader.hpp"
#include "support/test_domain.hpp"

namespace skytrack::test {
namespace {

using namespace std::chrono_literals;
using ::testing::HasSubstr;
namespace x = xcdr2;

PlotScan valid_scan(std::uint64_t number) {
  PlotScan scan;
  scan.sensor = 1;
  scan.scan = number;
  scan.time = static_cast<double>(number);
  scan.sigma.range = 20.0;
  scan.sigma.azimuth = 0.002;
  for (int i = 0; i < 3; ++i) {
    Plot p;
    p.id = i;
    p.range = 20000.0 + 5000.0 * i + 150.0 * static_cast<double>(number);
    p.azimuth = 0.5 * i;
    scan.plots.push_back(p);
  }
  return scan;
}

/// scans_processed and scans_rejected from the first line of `skytrack status`.
std::uint64_t scan_counts(const std::string& output,
                          std::map<std::string, std::uint64_t>& rejected) {
  simdjson::dom::parser parser;
  simdjson::dom::element doc;
  std::uint64_t processed = 0;
  if (parser.parse(output.substr(0, output.find('\n'))).get(doc) != simdjson::SUCCESS) return 0;
  if (doc["scans_processed"].get_uint64().get(processed) != simdjson::SUCCESS) return 0;
  simdjson::dom::object counts;
  if (doc["scans_rejected"].get_object().get(counts) == simdjson::SUCCESS) {
    for (auto [k, v] : counts) rejected[std::string(k)] = v.get_uint64().value_unsafe();
  }
  return processed;
}

TEST(CraftedSamples, DaemonAndRecordRefuseThemAndKeepTrackingTheValidOnes) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("skytrack_crafted_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const auto path = [&](const std::string& name) { return (dir / name).string(); };
  daemon::DdsSettings dds;
  const TestDomain lease;
  dds.domain = lease.id();
  std::ofstream(path("skytrackd.yaml"))
      << "skytrackd: {instance: crafted, status_period: 0.2}\n"
      << "dds: {domain: " << dds.domain << ", qos: {status: {deadline: 1.0}}}\n";

  // GIVEN skytrackd, `skytrack record`, and a peer that writes raw bytes on both topics
  Child daemon({SKYTRACKD, "--config", path("skytrackd.yaml")}, path("daemon.log"));
  ASSERT_TRUE(daemon.wait_for_log("running", 10s)) << daemon.log();
  Child record({SKYTRACK_TOOL, "record", "--config", path("skytrackd.yaml"), "--tracks",
                path("tracks.jsonl"), "--until-idle", "1.5"},
               path("record.log"));
  ASSERT_TRUE(record.wait_for_log("matched a TrackBatch writer", 10s)) << record.log();
  auto session = daemon::DdsSession::open(dds);
  ASSERT_TRUE(session) << session.error().message;
  auto plot_topic = session->topic(&skytrack_dds_PlotBatch_desc, dds.topics.plots);
  auto track_topic = session->topic(&skytrack_dds_TrackBatch_desc, dds.topics.tracks);
  ASSERT_TRUE(plot_topic && track_topic);
  auto plots = session->writer(*plot_topic, daemon::plots_writer_qos(dds).get());
  auto tracks = session->writer(*track_topic, daemon::tracks_writer_qos(dds).get());
  ASSERT_TRUE(plots && tracks);
  const RawCdrWriter raw_plots(session->participant(), *plots, &skytrack_dds_PlotBatch_desc,
                               dds::to_dds(valid_scan(0))->data());
  const RawCdrWriter raw_tracks(session->participant(), *tracks, &skytrack_dds_TrackBatch_desc,
                                dds::to_dds(TrackFrame{})->data());
  ASSERT_TRUE(raw_plots.ready() && raw_tracks.ready());
  ASSERT_TRUE(daemon::wait_for_readers(*plots, 1, 10s));   // skytrackd
  ASSERT_TRUE(daemon::wait_for_readers(*tracks, 1, 10s));  // record
  const auto write = [&](std::uint64_t number) {
    return dds_write(*plots, dds::to_dds(valid_scan(number))->data()) == DDS_RETCODE_OK;
  };

  // WHEN each crafted sample of finding 7 is followed by a valid scan of sensor 1
  ASSERT_TRUE(write(1));
  ASSERT_TRUE(raw_plots.write(
      x::half_present_plot_batch(x::HalfPresent::kPlotIds, 1000, false, 1, 1000).bytes()));
  ASSERT_TRUE(write(2));
  ASSERT_TRUE(raw_plots.write(
      x::half_present_plot_batch(x::HalfPresent::kPlotValues, 64, false, 1, 1001).bytes()));
  ASSERT_TRUE(write(3));
  ASSERT_TRUE(raw_tracks.write(x::shifted_track_batch(x::kShiftedAssociations, false).bytes()));
  ASSERT_TRUE(write(4));

  // THEN record refuses the TrackBatch, keeps running and records the four valid scans
  ASSERT_EQ(record.wait(30s), 0) << record.log();
  EXPECT_THAT(record.log(), HasSubstr("malformed sample: skytrack::dds::TrackBatch #5[0].#14"));
  EXPECT_THAT(record.log(), HasSubstr("4 track batches written, 1 samples malformed"));
  std::vector<std::uint64_t> recorded;
  auto reader = io::TrackReader::open(path("tracks.jsonl"));
  ASSERT_TRUE(reader);
  while (auto frame = reader->next()) {
    EXPECT_EQ(frame->sensor, 1u);
    recorded.push_back(frame->scan);
  }
  EXPECT_EQ(recorded, (std::vector<std::uint64_t>{1, 2, 3, 4}));
  // AND skytrackd counts both PlotBatches as malformed samples, naming the sequence at fault,
  // and tracked every valid scan
  ASSERT_EQ(run({SKYTRACK_TOOL, "status", "--config", path("skytrackd.yaml")}, path("status.log")),
            0);
  daemon.signal(SIGTERM);
  ASSERT_EQ(daemon.wait(5s), 0) << daemon.log();
  std::map<std::string, std::uint64_t> rejected;
  EXPECT_EQ(scan_counts(read_file(path("status.log")), rejected), 4u);
  EXPECT_EQ(rejected, (std::map<std::string, std::uint64_t>{{"malformed sample", 2}}));
  EXPECT_THAT(daemon.log(), HasSubstr("malformed sample: skytrack::dds::PlotBatch #9 at byte 156"));
  if (!HasFailure()) std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace skytrack::test
