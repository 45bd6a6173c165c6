#pragma once
// The estimator of `mode: bernoulli` (estimator.hpp): one multiple-model Bernoulli particle
// filter per sensor (paper 001), each watching for at most one target. Every look reports
// that sensor's target with its existence probability q as `quality`: tentative while q is at
// or below the threshold, confirmed above it (with the model-probability-weighted state and
// the model probabilities), deleted once q falls back. Each rise above the threshold is a new
// target and gets a new number. 2-D.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "skytrack/bernoulli/bernoulli_estimate.hpp"
#include "skytrack/bernoulli/mm_bernoulli_filter.hpp"
#include "skytrack/config/profile.hpp"
#include "skytrack/core/expected.hpp"
#include "skytrack/tracking/estimator.hpp"

namespace skytrack::bernoulli {

class BernoulliTracker final : public Estimator {
 public:
  /// Checks the profile's Bernoulli section (models, particles, probabilities).
  static Expected<BernoulliTracker> create(const config::TrackingProfile& profile);

  void process(const PlotScan& look, Preprocessing& pre, TrackFrame& frame,
               ScanReport& report) override;
  void report_only(const PlotScan& batch, TrackFrame& frame, ScanReport& report) override;
  /// None: a Bernoulli filter may take a plot anywhere (a birth), so a rotating antenna's
  /// looks close on the sweep alone.
  void search_regions(const PlotScan&, double, std::vector<SearchRegion>&) const override {}

 private:
  BernoulliTracker(const config::TrackingProfile& profile, std::vector<std::string> names)
      : profile_(profile), model_names_(std::move(names)) {}

  struct Watch {  // one sensor's filter and what it last reported
    MmBernoulliFilter filter;
    std::uint64_t epoch = 0;  // the filter's report_epoch last seen
    std::int64_t number = 0;  // the current target's track number (0: none yet)
    bool reported = false;    // confirmed in the last look
  };
  Watch& watch_of(std::uint32_t sensor);
  void report(const Watch& watch, const BernoulliEstimate& estimate, TrackStatus status,
              TrackFrame& frame, ScanReport& report) const;

  config::TrackingProfile profile_;
  std::vector<std::string> model_names_;
  std::map<std::uint32_t, Watch> watches_;
  std::int64_t next_number_ = 1;
};

}  // namespace skytrack::bernoulli
