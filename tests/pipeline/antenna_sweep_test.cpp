// AntennaSweep: the rotation learnt from the plots' own times and azimuths, and the sweep
// (cumulative angle turned) it places each plot at.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "skytrack/geometry/angles.hpp"
#include "skytrack/pipeline/antenna_sweep.hpp"

namespace skytrack {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kPeriod = 4.0;            // [s] one revolution
constexpr int kPlotsPerRevolution = 40;    // on a jittered grid of azimuths
constexpr double kAzimuthNoise = 0.002;    // [rad] 1 sigma
constexpr double kRateTolerance = 0.01;    // learnt rate within 1 % of 2 pi / T
constexpr std::uint64_t kSeed = 20240611;  // fixed: the same plots every run

/// Synthetic rotating-antenna batches: revolution r's plot k is seen at
/// t = r T + (k + jitter_k) T / N and azimuth sense * 2 pi t / T + noise, so a plot's own time
/// advances with its azimuth. Jitter depends on k only: plot k of every revolution is at
/// the same azimuth (up to noise). Each batch is one revolution, its plots shuffled and the
/// batch stamped at the revolution's end.
class RotatingPlots {
 public:
  RotatingPlots(int sense, std::uint64_t seed) : sense_(sense), rng_(seed) {
    std::uniform_real_distribution<double> jitter(-0.3, 0.3);
    for (int k = 0; k < kPlotsPerRevolution; ++k) jitter_.push_back(jitter(rng_));
  }

  double time_of(int revolution, int k) const {
    return revolution * kPeriod +
           (k + 0.5 + jitter_[static_cast<std::size_t>(k)]) * kPeriod / kPlotsPerRevolution;
  }

  PlotScan revolution(int r, bool with_own_times = true) {
    std::normal_distribution<double> noise(0.0, kAzimuthNoise);
    PlotScan scan;
    scan.sensor = 1;
    scan.scan = static_cast<std::uint64_t>(r);
    scan.time = (r + 1) * kPeriod;
    for (int k = 0; k < kPlotsPerRevolution; ++k) {
      Plot p;
      p.id = k;
      p.range = 20000.0 + 500.0 * k;
      const double t = time_of(r, k);
      p.azimuth = wrap_angle(sense_ * kTwoPi * t / kPeriod + noise(rng_));
      if (with_own_times) p.time = t;
      scan.plots.push_back(p);
    }
    std::shuffle(scan.plots.begin(), scan.plots.end(), rng_);
    return scan;
  }

