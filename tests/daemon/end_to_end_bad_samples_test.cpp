// skytrackd counts bad plots and samples under their reasons and tracks the good scans as offline.
#include <algorithm>
#include <csignal>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "end_to_end_test_support.hpp"
#include "process_helpers.hpp"
#include "skytrack/daemon/dds_session.hpp"
#include "skytrack/daemon/tsan_suppressions.hpp"
#include "skytrack/dds/conversion.hpp"
#include "skytrack/io/jsonl_reader.hpp"

namespace skytrack::test {
namespace {

using namespace std::chrono_literals;
using ::testing::HasSubstr;

/// Publishes samples straight onto the plot topic, so that values a JSON file cannot carry
/// (NaN, inf) and malformed samples reach the daemon.
class RawPublisher {
 public:
  explicit RawPublisher(int domain) {
    daemon::DdsSettings settings;
    settings.domain = domain;
    auto session = daemon::DdsSession::open(settings);
    if (!session) return;
    session_.emplace(std::move(*session));
    auto topic = session_->topic(&skytrack_dds_PlotBatch_desc, settings.topics.plots);
    if (!topic) return;
    auto writer = session_->writer(*topic, daemon::plots_writer_qos(settings).get());
    if (writer) writer_ = *writer;
  }
  bool ready() { return writer_ > 0 && daemon::wait_for_readers(writer_, 1, 10s); }
  bool write(const PlotScan& scan) {
    auto sample = dds::to_dds(scan);
    return sample && dds_write(writer_, sample->data()) == DDS_RETCODE_OK;
  }
  bool write(dds::PlotBatchSample& sample) {
    return dds_write(writer_, sample.data()) == DDS_RETCODE_OK;
  }

 private:
  std::optional<daemon::DdsSession> session_;
  dds_entity_t writer_ = 0;
};

Plot polar(std::int64_t id, double range) {
  Plot p;
  p.id = id;
  p.range = range;
  p.azimuth = 0.3;
  p.elevation = 0.01;
  return p;
}

TEST_F(EndToEnd, BadSamplesAreCountedAndTheGoodScansTracksAreUnchanged) {
  // GIVEN the default scenario tracked offline, and skytrackd accepting sensor 1 only with at
  // most 1000 plots per scan
  simulate_and_track_offline();
  std::vector<PlotScan> good;
  {
    auto reader = io::PlotStreamReader::open(path("plots.jsonl"));
    ASSERT_TRUE(reader);
    while (auto scan = reader->next()) good.push_back(std::move(*scan));
  }
  ASSERT_GT(good.size(), 30u);
  ASSERT_EQ(good.front().sensor, 1u);
  std::uint64_t good_plots = 0;
  for (const auto& s : good) good_plots += s.plots.size();
  const std::string config = write_config(kProfile, ", sensors: [1], max_plots_per_scan: 1000");
  Child daemon({kDaemon, "--config", config}, path("daemon.log"));
  ASSERT_TRUE(daemon.wait_for_log("running", 10s)) << daemon.log();
  Child record({kTool, "record", "--config", config, "--tracks", path("live.tracks.jsonl"),
                "--until-idle", "1.5"},
               path("record.log"));
  ASSERT_TRUE(record.wait_for_log("matched a TrackBatch writer", 10s)) << record.log();
  RawPublisher publisher(domain_);
  ASSERT_TRUE(publisher.ready());

  // WHEN the good scans go out with bad plots and bad samples mixed in
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < good.size(); ++i) {
    PlotScan scan = good[i];
    if (i == 5) scan.plots.push_back(polar(9001, nan));    // non-finite polar value
    if (i == 7) scan.plots.push_back(polar(9002, -50.0));  // negative range
    if (i == 9) {
      Plot p;
      p.id = 9003;
      p.form = PlotForm::kCartesian;
      p.x = std::numeric_limits<double>::infinity();
      scan.plots.push_back(p);  // non-finite Cartesian value
    }
    if (i == 11) scan.plots.push_back(polar(9004, 5e22));  // range beyond max_range
    ASSERT_TRUE(publisher.write(scan));
    const PlotScan& next = good[std::min(i + 1, good.size() - 1)];
    if (i == 10) {
      ASSERT_TRUE(publisher.write(good[i]));  // duplicate scan
    }
    if (i == 12) {
      ASSERT_TRUE(publisher.write(good[3]));  // out-of-order scan
    }
    if (i == 14) {
      PlotScan other = next;
      other.sensor = 99;  // unknown sensor
      ASSERT_TRUE(publisher.write(other));
    }
    if (i == 16) {
      PlotScan huge = next;
      huge.plots.clear();
      for (int k = 0; k < 1001; ++k) huge.plots.push_back(polar(k, 1000.0 + k));
      ASSERT_TRUE(publisher.write(huge));  // too many plots
    }
    if (i == 18) {
      auto sample = dds::to_dds(next);
      ASSERT_TRUE(sample);
      sample->get().plot_flags._length -= 1;  // malformed sample
      ASSERT_TRUE(publisher.write(*sample));
      sample->get().plot_flags._length += 1;
    }
    if (i == 20) {
      PlotScan when = next;
      when.time = nan;  // non-finite batch time
      ASSERT_TRUE(publisher.write(when));
    }
    if (i == 22) {
      PlotScan where = next;
      where.platform.position.z() = nan;  // non-finite platform state
      ASSERT_TRUE(publisher.write(where));
    }
    if (i == 24) {
      PlotScan back = next;
      back.time = good[i].time - 1.0;  // time goes backwards
      ASSERT_TRUE(publisher.write(back));
    }
    if (i == 26) {
      PlotScan ahead = next;
      ahead.time += 50.0 * 365.25 * 86400.0;  // time jumps forward: the sensor goes on
      ASSERT_TRUE(publisher.write(ahead));
    }
  }
  ASSERT_EQ(record.wait(30s), 0) << record.log();
  ASSERT_EQ(run({kTool, "status", "--config", config}, path("status.log")), 0)
      << read_file(path("status.log"));
  daemon.signal(SIGTERM);
  ASSERT_EQ(daemon.wait(5s), 0) << daemon.log();

  // THEN every bad sample is counted under its reason in TrackerStatus ...
  std::map<std::string, std::uint64_t> plots, scans;
  const auto numbers = status_numbers(read_file(path("status.log")), plots, scans);
  EXPECT_EQ(numbers.at("scans_processed"), static_cast<double>(good.size()));
  EXPECT_EQ(numbers.at("plots_processed"), static_cast<double>(good_plots + 4));
  EXPECT_EQ(numbers.at("scans_dropped"), 0.0);
  const std::map<std::string, std::uint64_t> expected_plots{{"non-finite polar value", 1},
                                                            {"negative range", 1},
                                                            {"non-finite Cartesian value", 1},
                                                            {"range beyond max_range", 1}};
  EXPECT_EQ(plots, expected_plots);
  const std::map<std::string, std::uint64_t> expected_scans{{"duplicate scan", 1},
                                                            {"out-of-order scan", 1},
                                                            {"unknown sensor", 1},
                                                            {"too many plots", 1},
                                                            {"malformed sample", 1},
                                                            {"non-finite batch time", 1},
                                                            {"non-finite platform state", 1},
                                                            {"time goes backwards", 1},
                                                            {"time jumps forward", 1}};
  EXPECT_EQ(scans, expected_scans);
  // ... and the tracks are those of the clean stream
  expect_same_tracks(read_tracks(path("live.tracks.jsonl")),
                     read_tracks(path("offline.tracks.jsonl")));
}

}  // namespace
}  // namespace skytrack::test
