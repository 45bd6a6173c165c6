#pragma once
// A sensor's time of day made continuous across midnight, and the reference that completes
// CAT001 truncated times. A time of day more than half a day below the last one means midnight
// passed; one more than half a day above it is a late record from before midnight.
#include <cmath>
#include <cstdint>
#include <optional>

#include "category_decoders.hpp"

namespace skytrack::asterix::detail {

class SensorClock {
 public:
  explicit SensorClock(std::uint32_t sensor) : sensor_(sensor) {}
  std::uint32_t sensor() const { return sensor_; }

  /// `tod` [0, 86 400) as a continuous time; advances the day at midnight.
  double continued(double tod) {
    if (!started_) {
      started_ = true;
      last_ = tod;
      return day_ + tod;
    }
    const double step = tod - last_;
    if (step < -kSecondsPerDay / 2) {
      day_ += kSecondsPerDay;
    } else if (step > kSecondsPerDay / 2) {
      return day_ - kSecondsPerDay + tod;  // late, from the previous day
    }
    last_ = tod;
    return day_ + tod;
  }

  /// As continued(), without changing the clock.
  double peek(double tod) const {
    if (!started_) return day_ + tod;
    const double step = tod - last_;
    if (step < -kSecondsPerDay / 2) return day_ + kSecondsPerDay + tod;
    if (step > kSecondsPerDay / 2) return day_ - kSecondsPerDay + tod;
    return day_ + tod;
  }

  /// A CAT002 time (continuous) and the reception time it came with, if any.
  void set_reference(double time, std::optional<double> reception) {
    reference_ = time;
    reference_reception_ = reception;
  }

  /// The full time of a truncated time of day (modulo 512 s): the candidate nearest the
  /// latest CAT002 time (moved on by the reception time elapsed since, when known), else the
  /// reception time. nullopt when there is neither.
  std::optional<double> complete(double truncated, std::optional<double> reception_tod) {
    std::optional<double> ref;
    if (reference_) {
      ref = *reference_;
      if (reference_reception_ && reception_tod) {
        double elapsed = *reception_tod - *reference_reception_;
        if (elapsed < -kSecondsPerDay / 2) elapsed += kSecondsPerDay;
        if (elapsed > 0.0 && elapsed < kSecondsPerDay / 2) *ref += elapsed;
      }
    } else if (reception_tod) {
      ref = peek(*reception_tod);
    }
    if (!ref) return std::nullopt;
    const double k = std::round((*ref - truncated) / kTruncatedTimeSpan);
    const double full = truncated + k * kTruncatedTimeSpan;
    continued(std::fmod(std::fmod(full, kSecondsPerDay) + kSecondsPerDay, kSecondsPerDay));
    return full;
  }

 private:
  std::uint32_t sensor_;
  bool started_ = false;
  double last_ = 0.0;
  double day_ = 0.0;
  std::optional<double> reference_;
  std::optional<double> reference_reception_;
};

}  // namespace skytrack::asterix::detail
