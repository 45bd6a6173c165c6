#pragma once
// What a look goes through once the pipeline has it: preprocessing (preprocessing.hpp), then
// the estimator the profile's mode selects from the closed set of modes (estimator.hpp).
#include <memory>
#include <vector>

#include "skytrack/config/profile.hpp"
#include "skytrack/core/expected.hpp"
#include "skytrack/core/look.hpp"
#include "skytrack/core/plot.hpp"
#include "skytrack/core/scan_report.hpp"
#include "skytrack/core/track_report.hpp"
#include "skytrack/preprocess/preprocessing.hpp"
#include "skytrack/tracking/estimator.hpp"

namespace skytrack {

class EstimatorStages {
 public:
  /// The stages for `profile` in a `dims`-dimensional tracking frame (2 or 3). Fails with a
  /// message naming what is wrong: a bad model set, or a mode not implemented yet.
  static Expected<EstimatorStages> create(const config::TrackingProfile& profile, int dims);

  /// One look (without `sources`: the batch as it arrived, a snapshot look).
  void process(const PlotScan& look, const LookSources* sources, TrackFrame& frame,
               ScanReport& report);
  void report_only(const PlotScan& batch, TrackFrame& frame, ScanReport& report) {
    estimator_->report_only(batch, frame, report);
  }
  void search_regions(const PlotScan& header, double time, std::vector<SearchRegion>& out) const {
    estimator_->search_regions(header, time, out);
  }

  const Estimator& estimator() const { return *estimator_; }

 private:
  EstimatorStages(Preprocessing pre, std::unique_ptr<Estimator> estimator)
      : pre_(std::move(pre)), estimator_(std::move(estimator)) {}

  Preprocessing pre_;
  std::unique_ptr<Estimator> estimator_;
};

}  // namespace skytrack
