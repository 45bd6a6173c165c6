// Several extended objects in clutter with a crossing (see multi_scenario.hpp).
#include "multi_scenario.hpp"

#include <chrono>
#include <cmath>
#include <random>
#include <vector>

#include <fmt/core.h>

#include "paper_scenario.hpp"
#include "skytrack/extended/ellipse_geometry.hpp"
#include "skytrack/extended/extended_tracker.hpp"
#include "skytrack/metrics/gaussian_wasserstein.hpp"

namespace skytrack::extended::experiment {
namespace {

constexpr double kPeriod = 10.0;          // [s]
constexpr double kDuration = 300.0;       // [s]
constexpr double kHalfWidth = 3000.0;     // [m] clutter over [-3, 3] km squared
constexpr double kClutterMean = 20.0;     // clutter plots per scan
constexpr double kPlotsMean = 8.0;        // plots per object per scan
constexpr double kDetection = 0.95;       // probability an object gives plots in a scan
constexpr double kMatchDistance = 200.0;  // [m] a confirmed track "on" an object
constexpr int kSettleScans = 3;           // scans before a track can be confirmed: not scored

struct Mover {
  Eigen::Vector2d start, velocity;
  double major, minor;
};

// A and B cross at the origin at t = 133 s; the others pass them at 600 m or more.
const Mover kMovers[] = {
    {{-2000.0, 0.0}, {15.0, 0.0}, 100.0, 25.0},
    {{0.0, -2000.0}, {0.0, 15.0}, 100.0, 25.0},
    {{2000.0, 2000.0}, {-11.0, -2.0}, 60.0, 20.0},
    {{-1500.0, 1800.0}, {7.0, -7.0}, 170.0, 40.0},
};
constexpr int kObjects = 4;

ObjectTruth truth_at(const Mover& m, double t) {
  const double heading = std::atan2(m.velocity.y(), m.velocity.x());
  return {t, m.start + t * m.velocity, m.velocity, shape_from_axes(m.major, m.minor, heading)};
}

}  // namespace

std::vector<MultiScan> multi_object_scans(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::poisson_distribution<int> object_count(kPlotsMean), clutter_count(kClutterMean);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Eigen::Matrix2d bound = PaperScenario{}.sensor_bound;
  std::vector<MultiScan> scans;
  for (int k = 0; k * kPeriod <= kDuration + 1e-9; ++k) {
    MultiScan& scan = scans.emplace_back();
    scan.time = k * kPeriod;
    for (const Mover& mover : kMovers) {
      scan.truth.push_back(truth_at(mover, scan.time));
      if (unit(rng) < kDetection) {
        sample_object_plots(scan.truth.back(), object_count(rng), bound, NoiseKind::kGaussian, rng,
                            scan.plots);
      }
    }
    const int clutter = clutter_count(rng);
    for (int c = 0; c < clutter; ++c) {
      // Each draw is its own step, last argument first: the order GCC used when the scenes were
      // measured (C++ leaves the evaluation order of arguments unspecified).
      const double uy = unit(rng), ux = unit(rng);
      scan.plots.emplace_back((2.0 * ux - 1.0) * kHalfWidth, (2.0 * uy - 1.0) * kHalfWidth);
    }
  }
  return scans;
}

MultiResult run_multi_object(const ExtendedSpec& spec, const Eigen::Matrix2d& noise, int runs,
                             std::uint64_t seed) {
  MultiResult r;
  long matched = 0, scored = 0, scans = 0, false_total = 0, one_number = 0;
  double gwd = 0.0, gwd2 = 0.0, centre2 = 0.0, changes = 0.0, cost_us = 0.0;
  std::vector<Eigen::Matrix2d> noises;
  for (int run = 0; run < runs; ++run) {
    const std::vector<MultiScan> run_scans =
        multi_object_scans(seed * 7919ULL + static_cast<std::uint64_t>(run));
    ExtendedTracker tracker(spec);
    std::uint64_t number[kObjects] = {};
    int number_changes[kObjects] = {};
    for (int k = 0; k < static_cast<int>(run_scans.size()); ++k) {
      const double t = run_scans[k].time;
      const std::vector<Eigen::Vector2d>& plots = run_scans[k].plots;
      const std::vector<ObjectTruth>& truth = run_scans[k].truth;
      noises.assign(plots.size(), noise);
      const auto start = std::chrono::steady_clock::now();
      tracker.process(t, plots, noises);
      cost_us += std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
                     .count();
      ++scans;
      // Score: greedy nearest confirmed track per object within kMatchDistance.
      std::vector<bool> used(tracker.tracks().size(), false);
      int confirmed = 0;
      for (const ExtendedTrack& track : tracker.tracks()) {
        confirmed += track.status == ExtendedTrackStatus::kConfirmed;
      }
      int on_objects = 0;
      for (int o = 0; o < kObjects; ++o) {
        if (k < kSettleScans) continue;
        ++scored;
        // CLEAR MOT correspondence: the track on it last scan while still near, else the
        // nearest free one.
        int best = -1;
        double best_d = kMatchDistance;
        for (std::size_t i = 0; i < tracker.tracks().size(); ++i) {
          const ExtendedTrack& track = tracker.tracks()[i];
          if (track.id != number[o] || used[i] || track.status != ExtendedTrackStatus::kConfirmed) {
            continue;
          }
          const double d = (track.position() - truth[o].position).norm();
          if (d < best_d) best_d = d, best = static_cast<int>(i);
        }
        const bool kept = best >= 0;
        for (std::size_t i = 0; !kept && i < tracker.tracks().size(); ++i) {
          const ExtendedTrack& track = tracker.tracks()[i];
          if (used[i] || track.status != ExtendedTrackStatus::kConfirmed) continue;
          const double d = (track.position() - truth[o].position).norm();
          if (d < best_d) best_d = d, best = static_cast<int>(i);
        }
        if (best < 0) continue;
        used[best] = true;
        ++on_objects;
        ++matched;
        const ExtendedTrack& track = tracker.tracks()[best];
        if (number[o] != 0 && number[o] != track.id) {
          ++number_changes[o];
        }
        number[o] = track.id;
        const double d2 = metrics::gaussian_wasserstein_squared(truth[o].position, truth[o].extent,
                                                                track.position(), track.extent());
        gwd2 += d2;
        gwd += std::sqrt(d2);
        centre2 += (track.position() - truth[o].position).squaredNorm();
      }
      if (k >= kSettleScans) false_total += confirmed - on_objects;
    }
    for (int o = 0; o < kObjects; ++o) {
      changes += number_changes[o];
      one_number += number_changes[o] == 0 && number[o] != 0;
    }
  }
  r.mean_gwd = matched ? gwd / matched : 0.0;
  r.mean_gwd_squared = matched ? gwd2 / matched : 0.0;
  r.centre_rmse = matched ? std::sqrt(centre2 / matched) : 0.0;
  r.missed = scored ? 1.0 - static_cast<double>(matched) / scored : 0.0;
  r.number_changes = changes / (runs * kObjects);
  r.number_change_count = std::lround(changes);
  r.objects_one_number = static_cast<double>(one_number) / (runs * kObjects);
  r.false_tracks = static_cast<double>(false_total) / std::max(1L, scans - runs * kSettleScans);
  r.scan_cost_us = cost_us / scans;
  return r;
}

void print_multi_table(const Eigen::Matrix2d& bayes_noise, int runs, std::uint64_t seed) {
  fmt::print(
      "Four objects (two crossing at the origin), {} clutter plots per scan, Gaussian "
      "noise N(0, U/4), {} runs\n\n",
      kClutterMean, runs);
  fmt::print(
      "| filter | mean GWD root [m] | mean GWD eq. 50 [m^2] | centre RMSE [m] | missed "
      "| objects with one number | number changes per object | number changes "
      "| false tracks per scan | per scan [us] |\n");
  fmt::print("|---|---|---|---|---|---|---|---|---|---|\n");
  const PaperScenario paper;
  for (FilterSetup filter : paper_filters(paper, bayes_noise)) {
    // Every filter gets the plots' covariance U / 4 as R; SMF-EOT bounds it at 2 sigma = U.
    Eigen::Matrix2d noise = paper.sensor_bound / 4.0;
    filter.spec.smf.bound_sigmas = 2.0;
    const MultiResult r = run_multi_object(filter.spec, noise, runs, seed);
    fmt::print(
        "| {} | {:.2f} | {:.1f} | {:.2f} | {:.3f} | {:.3f} | {:.3f} | {} | {:.3f} | {:.1f} |\n",
        filter.name, r.mean_gwd, r.mean_gwd_squared, r.centre_rmse, r.missed, r.objects_one_number,
        r.number_changes, r.number_change_count, r.false_tracks, r.scan_cost_us);
  }
  fmt::print("\n");
}

}  // namespace skytrack::extended::experiment
