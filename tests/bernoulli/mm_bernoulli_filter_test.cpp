// The MMBPF and the IMMBPF baseline on paper 001's scenario and on edge cases.
#include "skytrack/bernoulli/mm_bernoulli_filter.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "skytrack/bernoulli/imm_bernoulli_filter.hpp"
#include "skytrack/bernoulli/paper001_scenario.hpp"

namespace skytrack::bernoulli {
namespace {

const Eigen::Vector2d kOrigin = Eigen::Vector2d::Zero();

template <class Filter>
std::vector<BernoulliEstimate> run(Filter& filter, const std::vector<Paper001Scan>& scans) {
  std::vector<BernoulliEstimate> out;
  for (const Paper001Scan& scan : scans) {
    out.push_back(filter.step(scan.time, kOrigin, std::span(scan.plots)));
  }
  return out;
}

TEST(MmBernoulliFilter, NoPlotsNoTarget) {
  MmBernoulliFilter filter{BernoulliSpec{}};
  for (int k = 0; k < 10; ++k) {
    const BernoulliEstimate e = filter.step(k, kOrigin, std::span<const PolarPlot2d>{});
    EXPECT_EQ(e.existence, 0.0);
    EXPECT_FALSE(e.target_reported);
  }
}

TEST(MmBernoulliFilter, EmptyScanAfterBirthsGivesTheMissOnlyExistence) {
  // GIVEN plots in scan 0 (they seed births) and none in scan 1
  BernoulliSpec spec;
  MmBernoulliFilter filter(spec);
  const std::vector<PolarPlot2d> plots{{15000.0, 1.0, 5.0, 3e-3}, {9000.0, 2.0, 5.0, 3e-3}};
  filter.step(0.0, kOrigin, std::span(plots));
  const BernoulliEstimate e = filter.step(1.0, kOrigin, std::span<const PolarPlot2d>{});
  // THEN eq. 9, 13: q_pred = p_b, q = p_b (1 - p_d) / (1 - p_b + p_b (1 - p_d))
  const double q_pred = 0.01, miss = 0.02;
  EXPECT_NEAR(e.existence, q_pred * miss / (1.0 - q_pred + q_pred * miss), 1e-15);
  // and the model probabilities stay the birth ones (every model saw the same miss)
  EXPECT_NEAR(e.model_probabilities[0], 0.96, 1e-12);
  EXPECT_NEAR(e.model_probabilities[1], 0.02, 1e-12);
}

TEST(MmBernoulliFilter, TracksThePaperTargetThroughItsTurns) {
  const std::vector<Paper001Scan> scans = simulate_paper001(Paper001Options{.seed = 11});
  MmBernoulliFilter filter{BernoulliSpec{}};
  const std::vector<BernoulliEstimate> out = run(filter, scans);
  int reported = 0;
  for (std::size_t k = 1; k < scans.size(); ++k) {
    reported += out[k].target_reported;
    double mu_sum = 0.0;
    for (int j = 0; j < out[k].model_count; ++j) mu_sum += out[k].model_probabilities[j];
    EXPECT_NEAR(mu_sum, 1.0, 1e-9);
    if (!out[k].target_reported) continue;
    const Eigen::Vector4d e = out[k].mean - scans[k].truth;
    // cross-range sigma is 3 mrad x ~20 km = 60 m; 250 m is a lost track
    EXPECT_LT(std::hypot(e[0], e[2]), 250.0) << "scan " << k;
    EXPECT_LT(std::hypot(e[1], e[3]), 120.0) << "scan " << k;
  }
  EXPECT_GE(reported, 95);
  // the clockwise turn (scans 20-39) is the CT1 model's: on average it leads there
  double ct1 = 0.0, cv = 0.0;
  for (std::size_t k = 25; k < 40; ++k) {
    ct1 += out[k].model_probabilities[1];
    cv += out[k].model_probabilities[0];
  }
  EXPECT_GT(ct1, cv);
}

TEST(MmBernoulliFilter, CvLegPositionVariesLittleOverTheFiltersOwnDraws) {
  // GIVEN runs 1-10 of the paper's scenario, each filtered with 6 filter seeds (same plots)
  constexpr int kRuns = 10, kSeeds = 6;
  double spread = 0.0;  // mean over runs and scans of the position variance over seeds
  int cells = 0;
  for (int r = 1; r <= kRuns; ++r) {
    const std::vector<Paper001Scan> scans =
        simulate_paper001(Paper001Options{.seed = static_cast<std::uint64_t>(r)});
    std::vector<std::vector<BernoulliEstimate>> outs;
    for (int s = 0; s < kSeeds; ++s) {
      MmBernoulliFilter filter{
          BernoulliSpec{.seed = 1000003ULL + static_cast<std::uint64_t>(r + 7919 * s)}};
      outs.push_back(run(filter, scans));
    }
    // WHEN the second CV leg (scans 41-60) is reported by every seed
    for (std::size_t k = 41; k <= 60; ++k) {
      Eigen::Vector2d mean = Eigen::Vector2d::Zero();
      bool all = true;
      for (const auto& out : outs) {
        all = all && out[k].target_reported;
        mean += Eigen::Vector2d(out[k].mean[0], out[k].mean[2]) / static_cast<double>(kSeeds);
      }
      if (!all) continue;
      double variance = 0.0;
      for (const auto& out : outs) {
        variance += (Eigen::Vector2d(out[k].mean[0], out[k].mean[2]) - mean).squaredNorm();
      }
      spread += variance / static_cast<double>(kSeeds - 1);
      ++cells;
    }
  }
  // THEN the CV model's Monte Carlo noise is small: measured 6.1 m^2 with its block
  // resampling, 25.8 m^2 when its 300 particles are resampled whole (docs/bernoulli.md)
  ASSERT_GT(cells, 150);
  EXPECT_LT(spread / static_cast<double>(cells), 15.0);
}

TEST(MmBernoulliFilter, ExistenceRisesAfterBirthAndFallsAfterDeath) {
  Paper001Options options{.first_scan_with_target = 10, .last_scan_with_target = 70, .seed = 3};
  const std::vector<Paper001Scan> scans = simulate_paper001(options);
  MmBernoulliFilter filter{BernoulliSpec{}};
  const std::vector<BernoulliEstimate> out = run(filter, scans);
  for (int k = 0; k < 10; ++k) EXPECT_FALSE(out[k].target_reported) << "scan " << k;
  EXPECT_TRUE(out[13].target_reported);
  EXPECT_LT(out[73].existence, 0.5);
  for (int k = 74; k < 100; ++k) EXPECT_FALSE(out[k].target_reported) << "scan " << k;
  EXPECT_EQ(out[9].report_epoch, 0u);  // one target, one epoch (this seed has no false track)
  EXPECT_EQ(out[13].report_epoch, 1u);
  EXPECT_EQ(out[99].report_epoch, 1u);
}

TEST(MmBernoulliFilter, PlotPairsFindATargetBornInATurnWithoutAVelocityPrior) {
  Paper001Options options{.first_scan_with_target = 30, .last_scan_with_target = 90, .seed = 5};
  const std::vector<Paper001Scan> scans = simulate_paper001(options);
  BernoulliSpec spec;
  spec.birth_proposal = BirthProposal::kPlotPairs;
  MmBernoulliFilter filter(spec);
  const std::vector<BernoulliEstimate> out = run(filter, scans);
  bool found = false;
  for (int k = 30; k <= 33; ++k) found = found || out[k].target_reported;
  EXPECT_TRUE(found);
  const Eigen::Vector4d e = out[50].mean - scans[50].truth;
  EXPECT_LT(std::hypot(e[0], e[2]), 250.0);
}

TEST(MmBernoulliFilter, ModelsWithoutBirthMassStayOutOfTheEstimate) {
  // GIVEN newborns only in CV: the CT clouds are empty until the Markov chain feeds them
  BernoulliSpec spec;
  spec.birth_model_probabilities = {1.0, 0.0, 0.0};
  const std::vector<Paper001Scan> scans = simulate_paper001(Paper001Options{.seed = 12});
  MmBernoulliFilter filter(spec);
  const std::vector<BernoulliEstimate> out = run(filter, scans);
  for (std::size_t k = 2; k < 60; ++k) {
    ASSERT_TRUE(out[k].mean.allFinite());
    if (!out[k].target_reported) continue;
    const Eigen::Vector4d e = out[k].mean - scans[k].truth;
    EXPECT_LT(std::hypot(e[0], e[2]), 250.0) << "scan " << k;
  }
}

TEST(MmBernoulliFilter, SameSeedSameOutput) {
  const std::vector<Paper001Scan> scans = simulate_paper001(Paper001Options{.seed = 2});
  MmBernoulliFilter a{BernoulliSpec{}}, b{BernoulliSpec{}};
  const auto ra = run(a, scans), rb = run(b, scans);
  for (std::size_t k = 0; k < ra.size(); ++k) {
    EXPECT_EQ(ra[k].existence, rb[k].existence);
    EXPECT_EQ(ra[k].mean, rb[k].mean);
  }
}

TEST(MmBernoulliFilter, OutOfOrderScanSkippedAndBadPlotsCounted) {
  const std::vector<Paper001Scan> scans = simulate_paper001(Paper001Options{.seed = 4});
  MmBernoulliFilter filter{BernoulliSpec{}};
  for (int k = 0; k < 5; ++k) filter.step(scans[k].time, kOrigin, std::span(scans[k].plots));
  const BernoulliEstimate before = filter.last();
  const BernoulliEstimate skipped = filter.step(2.0, kOrigin, std::span(scans[5].plots));
  EXPECT_TRUE(skipped.scan_skipped);
  EXPECT_EQ(skipped.existence, before.existence);
  EXPECT_TRUE(filter.step(NAN, kOrigin, std::span(scans[5].plots)).scan_skipped);
  std::vector<PolarPlot2d> plots = scans[5].plots;
  plots.push_back({NAN, 0.3, 5.0, 3e-3});
  plots.push_back({1000.0, 0.3, -5.0, 3e-3});
  const BernoulliEstimate e = filter.step(scans[5].time, kOrigin, std::span(plots));
  EXPECT_EQ(e.plots_rejected, 2);
  EXPECT_EQ(e.plots_used, static_cast<int>(scans[5].plots.size()));
  EXPECT_TRUE(e.mean.allFinite());
  EXPECT_TRUE(e.target_reported);
}

TEST(MmBernoulliFilter, PlotMeasurementsFromAMovingHeadedPlatformTrackTheSameTarget) {
  // GIVEN a platform flying east at 200 m/s with heading 0.6 rad, plots in its body frame
  const std::vector<Eigen::Vector4d> truth = paper001_truth(40);
  MmBernoulliFilter filter{BernoulliSpec{}};
  NormalSampler noise(8);
  const double heading = 0.6;
  BernoulliEstimate e;
  for (int k = 0; k < 40; ++k) {
    PlatformState platform;
    platform.position = {-5000.0 + 200.0 * k, 2000.0, 0.0};
    platform.velocity = {200.0, 0.0, 0.0};
    platform.attitude = {heading, 0.0, 0.0};
    MeasVec sigma(2);
    sigma << 5.0, 3e-3;
    const MeasurementModel model = MeasurementModel::polar(platform, false, false, 2, sigma);
    const double dx = truth[k][0] - platform.position.x(), dy = truth[k][2] - platform.position.y();
    MeasVec z(2);
    z << std::hypot(dx, dy) + 5.0 * noise.normal(),
        std::atan2(dx, dy) - heading + 3e-3 * noise.normal();
    std::vector<PlotMeasurement> plots{{model, z, static_cast<double>(k)}};
    for (int c = 0; c < 20; ++c) {  // clutter in the body frame
      MeasVec zc(2);
      zc << 25000.0 * noise.uniform(), 3.14159 * noise.uniform();
      plots.push_back({model, zc, static_cast<double>(k)});
    }
    e = filter.step(k, platform.position.head<2>(), std::span<const PlotMeasurement>(plots));
    EXPECT_EQ(e.plots_rejected, 0);
  }
  // THEN the target is held in the tracking frame
  ASSERT_TRUE(e.target_reported);
  const Eigen::Vector4d err = e.mean - truth[39];
  EXPECT_LT(std::hypot(err[0], err[2]), 250.0);
}

TEST(ImmBernoulliFilter, TracksThePaperTarget) {
  const std::vector<Paper001Scan> scans = simulate_paper001(Paper001Options{.seed = 11});
  ImmBernoulliFilter filter(BernoulliSpec{}, 1000);
  const std::vector<BernoulliEstimate> out = run(filter, scans);
  int reported = 0;
  for (std::size_t k = 1; k < scans.size(); ++k) {
    reported += out[k].target_reported;
    if (!out[k].target_reported) continue;
    const Eigen::Vector4d e = out[k].mean - scans[k].truth;
    EXPECT_LT(std::hypot(e[0], e[2]), 250.0) << "scan " << k;
  }
  EXPECT_GE(reported, 95);
}

}  // namespace
}  // namespace skytrack::bernoulli
