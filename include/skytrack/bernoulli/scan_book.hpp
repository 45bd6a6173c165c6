#pragma once
// What both Bernoulli filters (MMBPF and its IMMBPF baseline) keep from scan to scan: the
// last estimate and its time, which scans may follow, and the report epoch.
#include <cmath>

#include "skytrack/bernoulli/bernoulli_estimate.hpp"

namespace skytrack::bernoulli {

class ScanBook {
 public:
  explicit ScanBook(int model_count) noexcept { reset(model_count); }

  void reset(int model_count) noexcept {
    last_ = BernoulliEstimate{};
    last_.model_count = model_count;
    started_ = false;
    last_time_ = 0.0;
  }

  /// A scan at `time` may follow: finite and after the last scan's.
  bool follows(double time) const noexcept {
    return std::isfinite(time) && (!started_ || time > last_time_);
  }
  /// The last estimate, marked skipped (a scan that may not follow changes nothing).
  BernoulliEstimate skipped() const noexcept {
    BernoulliEstimate estimate = last_;
    estimate.scan_skipped = true;
    return estimate;
  }
  /// The estimate a scan at `time` updates, started from the last.
  BernoulliEstimate open(double time, int rejected, int used) const noexcept {
    BernoulliEstimate estimate = last_;
    estimate.time = time;
    estimate.scan_skipped = false;
    estimate.plots_rejected = rejected;
    estimate.plots_used = used;
    return estimate;
  }
  /// A scan before this one: its recursion runs over `time - last_time()`; the first scan
  /// only seeds births.
  bool started() const noexcept { return started_; }
  double last_time() const noexcept { return last_time_; }
  /// Takes the updated estimate as the last; each rise above the threshold is a new epoch.
  const BernoulliEstimate& close(BernoulliEstimate estimate) noexcept {
    if (estimate.target_reported && !last_.target_reported) ++estimate.report_epoch;
    started_ = true;
    last_time_ = estimate.time;
    last_ = estimate;
    return last_;
  }
  const BernoulliEstimate& last() const noexcept { return last_; }

 private:
  BernoulliEstimate last_;
  bool started_ = false;
  double last_time_ = 0.0;
};

}  // namespace skytrack::bernoulli
