#pragma once
// Core plots, scans, tracks and frames for the DDS conversion tests.
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "skytrack/core/plot.hpp"
#include "skytrack/core/track_report.hpp"

namespace skytrack::test {

inline MeasurementSigma full_sigma() {
  return {.range = 15.0,
          .azimuth = 0.002,
          .elevation = 0.004,
          .range_rate = 1.0,
          .x = 2.5,
          .y = 3.5,
          .z = 4.5};
}

inline Plot polar_plot(std::int64_t id, bool with_optionals) {
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

inline Plot cartesian_plot(std::int64_t id, std::optional<double> z) {
  Plot plot;
  plot.id = id;
  plot.form = PlotForm::kCartesian;
  plot.x = 1200.0 + static_cast<double>(id);
  plot.y = -340.0;
  plot.z = z;
  return plot;
}

inline PlotScan scan_with(std::vector<Plot> plots) {
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

inline TrackReport track_2d() {
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

inline TrackReport track_3d() {
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

inline TrackReport group_track() {
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

inline TrackFrame frame_with(std::vector<TrackReport> tracks) {
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

}  // namespace skytrack::test
