// Small daemon parts: rate-limited logging, status counters, profile reload decisions.
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "skytrack/daemon/daemon.hpp"
#include "skytrack/daemon/rate_limiter.hpp"
#include "skytrack/daemon/status_collector.hpp"

namespace skytrack::daemon {
namespace {

TEST(RateLimiter, OneMessagePerIntervalCountingTheSuppressedEvents) {
  RateLimiter limiter(std::chrono::seconds(1));
  const RateLimiter::Clock::time_point t0{};
  EXPECT_EQ(limiter.allow(t0), 1u);
  EXPECT_FALSE(limiter.allow(t0 + std::chrono::milliseconds(100)));
  EXPECT_FALSE(limiter.allow(t0 + std::chrono::milliseconds(900)));
  EXPECT_EQ(limiter.allow(t0 + std::chrono::milliseconds(1000)), 3u);
  EXPECT_FALSE(limiter.allow(t0 + std::chrono::milliseconds(1500)));
}

TEST(StatusCollector, CountsRejectionsByReasonAndTracksByStatus) {
  StatusCollector status("unit");
  status.set_profile("default", "3");
  status.scan_rejected("duplicate scan");
  status.scan_rejected("duplicate scan");
  status.scan_rejected("unknown sensor");
  status.plots_rejected("negative range", 2);
  status.plots_rejected("clutter", 0);  // nothing to count: no entry
  EXPECT_EQ(status.scan_dropped(), 1u);
  TrackFrame frame;
  frame.tracks.resize(4);
  frame.tracks[0].status = TrackStatus::kConfirmed;
  frame.tracks[1].status = TrackStatus::kConfirmed;
  frame.tracks[2].status = TrackStatus::kCoasting;
  frame.tracks[3].status = TrackStatus::kTentative;
  status.scan_processed(12, 0.002, frame, 3);
  status.scan_processed(0, 0.001, frame, 2);
  const TrackerStatusReport r = status.snapshot(5);
  EXPECT_EQ(r.instance, "unit");
  EXPECT_EQ(r.profile_version, "3");
  EXPECT_EQ(r.scans_processed, 2u);
  EXPECT_EQ(r.plots_processed, 12u);
  EXPECT_EQ(r.numeric_failures, 5u);
  EXPECT_EQ(r.scans_dropped, 1u);
  EXPECT_EQ(r.queue_depth, 5u);
  EXPECT_EQ(r.scans_rejected,
            (std::vector<RejectionCount>{{"duplicate scan", 2}, {"unknown sensor", 1}}));
  EXPECT_EQ(r.plots_rejected, (std::vector<RejectionCount>{{"negative range", 2}}));
  EXPECT_EQ(r.tracks_confirmed, 2u);
  EXPECT_EQ(r.tracks_coasting, 1u);
  EXPECT_EQ(r.tracks_tentative, 1u);
  EXPECT_DOUBLE_EQ(r.latency_max, 0.002);
  EXPECT_GE(r.uptime, 0.0);
}

TEST(ProfileReload, OnlyAnIdentityChangeKeepsTheTracks) {
  config::TrackingProfile before;
  config::TrackingProfile renamed = before;
  renamed.identity.version = "2";
  EXPECT_EQ(restart_reason(before, renamed), "");
  config::TrackingProfile tuned = before;
  tuned.dimension = 3;
  tuned.point.track_life = {};
  tuned.association.gate_probability = 0.99;
  EXPECT_EQ(restart_reason(before, tuned), "dimension, association");
}

TEST(ProfileReload, AnAntennaOrModeTransitionIntervalChangeRestartsTheTracks) {
  // GIVEN a profile whose antenna is described, or whose Markov interval changes
  config::TrackingProfile before;
  config::TrackingProfile antenna = before;
  antenna.antenna.period = 4.8;
  config::TrackingProfile interval = before;
  interval.mode_transition_interval = 10.0;
  // THEN either restarts the tracks (their looks and mode switching depend on them)
  EXPECT_EQ(restart_reason(before, antenna), "antenna");
  EXPECT_EQ(restart_reason(before, interval), "mode_transition_interval");
}

TEST(ProfileReload, EverySectionRestartsTheTracksButIdentityAndInputLimits) {
  using config::TrackingProfile;
  const TrackingProfile before;
  const std::vector<std::pair<const char*, void (*)(TrackingProfile&)>> sections = {
      {"mode", [](TrackingProfile& p) { p.mode = config::TrackingMode::kGroup; }},
      {"dimension", [](TrackingProfile& p) { p.dimension = 2; }},
      {"measurement", [](TrackingProfile& p) { p.measurement.default_sigma.range = 50.0; }},
      {"antenna", [](TrackingProfile& p) { p.antenna.period = 10.0; }},
      {"motion_models", [](TrackingProfile& p) { p.motion_models[0].accel_sigma = 3.0; }},
      {"mode_transition",
       [](TrackingProfile& p) {
         p.mode_transition[0] = {0.8, 0.1, 0.1};
       }},
      {"mode_transition_interval", [](TrackingProfile& p) { p.mode_transition_interval = 2.0; }},
      {"initial_mode_probabilities",
       [](TrackingProfile& p) {
         p.initial_mode_probabilities = {0.6, 0.2, 0.2};
       }},
      {"association", [](TrackingProfile& p) { p.association.k_best = 50; }},
      {"clutter_rejection", [](TrackingProfile& p) { p.clutter_rejection.enabled = true; }},
      {"point.initiation", [](TrackingProfile& p) { p.point.initiation.max_speed = 400.0; }},
      {"point.track_life", [](TrackingProfile& p) { p.point.track_life.confirm_m = 2; }},
      {"point.branching", [](TrackingProfile& p) { p.point.branching.coast_sons = 2; }},
      {"bernoulli", [](TrackingProfile& p) { p.bernoulli.birth_particles = 50; }},
      {"group", [](TrackingProfile& p) { p.group.max_missed = 1; }},
      {"extended", [](TrackingProfile& p) { p.extended.delete_misses = 9; }},
  };
  for (const auto& [name, change] : sections) {
    TrackingProfile after = before;
    change(after);
    EXPECT_EQ(restart_reason(before, after), name);
  }
  // The running pipeline takes new input limits; the tracks go on.
  TrackingProfile limits = before;
  limits.input_limits.max_range = 500e3;
  limits.input_limits.max_time_jump = 60.0;
  EXPECT_EQ(restart_reason(before, limits), "");
}

}  // namespace
}  // namespace skytrack::daemon
