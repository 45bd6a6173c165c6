// `skytrack rebatch` on a small rotating stream (tests/tools/data/rotating.plots.jsonl: two
// revolutions of a 4 s clockwise antenna, 7 and 8 plots timed by their azimuth, listed out of
// time order, one plot without its own time): every plot is kept, only the batches change.
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <numbers>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cli_runner.hpp"

#include "skytrack/geometry/angles.hpp"
#include "skytrack/io/jsonl_reader.hpp"

namespace skytrack {
namespace {

using ::testing::HasSubstr;

using skytrack::testing::RunResult;

RunResult run(const std::string& arguments) {
  return skytrack::testing::run_skytrack(arguments);
}

const std::string kInput =
    std::string(SKYTRACK_SOURCE_DIR) + "/tests/tools/data/rotating.plots.jsonl";
constexpr double kPeriod = 4.0;  // [s] the stream's revolution

std::vector<PlotScan> read_all(const std::string& path) {
  std::vector<PlotScan> out;
  auto reader = io::PlotStreamReader::open(
      path, [](const io::LineError& e) { ADD_FAILURE() << io::to_string(e); });
  if (!reader) {
    ADD_FAILURE() << reader.error().message;
    return out;
  }
  while (auto scan = reader->next()) out.push_back(std::move(*scan));
  return out;
}

/// Every plot as (id, own time or its batch's, range, azimuth), sorted.
using PlotKey = std::tuple<std::int64_t, double, double, double>;
std::multiset<PlotKey> plots_of(const std::vector<PlotScan>& scans) {
  std::multiset<PlotKey> out;
  for (const PlotScan& s : scans) {
    for (const Plot& p : s.plots) out.insert({p.id, plot_time(p, s), p.range, p.azimuth});
  }
  return out;
}

class SkytrackRebatch : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("skytrack_rebatch_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  /// Runs rebatch with `options`; returns the batches it wrote.
  std::vector<PlotScan> rebatch(const std::string& options) {
    const std::string out = (dir_ / "out.plots.jsonl").string();
    const RunResult r = run("rebatch --plots " + kInput + " --out " + out + " " + options);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_THAT(r.output, HasSubstr("2 batches in, 0 lines rejected"));
    return read_all(out);
  }

  /// What every rebatched stream keeps: each plot (id, time, position), the header, a batch
  /// time that is its latest plot's, and no coverage.
  static void expect_same_plots_restamped(const std::vector<PlotScan>& input,
                                          const std::vector<PlotScan>& output) {
    EXPECT_EQ(plots_of(output), plots_of(input));
    for (std::size_t b = 0; b < output.size(); ++b) {
      const PlotScan& batch = output[b];
      SCOPED_TRACE("output batch " + std::to_string(b));
      ASSERT_FALSE(batch.plots.empty());
      double latest = -INFINITY;
      std::set<std::int64_t> ids;
      for (const Plot& p : batch.plots) {
        ASSERT_TRUE(p.time.has_value()) << "plot " << p.id << " lost its own time";
        latest = std::max(latest, *p.time);
        EXPECT_TRUE(ids.insert(p.id).second) << "id " << p.id << " twice in one batch";
      }
      EXPECT_EQ(batch.time, latest);
      EXPECT_FALSE(batch.coverage);
      EXPECT_EQ(batch.sensor, input.front().sensor);
      EXPECT_EQ(batch.platform, input.front().platform);
      EXPECT_EQ(batch.sigma, input.front().sigma);
      if (b > 0) {
        EXPECT_GT(batch.scan, output[b - 1].scan);
        EXPECT_GE(batch.time, output[b - 1].time);
      }
    }
  }

  std::filesystem::path dir_;
};

TEST_F(SkytrackRebatch, FourSectorsKeepEveryPlotInQuarterRevolutionBatches) {
  // GIVEN two revolutions with plots in each quarter of each
  const std::vector<PlotScan> input = read_all(kInput);
  ASSERT_EQ(input.size(), 2u);
  // WHEN rebatched into 4 sectors
  const std::vector<PlotScan> output = rebatch("--sectors 4");
  // THEN every plot is kept with its id and time, each batch stamped with its latest plot's
  expect_same_plots_restamped(input, output);
  // ... a batch per quarter revolution: plots of one quarter (by azimuth clockwise from the
  // nose) and one revolution
  EXPECT_EQ(output.size(), 8u);
  for (const PlotScan& batch : output) {
    std::set<int> quarters;
    double first = INFINITY, last = -INFINITY;
    for (const Plot& p : batch.plots) {
      quarters.insert(static_cast<int>(wrap_angle_positive(p.azimuth) / (0.5 * std::numbers::pi)));
      first = std::min(first, *p.time);
      last = std::max(last, *p.time);
    }
    EXPECT_EQ(quarters.size(), 1u) << "batch " << batch.scan;
    EXPECT_EQ(std::floor(first / kPeriod), std::floor(std::nextafter(last, 0.0) / kPeriod))
        << "batch " << batch.scan;
  }
}

TEST_F(SkytrackRebatch, BlocksOfTwoKeepEveryPlotInTimeOrder) {
  // GIVEN the same 15 plots
  const std::vector<PlotScan> input = read_all(kInput);
  // WHEN rebatched in blocks of 2
  const std::vector<PlotScan> output = rebatch("--block 2");
  // THEN every plot is kept, each batch stamped with its latest plot's time ...
  expect_same_plots_restamped(input, output);
  // ... 2 plots a batch (the last holds the odd one), in time order across batches
  ASSERT_EQ(output.size(), 8u);
  double previous = -INFINITY;
  for (std::size_t b = 0; b < output.size(); ++b) {
    EXPECT_EQ(output[b].plots.size(), b + 1 < output.size() ? 2u : 1u);
    for (const Plot& p : output[b].plots) {
      EXPECT_GE(*p.time, previous);
      previous = *p.time;
    }
  }
}

TEST_F(SkytrackRebatch, NeitherOrBothOptionsExitTwo) {
  const std::string out = (dir_ / "out.plots.jsonl").string();
  const RunResult neither = run("rebatch --plots " + kInput + " --out " + out);
  EXPECT_EQ(neither.exit_code, 2) << neither.output;
  EXPECT_THAT(neither.output, HasSubstr("give one of --sectors N or --block N"));
  const RunResult both =
      run("rebatch --plots " + kInput + " --out " + out + " --sectors 4 --block 2");
  EXPECT_EQ(both.exit_code, 2) << both.output;
}

}  // namespace
}  // namespace skytrack