 private:
  int sense_;
  std::mt19937_64 rng_;
  std::vector<double> jitter_;
};

config::AntennaSpec spec(config::AntennaRotation rotation, std::optional<double> period = {},
                         config::RotationDirection direction = config::RotationDirection::kAuto) {
  config::AntennaSpec s;
  s.rotation = rotation;
  s.period = period;
  s.direction = direction;
  return s;
}

/// Reads revolutions until the rotation is known (at most `max`); returns how many it took.
int learn(AntennaSweep& antenna, RotatingPlots& plots, int max) {
  for (int r = 0; r < max; ++r) {
    if (antenna.read(plots.revolution(r)) == AntennaSweep::Kind::kRotating) return r + 1;
  }
  return max + 1;
}

TEST(AntennaSweep, LearnsAClockwiseRotationFromThePlotsOwnTimes) {
  // GIVEN an automatic antenna and plots whose own time advances clockwise with azimuth
  AntennaSweep antenna(spec(config::AntennaRotation::kAuto));
  EXPECT_EQ(antenna.kind(), AntennaSweep::Kind::kUndecided);
  RotatingPlots plots(+1, kSeed);
  // WHEN a few revolutions are read
  const int read = learn(antenna, plots, 3);
  // THEN it is rotating clockwise at 2 pi / T within 1 %
  ASSERT_LE(read, 3);
  EXPECT_TRUE(antenna.rotating());
  EXPECT_EQ(antenna.sense(), +1);
  EXPECT_NEAR(antenna.rate(), kTwoPi / kPeriod, kRateTolerance * kTwoPi / kPeriod);
  EXPECT_NEAR(antenna.period(), kPeriod, kRateTolerance * kPeriod);
  EXPECT_GT(antenna.samples(), 0u);
}

TEST(AntennaSweep, LearnsACounterclockwiseRotation) {
  // GIVEN plots whose azimuth decreases as their own time advances
  AntennaSweep antenna(spec(config::AntennaRotation::kAuto));
  RotatingPlots plots(-1, kSeed);
  // WHEN read
  ASSERT_LE(learn(antenna, plots, 3), 3);
  // THEN the sense is -1 and the rate (positive) is still 2 pi / T within 1 %
  EXPECT_EQ(antenna.sense(), -1);
  EXPECT_GT(antenna.rate(), 0.0);
  EXPECT_NEAR(antenna.rate(), kTwoPi / kPeriod, kRateTolerance * kTwoPi / kPeriod);
}

TEST(AntennaSweep, PlotsWithoutOwnTimesMakeASnapshotSensor) {
  // GIVEN an automatic antenna
  AntennaSweep antenna(spec(config::AntennaRotation::kAuto));
  RotatingPlots plots(+1, kSeed);
  // WHEN its first batch's plots carry no time of their own
  EXPECT_EQ(antenna.read(plots.revolution(0, /*with_own_times=*/false)),
            AntennaSweep::Kind::kSnapshot);
  // THEN it is a snapshot sensor for good, even if timed plots follow
  for (int r = 1; r < 4; ++r) antenna.read(plots.revolution(r));
  EXPECT_EQ(antenna.kind(), AntennaSweep::Kind::kSnapshot);
  EXPECT_FALSE(antenna.rotating());
}

TEST(AntennaSweep, ASnapshotProfileIsNeverRotating) {
  // GIVEN a profile that says snapshot
  AntennaSweep antenna(spec(config::AntennaRotation::kSnapshot));
  EXPECT_EQ(antenna.kind(), AntennaSweep::Kind::kSnapshot);
  // WHEN plots of a steadily rotating antenna are read
  RotatingPlots plots(+1, kSeed);
  for (int r = 0; r < 4; ++r) antenna.read(plots.revolution(r));
  // THEN it stays a snapshot sensor, and place() gives no sweeps
  EXPECT_EQ(antenna.kind(), AntennaSweep::Kind::kSnapshot);
  std::vector<double> sweeps{1.0};
  antenna.place(plots.revolution(4), 0.0, sweeps);
  EXPECT_TRUE(sweeps.empty());
}

TEST(AntennaSweep, ARotatingProfileWithPeriodAndDirectionRotatesFromTheStart) {
  // GIVEN a profile that gives rotation, period and direction; WHEN nothing is read yet
  const AntennaSweep clockwise(
      spec(config::AntennaRotation::kRotating, 5.0, config::RotationDirection::kClockwise));
  const AntennaSweep counter(
      spec(config::AntennaRotation::kRotating, 10.0, config::RotationDirection::kCounterclockwise));
  // THEN both already rotate at the given period and sense
  EXPECT_EQ(clockwise.kind(), AntennaSweep::Kind::kRotating);
  EXPECT_EQ(clockwise.sense(), +1);
  EXPECT_DOUBLE_EQ(clockwise.period(), 5.0);
  EXPECT_EQ(counter.kind(), AntennaSweep::Kind::kRotating);
  EXPECT_EQ(counter.sense(), -1);
  EXPECT_DOUBLE_EQ(counter.rate(), kTwoPi / 10.0);
}

TEST(AntennaSweep, ARotatingProfileWithoutDirectionStillLearns) {
  // GIVEN rotating with a period but automatic direction: undecided until the plots show it
  AntennaSweep antenna(spec(config::AntennaRotation::kRotating, kPeriod));
  EXPECT_EQ(antenna.kind(), AntennaSweep::Kind::kUndecided);
  RotatingPlots plots(-1, kSeed);
  ASSERT_LE(learn(antenna, plots, 3), 3);
  // THEN the sense is measured and the rate is the profile's period exactly
  EXPECT_EQ(antenna.sense(), -1);
  EXPECT_DOUBLE_EQ(antenna.period(), kPeriod);
}

/// Learns the rotation, then places the next `n` revolutions after looks that reached `base`;
/// returns every placed plot's (time, sweep) in time order.
std::vector<std::pair<double, double>> placed(double base, int n, AntennaSweep& antenna,
                                              RotatingPlots& plots) {
  const int learnt = learn(antenna, plots, 3);
  EXPECT_LE(learnt, 3);
  std::vector<std::pair<double, double>> out;
  std::vector<double> sweeps;
  for (int r = learnt; r < learnt + n; ++r) {
    const PlotScan scan = plots.revolution(r);
    antenna.read(scan);
    antenna.place(scan, base, sweeps);
    EXPECT_EQ(sweeps.size(), scan.plots.size());
    for (std::size_t i = 0; i < sweeps.size(); ++i)
      out.emplace_back(*scan.plots[i].time, sweeps[i]);
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(AntennaSweep, PlacedSweepsIncreaseWithTimeAndARevolutionLaterIsTwoPiFurther) {
  for (const int sense : {+1, -1}) {
    SCOPED_TRACE(sense > 0 ? "clockwise" : "counterclockwise");
    // GIVEN an antenna that has learnt its rotation, its sensor's looks at sweep `base` (a
    // whole number of revolutions, as the snapshot looks before it leave it)
    AntennaSweep antenna(spec(config::AntennaRotation::kAuto));
    RotatingPlots plots(sense, kSeed);
    const double base = 3.0 * kTwoPi;
    // WHEN three revolutions of plots are placed
    const auto p = placed(base, 3, antenna, plots);
    ASSERT_EQ(p.size(), static_cast<std::size_t>(3 * kPlotsPerRevolution));
    // THEN the first plot starts a revolution after `base`
    EXPECT_GE(p.front().second, base + kTwoPi);
    EXPECT_LT(p.front().second, base + 2.0 * kTwoPi);
    // ... the sweeps increase with the plots' times (unwrapped, whatever the sense)
    for (std::size_t i = 1; i < p.size(); ++i) {
      EXPECT_GT(p[i].second, p[i - 1].second) << "plot " << i << " at t = " << p[i].first;
    }
    // ... the same azimuth a revolution later is 2 pi further, within the rate error (and
    // the azimuth noise of the two plots)
    const double tolerance = kRateTolerance * kTwoPi + 2.0 * 4.0 * kAzimuthNoise;
    for (std::size_t i = 0; i + kPlotsPerRevolution < p.size(); ++i) {
      EXPECT_NEAR(p[i + kPlotsPerRevolution].second - p[i].second, kTwoPi, tolerance);
    }
    // ... the latest sweep is the latest plot's, and the sweep goes on at the rate after it
    EXPECT_DOUBLE_EQ(antenna.latest(), p.back().second);
    EXPECT_DOUBLE_EQ(antenna.sweep_at(p.back().first - 1.0), antenna.latest());
    EXPECT_NEAR(antenna.sweep_at(p.back().first + 1.0), antenna.latest() + antenna.rate(), 1e-9);
    // ... and each sweep maps back to its plot's azimuth (time-ordered plots follow the
    // synthetic law sense * 2 pi t / T up to noise)
    for (const auto& [time, sweep] : p) {
      EXPECT_NEAR(wrap_angle(antenna.azimuth_of(sweep) - sense * kTwoPi * time / kPeriod), 0.0,
                  5.0 * kAzimuthNoise);
    }
  }
}

TEST(AntennaSweep, TheFirstPlacedPlotStartsARevolutionAfterAnyBase) {
  for (const int sense : {+1, -1}) {
    SCOPED_TRACE(sense > 0 ? "clockwise" : "counterclockwise");
    for (const double base : {3.0, -1.0, 0.25 * kTwoPi}) {
      // GIVEN an antenna that has learnt its rotation and looks that reached a `base` that is
      // not a whole number of revolutions
      AntennaSweep antenna(spec(config::AntennaRotation::kAuto));
      RotatingPlots plots(sense, kSeed);
      // WHEN the first revolution is placed
      const auto p = placed(base, 1, antenna, plots);
      ASSERT_FALSE(p.empty());
      // THEN its first plot is a revolution (and less than two) after `base` (header: "The
      // first plot placed starts a revolution after `base`"), and still at its azimuth
      EXPECT_GT(p.front().second, base + kTwoPi) << "base " << base;
      EXPECT_LT(p.front().second, base + 2.0 * kTwoPi) << "base " << base;
      EXPECT_NEAR(wrap_angle(antenna.azimuth_of(p.front().second) -
                             sense * kTwoPi * p.front().first / kPeriod),
                  0.0, 5.0 * kAzimuthNoise);
    }
  }
}

TEST(AntennaSweep, SweepOfAnAzimuthIsItsNextPassWithinOneRevolution) {
  for (const auto direction :
       {config::RotationDirection::kClockwise, config::RotationDirection::kCounterclockwise}) {
    // GIVEN a rotating antenna
    const AntennaSweep antenna(spec(config::AntennaRotation::kRotating, kPeriod, direction));
    for (const double after : {-7.0, 0.0, 0.3, 12.9}) {
      for (const double azimuth : {-3.0, -1.0, 0.0, 0.5, 3.1}) {
        // WHEN the sweep of an azimuth after `after` is asked for
        const double s = antenna.sweep_of(azimuth, after);
        // THEN it lies in (after, after + 2 pi] and is that azimuth
        EXPECT_GT(s, after);
        EXPECT_LE(s, after + kTwoPi + 1e-12);
        EXPECT_NEAR(wrap_angle(antenna.azimuth_of(s) - azimuth), 0.0, 1e-9);
      }
    }
  }
}

TEST(AntennaSweep, SectorFromToHoldsTheAzimuthsSweptBetweenThem) {
  for (const auto direction :
       {config::RotationDirection::kClockwise, config::RotationDirection::kCounterclockwise}) {
    SCOPED_TRACE(direction == config::RotationDirection::kClockwise ? "clockwise"
                                                                    : "counterclockwise");
    // GIVEN a rotating antenna and sweeps from..to (less than a revolution, some across +-pi)
    const AntennaSweep antenna(spec(config::AntennaRotation::kRotating, kPeriod, direction));
    for (const double from : {0.2, 2.9, 10.0, -4.0}) {
      for (const double width : {0.5, 2.0, 5.5}) {
        const double to = from + width;
        // WHEN the sector they swept is asked for
        const AzimuthSector sector = antenna.sector(from, to);
        // THEN it contains the azimuth of every sweep between them ...
        for (int i = 1; i < 20; ++i) {
          const double inside = from + width * i / 20.0;
          EXPECT_TRUE(sector.contains(antenna.azimuth_of(inside)))
              << "from " << from << " to " << to << ": sweep " << inside;
        }
        // ... and of none of the rest of the revolution
        for (int i = 1; i < 20; ++i) {
          const double outside = to + (kTwoPi - width) * i / 20.0;
          EXPECT_FALSE(sector.contains(antenna.azimuth_of(outside)))
              << "from " << from << " to " << to << ": sweep " << outside;
        }
      }
    }
  }
}

}  // namespace
}  // namespace skytrack
