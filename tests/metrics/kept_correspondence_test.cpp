// CLEAR MOT's kept correspondence in ScenarioEvaluation: two objects crossing, each track
// staying on its own object, are not renumbered when the crossing frame's optimal
// assignment flips between their tracks (the GOSPA-pair count sees two changes per object);
// a real exchange, and a new number after a loss, are.
#include "skytrack/metrics/kept_correspondence.hpp"

#include <gtest/gtest.h>

#include "skytrack/metrics/scenario_evaluation.hpp"

namespace skytrack::metrics {
namespace {

// Objects 1 and 2 on the x axis, 1 moving right from -50 m, 2 left from +50 m, 10 m/s,
// meeting at t = 5 s.
TruthFrame crossing_truth(double t) {
  TruthFrame frame;
  frame.time = t;
  TruthObject a, b;
  a.id = 1;
  a.dims = b.dims = 2;
  a.position = {-50.0 + 10.0 * t, 0.0, 0.0};
  b.id = 2;
  b.position = {50.0 - 10.0 * t, 0.0, 0.0};
  frame.objects = {a, b};
  return frame;
}

TrackReport track(std::int64_t id, double x) {
  TrackReport r;
  r.id = id;
  r.status = TrackStatus::kConfirmed;
  r.dims = 2;
  r.position = {x, 3.0, 0.0};
  return r;
}

// Tracks `first` and `second` on objects 1 and 2, each lagging its object by 6 m: at
// t = 5.5 s (objects at +5 and -5 m) track `first` sits at -1 m, nearer object 2, and
// `second` at +1 m, nearer object 1, so the frame's optimal pairs flip.
TrackFrame lagging_tracks(double t, std::int64_t first, std::int64_t second) {
  TrackFrame frame;
  frame.time = t;
  frame.tracks = {track(first, -50.0 + 10.0 * t - 6.0), track(second, 50.0 - 10.0 * t + 6.0)};
  return frame;
}

EvaluationSummary score(auto tracks_at) {
  ScenarioEvaluation evaluation({10.0, 2.0});  // cut-off 10 m: the lag (6 m) is inside
  for (int k = 0; k <= 20; ++k) {
    const double t = 0.5 * k;
    const TruthFrame truth = crossing_truth(t);
    const TrackFrame tracks = tracks_at(t);
    evaluation.add(truth, &tracks);
  }
  return evaluation.summary();
}

TEST(KeptCorrespondence, TracksStayingOnTheirObjectsThroughACrossingKeepTheirNumbers) {
  const EvaluationSummary s = score([](double t) { return lagging_tracks(t, 11, 12); });
  // The per-frame pairs flip at t = 5.5 s (the lag exceeds half the objects' distance) and
  // flip back once it no longer does: two changes on each object.
  EXPECT_GE(s.id_changes, 2);
  EXPECT_EQ(s.kept_id_changes, 0);
  EXPECT_EQ(s.kept_fragmentations, 0);
}

TEST(KeptCorrespondence, AnExchangeOfObjectsIsTwoChanges) {
  // From t = 7 s on (objects 40 m apart), track 11 follows object 2 and track 12 object 1.
  const EvaluationSummary s = score([](double t) {
    TrackFrame frame = lagging_tracks(t, 11, 12);
    if (t >= 7.0) std::swap(frame.tracks[0].id, frame.tracks[1].id);
    return frame;
  });
  EXPECT_EQ(s.kept_id_changes, 2);
}

TEST(KeptCorrespondence, ANewNumberAfterALossIsOneChangeAndOneFragmentation) {
  // Object 1's track is lost at t = 2 and 2.5 s and comes back as track 13.
  const EvaluationSummary s = score([](double t) {
    TrackFrame frame = lagging_tracks(t, t < 2.0 ? 11 : 13, 12);
    if (t >= 2.0 && t <= 2.5) frame.tracks.erase(frame.tracks.begin());
    return frame;
  });
  EXPECT_EQ(s.kept_id_changes, 1);
  EXPECT_EQ(s.kept_fragmentations, 1);
}

TEST(KeptCorrespondence, AKeptTrackBeyondTheCutoffIsReleased) {
  KeptCorrespondence kept(10.0);
  std::vector<std::optional<std::int64_t>> matched;
  const std::vector<std::int64_t> truths{1}, tracks{5, 6};
  Eigen::MatrixXd d(1, 2);
  d << 1.0, 4.0;
  kept.match(truths, tracks, d, matched);
  ASSERT_TRUE(matched[0]);
  EXPECT_EQ(*matched[0], 5);
  d << 3.0, 2.0;  // track 5 still within the cut-off: kept although 6 is nearer
  kept.match(truths, tracks, d, matched);
  EXPECT_EQ(*matched[0], 5);
  d << 12.0, 2.0;  // beyond it: the nearest other track
  kept.match(truths, tracks, d, matched);
  EXPECT_EQ(*matched[0], 6);
}

}  // namespace
}  // namespace skytrack::metrics
