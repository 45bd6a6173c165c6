#include "skytrack/pipeline/estimator_stages.hpp"

#include <chrono>
#include <string>

#include "skytrack/bernoulli/bernoulli_tracker.hpp"
#include "skytrack/extended/extended_estimator_mode.hpp"
#include "skytrack/group/group_estimator.hpp"
#include "skytrack/tracking/point_tracker.hpp"

namespace skytrack {

Expected<EstimatorStages> EstimatorStages::create(const config::TrackingProfile& profile,
                                                  int dims) {
  std::unique_ptr<Estimator> estimator;
  switch (profile.mode) {
    case config::TrackingMode::kPoint: {
      auto point = PointTracker::create(profile, dims);
      if (!point) return unexpected(point.error());
      estimator = std::make_unique<PointTracker>(std::move(*point));
      break;
    }
    case config::TrackingMode::kBernoulli: {
      auto watch = bernoulli::BernoulliTracker::create(profile);
      if (!watch) return unexpected(watch.error());
      estimator = std::make_unique<bernoulli::BernoulliTracker>(std::move(*watch));
      break;
    }
    case config::TrackingMode::kGroup: {
      auto groups = group::GroupEstimator::create(profile);
      if (!groups) return unexpected(groups.error());
      estimator = std::make_unique<group::GroupEstimator>(std::move(*groups));
      break;
    }
    case config::TrackingMode::kExtended: {
      auto objects = extended::ExtendedMode::create(profile);
      if (!objects) return unexpected(objects.error());
      estimator = std::make_unique<extended::ExtendedMode>(std::move(*objects));
      break;
    }
  }
  return EstimatorStages(Preprocessing(profile, dims), std::move(estimator));
}

void EstimatorStages::process(const PlotScan& look, const LookSources* sources, TrackFrame& frame,
                              ScanReport& report) {
  const auto start = std::chrono::steady_clock::now();
  pre_.prepare(look, sources, report);
  report.predict = std::chrono::duration_cast<std::chrono::microseconds>(
      std::chrono::steady_clock::now() - start);
  estimator_->process(look, pre_, frame, report);
  pre_.finish();
}

}  // namespace skytrack
