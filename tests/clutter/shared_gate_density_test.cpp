// The plots of one gate share its clutter density (Preprocessing::share_density): a look of
// a few Cartesian plots, as a navigation radar gives, where one plot's 3 x 3 block of map
// cells holds a counted false plot and its neighbour's, 23 m away in the next cell, holds
// none (its density falls to the profile's sparse value, a thousand times lower).
#include <gtest/gtest.h>

#include "skytrack/config/profile.hpp"
#include "skytrack/core/scan_report.hpp"
#include "skytrack/preprocess/preprocessing.hpp"
#include "skytrack/tracking/cluster_associator.hpp"

namespace skytrack {
namespace {

struct Look {
  Preprocessing pre;
  explicit Look(const config::TrackingProfile& profile) : pre(profile, 2) {}
};

config::TrackingProfile harbour_profile() {
  config::TrackingProfile profile;
  profile.dimension = 2;
  profile.association.clutter_map.cartesian_cell = 100.0;
  return profile;
}

PlotScan harbour_look() {
  // 0: a boat's plot at x -307 (cell x -400..-300); 1: a moored boat's at x -284 (cell
  // -300..-200), 23 m away; 2: a false plot at x -450, in plot 0's block only; 3: a plot
  // 400 m off, alone.
  PlotScan scan;
  scan.sensor = 1;
  scan.time = 10.0;
  const double xy[4][2] = {{-307.0, -485.0}, {-284.0, -488.0}, {-450.0, -470.0}, {100.0, -480.0}};
  for (int i = 0; i < 4; ++i) {
    Plot p;
    p.id = i;
    p.form = PlotForm::kCartesian;
    p.x = xy[i][0];
    p.y = xy[i][1];
    p.sigma.x = p.sigma.y = 7.0;
    scan.plots.push_back(p);
  }
  return scan;
}

// Only plot 2 counts as a false plot: 0 and 1 lie in a firm track's gate.
const std::vector<std::uint8_t> kFalsePlots = {0, 0, 1, 0};

TEST(SharedGateDensity, APlotWithoutCountedNeighboursTakesItsGateNeighboursDensity) {
  // GIVEN the look's densities estimated from the clutter map
  Look look(harbour_profile());
  const PlotScan scan = harbour_look();
  ScanReport report;
  look.pre.prepare(scan, nullptr, report);
  ASSERT_EQ(look.pre.plots().size(), 4u);
  look.pre.estimate_density(kFalsePlots);
  const auto density = [&](int j) { return look.pre.density(look.pre.plots()[j], j); };
  const double boat = density(0), moored = density(1), alone = density(3);
  // (the setup: one counted plot in the boat's block, 1 / (300 m)^2; none in the moored's)
  ASSERT_NEAR(boat, 1.0 / 9e4, 1e-9);
  ASSERT_LT(moored, boat / 100.0);
  // WHEN plots 0 and 1 share one track's gate
  const int gate[] = {0, 1};
  look.pre.share_density(gate);
  // THEN both are weighed against the boat's block's density, to the last bit
  EXPECT_EQ(density(1), boat);
  EXPECT_EQ(density(0), boat);
  // AND a plot in no gate keeps its own
  EXPECT_EQ(density(3), alone);
}

TEST(SharedGateDensity, ASharedDensityIsNotPassedOnToAnotherGate) {
  // GIVEN plot 1 given plot 0's density through one gate
  Look look(harbour_profile());
  ScanReport report;
  look.pre.prepare(harbour_look(), nullptr, report);
  look.pre.estimate_density(kFalsePlots);
  const auto density = [&](int j) { return look.pre.density(look.pre.plots()[j], j); };
  const double alone = density(3);
  const int first[] = {0, 1};
  look.pre.share_density(first);
  // WHEN plot 1 also shares a gate with plot 3, neither with an estimate of its own
  const int second[] = {1, 3};
  look.pre.share_density(second);
  // THEN plot 3 keeps the profile's sparse value
  EXPECT_EQ(density(3), alone);
  // AND a new estimate starts the look afresh: plot 1 again without one
  look.pre.estimate_density(kFalsePlots);
  EXPECT_LT(density(1), density(0) / 100.0);
}

TEST(SharedGateDensity, AStatedDensityIsNeverChanged) {
  // GIVEN a profile that states the clutter density
  config::TrackingProfile profile = harbour_profile();
  profile.association.clutter_density = 5e-5;
  Look look(profile);
  ScanReport report;
  look.pre.prepare(harbour_look(), nullptr, report);
  look.pre.estimate_density(kFalsePlots);
  // WHEN every plot shares one gate
  const int gate[] = {0, 1, 2, 3};
  look.pre.share_density(gate);
  // THEN each is weighed against the stated value
  for (int j = 0; j < 4; ++j) EXPECT_DOUBLE_EQ(look.pre.density(look.pre.plots()[j], j), 5e-5);
}

TEST(SharedGateDensity, TheAssociatorSharesEachTracksGate) {
  // GIVEN a confirmed track gating plots 0 and 1 and a tentative one gating plot 3
  const config::TrackingProfile profile = harbour_profile();
  Look look(profile);
  ScanReport report;
  look.pre.prepare(harbour_look(), nullptr, report);
  std::vector<PointTrack> tracks(2);
  tracks[0].life.status = TrackStatus::kConfirmed;
  tracks[1].life.status = TrackStatus::kTentative;
  std::vector<Candidate> candidates(3);
  candidates[0].track = 0, candidates[0].plot = 0;
  candidates[1].track = 0, candidates[1].plot = 1;
  candidates[2].track = 1, candidates[2].plot = 3;
  // WHEN the associator estimates the look's clutter density
  ClusterAssociator associator(profile);
  associator.estimate_clutter_density(look.pre, tracks, candidates);
  // THEN the confirmed track's plots share the density counted round plot 0 (plot 2 only)
  const auto density = [&](int j) { return look.pre.density(look.pre.plots()[j], j); };
  EXPECT_NEAR(density(0), 1.0 / 9e4, 1e-9);
  EXPECT_EQ(density(1), density(0));
  // AND the lone plot, a tentative track's only candidate, keeps the sparse value
  EXPECT_LT(density(3), density(0) / 100.0);
}

}  // namespace
}  // namespace skytrack
