#pragma once
// The prepared plots of the current scan and of the two before it: the current ones update
// the filter, the earlier ones seed the birth proposal (birth_proposal.hpp). Buffers are
// reused, so after the largest scan the heap does not grow.
#include <array>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "skytrack/bernoulli/bernoulli_estimate.hpp"
#include "skytrack/bernoulli/bernoulli_spec.hpp"
#include "skytrack/bernoulli/particle_kernel.hpp"
#include "skytrack/measurement/plot_measurement.hpp"

namespace skytrack::bernoulli {

class PlotHistory {
 public:
  explicit PlotHistory(const BernoulliSpec& spec);

  /// Prepares a scan's plots as the current ones; returns how many were rejected. Used:
  /// 2-D polar plots (range, azimuth about their own platform, heading-relative azimuth
  /// turned into the tracking frame; a range-rate is ignored) and Cartesian plots (x, y; the
  /// polar clutter intensity is divided by the range from `platform`). Rejected: 3-D
  /// tracker models, non-finite values, sigma <= 0.
  int load(std::span<const PlotMeasurement> plots, const Eigen::Vector2d& platform) noexcept;
  int load(const Eigen::Vector2d& platform, std::span<const PolarPlot2d> plots) noexcept;

  std::span<const ScanPlot> current() const noexcept { return buffers_[slot(0)]; }
  std::span<const ScanPlot> previous() const noexcept { return buffers_[slot(1)]; }
  std::span<const ScanPlot> before_previous() const noexcept { return buffers_[slot(2)]; }
  double previous_time() const noexcept { return times_[slot(1)]; }
  double before_previous_time() const noexcept { return times_[slot(2)]; }
  int scans_seen() const noexcept { return scans_; }  // scans advanced past, up to 3

  /// The current scan (at `time`) becomes the previous one.
  void advance(double time) noexcept;
  void clear() noexcept;

 private:
  std::size_t slot(int age) const noexcept {
    return (head_ + 3 - static_cast<std::size_t>(age)) % 3;
  }

  BernoulliSpec spec_;
  std::array<std::vector<ScanPlot>, 3> buffers_;
  std::array<double, 3> times_{};
  std::size_t head_ = 0;
  int scans_ = 0;
};

}  // namespace skytrack::bernoulli
