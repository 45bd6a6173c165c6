#include "skytrack/metrics/scenario_evaluation.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace skytrack::metrics {
namespace {

// Two targets crossing in 2-D, one of them an extended object.
TruthFrame truth_at(double t) {
  TruthFrame frame;
  frame.time = t;
  TruthObject a;
  a.id = 7;
  a.position = {100.0 * t, 0.0, 0.0};
  a.velocity = {100.0, 0.0, 0.0};
  TruthObject b;
  b.id = 9;
  b.kind = ObjectKind::kExtended;
  b.position = {500.0, 50.0 * t, 0.0};
  b.velocity = {0.0, 50.0, 0.0};
  b.extent = Eigen::Matrix2d{{2500.0, 300.0}, {300.0, 900.0}};
  frame.objects = {a, b};
  return frame;
}

// The truth reported back as confirmed tracks (track id = truth id + 100).
TrackFrame as_tracks(const TruthFrame& truth) {
  TrackFrame frame;
  frame.time = truth.time;
  for (const TruthObject& object : truth.objects) {
    TrackReport track;
    track.id = object.id + 100;
    track.status = TrackStatus::kConfirmed;
    track.kind = object.kind;
    track.dims = object.dims;
    track.position = object.position;
    track.velocity = object.velocity;
    track.extent = object.extent;
    frame.tracks.push_back(track);
  }
  return frame;
}

TEST(ScenarioEvaluation, TruthAgainstItselfScoresZero) {
  ScenarioEvaluation evaluation;
  for (int k = 0; k < 20; ++k) {
    const TruthFrame truth = truth_at(k * 1.0);
    const TrackFrame tracks = as_tracks(truth);
    const ScanRecord& record = evaluation.add(truth, &tracks);
    EXPECT_EQ(record.gospa, 0.0);
    EXPECT_EQ(record.truths, 2);
    EXPECT_EQ(record.tracks, 2);
  }
  const EvaluationSummary s = evaluation.summary();
  EXPECT_EQ(s.scans, 20u);
  EXPECT_EQ(s.gospa_mean, 0.0);
  EXPECT_EQ(s.ospa_mean, 0.0);
  EXPECT_EQ(s.gospa_missed_mean + s.gospa_false_mean, 0.0);
  EXPECT_EQ(s.rmse_position, 0.0);
  EXPECT_EQ(s.rmse_velocity, 0.0);
  EXPECT_EQ(s.matched_pairs, 40u);
  EXPECT_EQ(s.id_changes, 0);
  EXPECT_EQ(s.fragmentations, 0);
  EXPECT_EQ(s.gwd_pairs, 20u);
  EXPECT_NEAR(s.gwd_mean, 0.0, 1e-4);
  ASSERT_EQ(s.continuity.size(), 2u);
  EXPECT_EQ(s.continuity[0].frames_tracked, 20);
}

TEST(ScenarioEvaluation, IgnoresTentativeTracksAndMissingTrackFrames) {
  // GIVEN one frame with only tentative tracks and one with no track frame at all
  ScenarioEvaluation evaluation({50.0, 2.0});
  const TruthFrame truth = truth_at(0.0);
  TrackFrame tracks = as_tracks(truth);
  for (TrackReport& track : tracks.tracks) track.status = TrackStatus::kTentative;
  const ScanRecord first = evaluation.add(truth, &tracks);
  const ScanRecord second = evaluation.add(truth, nullptr);
  // THEN both truths are missed in both, GOSPA = sqrt(c^2/2 * 2) = c
  for (const ScanRecord& r : {first, second}) {
    EXPECT_EQ(r.tracks, 0);
    EXPECT_EQ(r.gospa_missed, 2);
    EXPECT_NEAR(r.gospa, 50.0, 1e-12);
  }
  const EvaluationSummary s = evaluation.summary();
  EXPECT_TRUE(std::isnan(s.rmse_position));
  EXPECT_TRUE(std::isnan(s.gwd_mean));
  EXPECT_EQ(s.gospa_missed_mean, 2.0);
}

TEST(ScenarioEvaluation, OffsetTracksGiveRmseAndIdSwapCountsAsChange) {
  // GIVEN 3-D tracks offset by (3, 4, 1000) in position and (1, 0, 0) in velocity
  ScenarioEvaluation evaluation;
  for (int k = 0; k < 4; ++k) {
    const TruthFrame truth = truth_at(k * 1.0);
    TrackFrame tracks = as_tracks(truth);
    for (TrackReport& track : tracks.tracks) {
      track.dims = 3;
      track.position += Eigen::Vector3d(3.0, 4.0, 1000.0);  // z is ignored against 2-D truth
      track.velocity += Eigen::Vector3d(1.0, 0.0, 0.0);
      if (k >= 2 && track.id == 107) track.id = 200;  // a new number for truth 7
    }
    evaluation.add(truth, &tracks);
  }
  const EvaluationSummary s = evaluation.summary();
  EXPECT_NEAR(s.rmse_position, 5.0, 1e-9);
  EXPECT_NEAR(s.rmse_velocity, 1.0, 1e-9);
  EXPECT_NEAR(s.gospa_mean, std::sqrt(2.0 * 25.0), 1e-9);
  EXPECT_NEAR(s.gospa_localisation_mean, 50.0, 1e-9);
  EXPECT_NEAR(s.gwd_mean, 5.0, 1e-4);  // same shape, centres 5 m apart
  EXPECT_EQ(s.id_changes, 1);
  EXPECT_EQ(s.fragmentations, 0);
}

}  // namespace
}  // namespace skytrack::metrics
