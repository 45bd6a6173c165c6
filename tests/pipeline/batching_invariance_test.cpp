// The same plots give the same tracks however the feed batches them: a rotating antenna's
// plots delivered as whole revolutions, as antenna sectors or as blocks of a few plots are
// regrouped into looks by the azimuth swept (pipeline/look_assembler.hpp), so every target
// keeps the same track numbers and the GOSPA hardly moves.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../tracking/tracker_test_support.hpp"
#include "skytrack/config/scenario_loader.hpp"
#include "skytrack/geometry/angles.hpp"
#include "skytrack/pipeline/antenna_sweep.hpp"

namespace skytrack {
namespace {

constexpr int kSeeds = 4;                // seeds 1..4
constexpr int kSectors = 8;              // batches per revolution
constexpr std::size_t kBlock = 4;        // plots per batch
constexpr double kCutoff = 500.0;        // GOSPA c [m]
constexpr double kOrder = 2.0;           // GOSPA p
constexpr double kHoldGate = 1000.0;     // [m] a truth is held by the nearest firm track this close
constexpr double kTimeTolerance = 1e-9;  // [s]

/// The plots of one revolution in time order, each with its own time.
std::vector<Plot> timed_plots(const PlotScan& revolution) {
  std::vector<Plot> plots = revolution.plots;
  for (Plot& p : plots) p.time = plot_time(p, revolution);
  std::stable_sort(plots.begin(), plots.end(),
                   [](const Plot& a, const Plot& b) { return *a.time < *b.time; });
  return plots;
}

/// A batch with `revolution`'s header (platform, sigmas), no coverage, numbered `number` and
/// stamped with its latest plot's time.
PlotScan batch_of(const PlotScan& revolution, std::uint64_t number, std::vector<Plot> plots) {
  PlotScan batch = revolution;
  batch.scan = number;
  batch.coverage.reset();
  batch.plots = std::move(plots);
  batch.time = -INFINITY;
  for (const Plot& p : batch.plots) batch.time = std::max(batch.time, *p.time);
  return batch;
}

/// Each revolution's plots split by body azimuth (clockwise from the nose) into kSectors
/// batches, in sweep order.
std::vector<PlotScan> by_sectors(const std::vector<PlotScan>& revolutions) {
  std::vector<PlotScan> out;
  for (const PlotScan& revolution : revolutions) {
    std::vector<Plot> pending;
    int key = -1;
    for (Plot& plot : timed_plots(revolution)) {
      const double a = wrap_angle_positive(body_azimuth(plot, revolution.platform));
      const int k =
          std::min(kSectors - 1, static_cast<int>(a / (2.0 * std::numbers::pi) * kSectors));
      if (!pending.empty() && k != key) {
        out.push_back(batch_of(revolution, out.size(), std::move(pending)));
        pending.clear();
      }
      key = k;
      pending.push_back(std::move(plot));
    }
    if (!pending.empty()) out.push_back(batch_of(revolution, out.size(), std::move(pending)));
  }
  return out;
}

/// The stream's plots in time order, kBlock to a batch (a batch never holds two plots of one
/// id, nor plots of batches with different headers), as `skytrack rebatch --block` does.
std::vector<PlotScan> by_blocks(const std::vector<PlotScan>& revolutions) {
  std::vector<PlotScan> out;
  std::vector<Plot> pending;
  std::set<std::int64_t> ids;
  const PlotScan* header = nullptr;
  const auto flush = [&] {
    if (pending.empty()) return;
    out.push_back(batch_of(*header, out.size(), std::move(pending)));
    pending.clear();
    ids.clear();
  };
  for (const PlotScan& revolution : revolutions) {
    if (header && (header->platform != revolution.platform || header->sigma != revolution.sigma)) {
      flush();
    }
    header = &revolution;
    for (Plot& plot : timed_plots(revolution)) {
      if (pending.size() >= kBlock || ids.count(plot.id) > 0) flush();
      ids.insert(plot.id);
      pending.push_back(std::move(plot));
    }
  }
  flush();
  return out;
}

/// The firm tracks of the latest frame at or before `time`, moved on by their velocity to it.
std::vector<TrackReport> held_at(const std::vector<TrackFrame>& frames, double time) {
  const auto after =
      std::upper_bound(frames.begin(), frames.end(), time + kTimeTolerance,
                       [](double t, const TrackFrame& frame) { return t < frame.time; });
  std::vector<TrackReport> tracks;
  if (after == frames.begin()) return tracks;
  const TrackFrame& frame = *std::prev(after);
  for (TrackReport track : frame.tracks) {
    if (!is_reported_as_firm(track.status)) continue;
    track.position += track.velocity * (time - frame.time);
    tracks.push_back(std::move(track));
  }
  return tracks;
}

struct DeliveryResult {
  double gospa_mean = 0.0;                              // [m] over the truth frames
  std::map<std::int64_t, std::set<std::int64_t>> held;  // truth id -> track numbers holding it
};

/// Runs `batches` through a fresh Pipeline and scores each truth frame against the latest
/// track frame at or before it.
DeliveryResult deliver(const std::vector<PlotScan>& batches, const std::vector<TruthFrame>& truth) {
  DeliveryResult result;
  auto pipeline = Pipeline::create(testing::test_profile());
  if (!pipeline) {
    ADD_FAILURE() << pipeline.error().message;
    return result;
  }
  std::vector<TrackFrame> frames;
  for (const PlotScan& batch : batches) {
    const ScanResult& r = pipeline->process(batch);
    EXPECT_TRUE(r.accepted) << r.rejection;
    if (r.accepted) frames.push_back(r.frame);
  }
  metrics::ScenarioEvaluation evaluation({kCutoff, kOrder});
  for (const TruthFrame& frame : truth) {
    const std::vector<TrackReport> tracks = held_at(frames, frame.time);
    evaluation.add(frame, tracks);
    for (const TruthObject& object : frame.objects) {
      const TrackReport* nearest = nullptr;
      double best = kHoldGate;
      for (const TrackReport& track : tracks) {
        const double d = (track.position - object.position).norm();
        if (d <= best) {
          best = d;
          nearest = &track;
        }
      }
      if (nearest) result.held[object.id].insert(nearest->id);
    }
  }
  result.gospa_mean = evaluation.summary().gospa_mean;
  return result;
}

struct SeedRun {
  DeliveryResult whole, sectors, blocks;
  std::size_t sector_batches = 0, block_batches = 0, revolutions = 0;
};

/// default.yaml for seeds 1..kSeeds, each delivered three ways (computed once per process).
const std::vector<SeedRun>& runs() {
  static const std::vector<SeedRun> cached = [] {
    std::vector<SeedRun> out;
    auto scenario =
        config::load_scenario(std::string(SKYTRACK_SOURCE_DIR) + "/config/scenarios/default.yaml");
    if (!scenario) {
      ADD_FAILURE() << scenario.error().message;
      return out;
    }
    for (int seed = 1; seed <= kSeeds; ++seed) {
      auto simulator = sim::Simulator::create(*scenario, static_cast<std::uint64_t>(seed));
      if (!simulator) {
        ADD_FAILURE() << simulator.error().message;
        return out;
      }
      std::vector<PlotScan> revolutions;
      std::vector<TruthFrame> truth;
      while (auto batch = simulator->next()) {
        revolutions.push_back(std::move(batch->plots));
        truth.push_back(std::move(batch->truth));
      }
      const std::vector<PlotScan> sectors = by_sectors(revolutions);
      const std::vector<PlotScan> blocks = by_blocks(revolutions);
      out.push_back({deliver(revolutions, truth), deliver(sectors, truth), deliver(blocks, truth),
                     sectors.size(), blocks.size(), revolutions.size()});
    }
    return out;
  }();
  return cached;
}

std::string numbers(const std::set<std::int64_t>& ids) {
  std::string out;
  for (const std::int64_t id : ids) out += (out.empty() ? "" : " ") + std::to_string(id);
  return "{" + out + "}";
}

TEST(BatchingInvariance, EveryTargetIsHeldByTheSameTrackNumbersWhateverTheBatching) {
  // GIVEN default.yaml (rotating 3-D radar, 4 s revolution, clutter) for seeds 1-4
  // WHEN its plots reach the pipeline as whole revolutions, as 8 sectors per revolution and
  // as blocks of 4 plots
  const std::vector<SeedRun>& all = runs();
  ASSERT_EQ(all.size(), static_cast<std::size_t>(kSeeds));
  for (int s = 0; s < kSeeds; ++s) {
    const SeedRun& run = all[static_cast<std::size_t>(s)];
    SCOPED_TRACE("seed " + std::to_string(s + 1));
    // (the deliveries really differ: several batches per revolution)
    EXPECT_GT(run.sector_batches, 4 * run.revolutions);
    EXPECT_GT(run.block_batches, 4 * run.revolutions);
    // THEN each truth target is held by the same set of firm track numbers in all three
    ASSERT_FALSE(run.whole.held.empty());
    for (const auto& [target, tracks] : run.whole.held) {
      const auto sectors = run.sectors.held.find(target);
      const auto blocks = run.blocks.held.find(target);
      EXPECT_EQ(sectors == run.sectors.held.end() ? "{}" : numbers(sectors->second),
                numbers(tracks))
          << "target " << target << ": 8 sectors against whole revolutions";
      EXPECT_EQ(blocks == run.blocks.held.end() ? "{}" : numbers(blocks->second), numbers(tracks))
          << "target " << target << ": 4-plot blocks against whole revolutions";
    }
    EXPECT_EQ(run.sectors.held.size(), run.whole.held.size());
    EXPECT_EQ(run.blocks.held.size(), run.whole.held.size());
  }
}

TEST(BatchingInvariance, GospaOfSectorsAndBlocksStaysWithinAFewPercentOfWholeRevolutions) {
  // GIVEN the same runs, scored at each truth time (the revolution's end) against the latest
  // frame at or before it, tracks moved on by their velocity (c = 500 m, p = 2)
  const std::vector<SeedRun>& all = runs();
  ASSERT_EQ(all.size(), static_cast<std::size_t>(kSeeds));
  double whole = 0.0, sectors = 0.0, blocks = 0.0;
  for (std::size_t s = 0; s < all.size(); ++s) {
    const SeedRun& run = all[s];
    RecordProperty("gospa_seed" + std::to_string(s + 1) + "_whole_sectors_blocks",
                   std::to_string(run.whole.gospa_mean) + " " +
                       std::to_string(run.sectors.gospa_mean) + " " +
                       std::to_string(run.blocks.gospa_mean));
    whole += run.whole.gospa_mean / kSeeds;
    sectors += run.sectors.gospa_mean / kSeeds;
    blocks += run.blocks.gospa_mean / kSeeds;
  }
  ASSERT_GT(whole, 0.0);
  // THEN 8 sectors score within 2 % of whole revolutions, and 4-plot blocks within 4 % (a
  // block of a few plots holds a track's plot until the next batch shows the beam passed its
  // gate, so a few tracks are a look later; measured +3.9 %: 353.4 m and 367.1 m)
  EXPECT_NEAR(sectors / whole, 1.0, 0.02)
      << "mean GOSPA whole " << whole << " m, 8 sectors " << sectors << " m";
  EXPECT_NEAR(blocks / whole, 1.0, 0.04)
      << "mean GOSPA whole " << whole << " m, 4-plot blocks " << blocks << " m";
  RecordProperty("gospa_whole", std::to_string(whole));
  RecordProperty("gospa_sectors", std::to_string(sectors));
  RecordProperty("gospa_blocks", std::to_string(blocks));
}

}  // namespace
}  // namespace skytrack
