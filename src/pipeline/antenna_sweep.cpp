#include "skytrack/pipeline/antenna_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "skytrack/geometry/angles.hpp"
#include "skytrack/geometry/frames.hpp"

namespace skytrack {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
// Rates an antenna may turn at: a revolution in 0.1 s to 10 min.
constexpr double kMinRate = kTwoPi / 600.0;
constexpr double kMaxRate = kTwoPi / 0.1;
// The rate is taken once this many consecutive-plot pairs are seen and this share of them
// agree with their median within kAgreeWithin. Pairs of plots seen in one dwell (two
// targets at one azimuth) or across a gap of more than half a revolution give wild rates;
// the median and the agreement test leave them out.
constexpr std::size_t kSamplesNeeded = 16;
constexpr std::size_t kSamplesKept = 63;
constexpr double kAgreeWithin = 0.1;
constexpr double kAgreeShare = 0.6;

double median(std::vector<double> values) {
  const auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  return *mid;
}

}  // namespace

double body_azimuth(const Plot& plot, const PlatformState& platform) {
  if (plot.form == PlotForm::kPolar) return plot.azimuth;
  return enu_to_polar(Eigen::Vector3d(plot.x, plot.y, plot.z.value_or(platform.position.z())),
                      platform)
      .azimuth;
}

AntennaSweep::AntennaSweep(const config::AntennaSpec& spec) : spec_(spec) {
  using config::AntennaRotation;
  using config::RotationDirection;
  if (spec.rotation == AntennaRotation::kSnapshot) kind_ = Kind::kSnapshot;
  // A rotating antenna described in full needs no learning.
  if (spec.rotation == AntennaRotation::kRotating && spec.period &&
      spec.direction != RotationDirection::kAuto) {
    rate_ = kTwoPi / *spec.period;
    sense_ = spec.direction == RotationDirection::kClockwise ? 1 : -1;
    kind_ = Kind::kRotating;
  }
}

double AntennaSweep::period() const {
  return rate_ > 0.0 ? kTwoPi / rate_ : 0.0;
}

void AntennaSweep::learn(const std::vector<Sample>& ordered) {
  std::optional<Sample> previous = last_;
  for (const Sample& s : ordered) {
    if (previous && s.time > previous->time) {
      const double rate = wrap_angle(s.azimuth - previous->azimuth) / (s.time - previous->time);
      if (std::abs(rate) >= kMinRate && std::abs(rate) <= kMaxRate) {
        rates_.push_back(rate);
        ++samples_;
      }
    }
    previous = s;
  }
  if (rates_.size() > kSamplesKept) {
    rates_.erase(rates_.begin(), rates_.end() - static_cast<std::ptrdiff_t>(kSamplesKept));
  }
  if (rates_.size() < kSamplesNeeded) return;
  const double m = median(rates_);
  const auto agree = std::count_if(rates_.begin(), rates_.end(), [m](double r) {
    return std::abs(r - m) <= kAgreeWithin * std::abs(m);
  });
  const int measured = m > 0.0 ? 1 : -1;
  const bool sense_ok =
      !(spec_.direction == config::RotationDirection::kClockwise && measured < 0) &&
      !(spec_.direction == config::RotationDirection::kCounterclockwise && measured > 0);
  if (static_cast<double>(agree) < kAgreeShare * static_cast<double>(rates_.size()) || !sense_ok) {
    // A full window of pairs that do not agree: no steady rotation (unless the profile says
    // it rotates: then keep learning).
    if (kind_ == Kind::kUndecided && rates_.size() >= kSamplesKept &&
        spec_.rotation != config::AntennaRotation::kRotating) {
      kind_ = Kind::kSnapshot;
    }
    return;
  }
  sense_ = measured;
  rate_ = spec_.period ? kTwoPi / *spec_.period : std::abs(m);
  kind_ = Kind::kRotating;
}

double AntennaSweep::unwrap(double azimuth, double time) const {
  const double u = sense_ * azimuth;
  const double predicted = latest_sweep_ + rate_ * (time - latest_time_);
  return u + kTwoPi * std::round((predicted - u) / kTwoPi);
}

void AntennaSweep::order(const PlotScan& scan) {
  const std::size_t n = scan.plots.size();
  order_.resize(n);
  for (std::size_t i = 0; i < n; ++i) order_[i] = i;
  std::stable_sort(order_.begin(), order_.end(), [&](std::size_t a, std::size_t b) {
    return plot_time(scan.plots[a], scan) < plot_time(scan.plots[b], scan);
  });
  ordered_.clear();
  for (const std::size_t i : order_) {
    ordered_.push_back(
        {plot_time(scan.plots[i], scan), body_azimuth(scan.plots[i], scan.platform)});
  }
}

AntennaSweep::Kind AntennaSweep::read(const PlotScan& scan) {
  if (kind_ == Kind::kSnapshot) return kind_;
  if (kind_ == Kind::kUndecided && !scan.plots.empty() &&
      std::none_of(scan.plots.begin(), scan.plots.end(),
                   [](const Plot& p) { return p.time.has_value(); })) {
    kind_ = Kind::kSnapshot;  // no plot timed by the sweep: nothing to follow it by
    return kind_;
  }
  // Until the rate is known the pairs teach it; afterwards (without a period in the
  // profile) they refine it.
  order(scan);
  learn(ordered_);
  if (!ordered_.empty()) last_ = ordered_.back();
  return kind_;
}

void AntennaSweep::place(const PlotScan& scan, double base, std::vector<double>& sweeps) {
  sweeps.clear();
  if (kind_ != Kind::kRotating) return;
  order(scan);
  if (!anchored_ && !ordered_.empty()) {
    latest_time_ = ordered_.front().time;
    const double u = sense_ * ordered_.front().azimuth;  // its sweep, mod 2 pi
    latest_sweep_ = base + kTwoPi + wrap_angle_positive(u - base);
    anchored_ = true;
  }
  sweeps.resize(scan.plots.size());
  for (std::size_t k = 0; k < ordered_.size(); ++k) {
    const Sample& s = ordered_[k];
    const double sweep = unwrap(s.azimuth, s.time);
    sweeps[order_[k]] = sweep;
    if (s.time >= latest_time_) {
      latest_time_ = s.time;
      latest_sweep_ = std::max(latest_sweep_, sweep);
    }
  }
}

double AntennaSweep::sweep_at(double time) const {
  return latest_sweep_ + rate_ * std::max(0.0, time - latest_time_);
}

double AntennaSweep::sweep_of(double azimuth, double after) const {
  const double ahead = wrap_angle_positive(sense_ * azimuth - after);
  return after + (ahead > 0.0 ? ahead : kTwoPi);
}

double AntennaSweep::azimuth_of(double sweep) const {
  return wrap_angle(sense_ * sweep);
}

AzimuthSector AntennaSweep::sector(double from, double to) const {
  return sense_ >= 0 ? AzimuthSector{azimuth_of(from), azimuth_of(to)}
                     : AzimuthSector{azimuth_of(to), azimuth_of(from)};
}

}  // namespace skytrack
