#pragma once
// Local track frames for the fusion tests.
#include <cstdint>
#include <initializer_list>
#include <vector>

#include "skytrack/core/track_report.hpp"

namespace skytrack::fusion::testing {

struct Local {
  std::int64_t id;
  double x, y;
  double vx = 100.0, vy = 0.0;
  double sigma = 30.0;  // [m] position
};

inline TrackReport report(const Local& l) {
  TrackReport t;
  t.id = l.id;
  t.status = TrackStatus::kConfirmed;
  t.dims = 2;
  t.position = {l.x, l.y, 0.0};
  t.velocity = {l.vx, l.vy, 0.0};
  t.covariance.assign(16, 0.0);
  const double v[4] = {l.sigma * l.sigma, 25.0, l.sigma * l.sigma, 25.0};
  for (int i = 0; i < 4; ++i) t.covariance[static_cast<std::size_t>(i * 5)] = v[i];
  return t;
}

inline TrackFrame frame(std::uint32_t sensor, double time, std::initializer_list<Local> tracks) {
  TrackFrame f;
  f.sensor = sensor;
  f.time = time;
  for (const Local& l : tracks) f.tracks.push_back(report(l));
  return f;
}

}  // namespace skytrack::fusion::testing
