#include "skytrack/tracking/gater.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "point_tracker_support.hpp"
#include "skytrack/core/chi_square.hpp"
#include "skytrack/geometry/frames.hpp"

namespace skytrack {

using namespace tracking_detail;

Gater::Gater(const config::TrackingProfile& profile, int dims)
    : default_sigma_(profile.measurement.default_sigma),
      dims_(dims),
      last_motion_false_plots_(profile.point.branching.last_motion_false_plots) {
  for (int d = 1; d <= kMaxMeasurementDim; ++d) {
    gate_threshold_[d] = chi_square_quantile(profile.association.gate_probability, d);
    const double half = 0.5 * d;
    gate_volume_per_peak_[d] = std::pow(0.5 * gate_threshold_[d], half) / std::tgamma(half + 1.0);
  }
  // What a track may do between looks, for its search region (search_regions): three sigma
  // of its models' white acceleration, or its fastest turn.
  for (const config::MotionModelSpec& m : profile.motion_models) {
    region_accel_ = std::max(region_accel_, 3.0 * m.accel_sigma);
    max_turn_rate_ = std::max(max_turn_rate_, std::abs(m.turn_rate));
  }
}

void Gater::gate(const PlotScan& scan, Preprocessing& pre, std::vector<PointTrack>& tracks,
                 const ImmFilter& filter, double batch_mid, double half_span, BranchHooks& hooks) {
  candidates_.clear();
  gated_.assign(pre.plots().size(), 0);
  batch_mid_ = batch_mid;
  half_span_ = half_span;
  predicted_.resize(tracks.size());
  coasted_.resize(tracks.size());
  for (ImmEstimate& e : coasted_) e.modes.clear();
  covered_.assign(tracks.size(), 1);
  took_candidates_.assign(tracks.size(), 0);
  // Without branching.last_motion_false_plots every track counts as in a clutter area (its
  // detectability chain applies everywhere).
  clutter_area_.assign(tracks.size(), last_motion_false_plots_ > 0.0 ? 0 : 1);
  const double widest = gate_threshold_[kMaxMeasurementDim];
  for (std::size_t t = 0; t < tracks.size(); ++t) {
    PointTrack& track = tracks[t];
    const ImmEstimate& estimate = track.estimate;
    if (scan.coverage) {
      // A sector look: most tracks lie far from it; a bound on the search region says which
      // need no prediction.
      SearchRegion bound = region_bound(tracks, static_cast<int>(t), filter, scan,
                                        std::max(batch_mid, estimate.time), widest, region_accel_);
      bound.radius += seed_speed(static_cast<int>(t)) * half_span;
      if (!covers_region(scan, bound.centre, bound.radius)) {
        covered_[t] = 0;
        predicted_[t] = estimate;
        continue;
      }
    }
    const double mid_time = std::max(batch_mid, estimate.time);
    // Predicted in place: predicted_[t] keeps its storage from look to look.
    ImmEstimate& predicted = predicted_[t];
    filter.predict(estimate, mid_time, predicted);
    const Gaussian mid = filter.combine(predicted);
    const Eigen::Vector3d centre = position_of(mid.mean, dims_);
    // A sector batch looks at a track whose predicted position lies in the sector; one whose
    // search region only reaches into it may take a plot from it but is not aged by it.
    covered_[t] =
        covers(scan, centre) && pre.sweep() - track.looked_by(pre.sensor()) > std::numbers::pi ? 1
                                                                                               : 0;
    const bool non_manoeuvre = hooks.at_mid_batch(static_cast<int>(t), covered_[t] != 0, mid,
                                                  std::max(batch_mid, estimate.time));
    // Search radius: the widest gate in the most uncertain direction, plus the motion over
    // half the batch's time span. The exact gate test is per plot, in measurement space.
    const double radius = search_radius(mid, centre, widest, scan);
    if (!covered_[t] && !covers_region(scan, centre, radius)) {
      predicted = estimate;
      continue;
    }
    pre.index().within(centre, radius, neighbours_);
    if (neighbours_.empty()) {
      coasted_[t] = predicted;
      predicted = estimate;
      continue;
    }
    // The track is updated at the time of its nearest candidate plot (a snapshot look's
    // plots share the batch's time: its prediction to the middle is that one).
    const double update_time = std::max(nearest_time(pre, neighbours_, centre), estimate.time);
    if (update_time != mid_time) filter.predict(estimate, update_time, predicted);
    if (!non_manoeuvre) continue;
    hooks.narrow(static_cast<int>(t), predicted, neighbours_, clutter_area_[t]);
    shapes_.clear();
    for (const int j : neighbours_) {
      // A plot inside any mode's gate (the union of the modes' gates), or the gate of the
      // prediction the hook narrowed it to, is a candidate.
      if (filter.min_nis(predicted, pre.plots()[j], shapes_) >
          gate_threshold_[pre.plots()[j].model.size()]) {
        continue;
      }
      PlotHypothesis hypothesis = filter.hypothesise(predicted, pre.plots()[j], shapes_);
      if (!hypothesis.usable || hypothesis.min_nis > gate_threshold_[pre.plots()[j].model.size()]) {
        continue;
      }
      gated_[j] = 1;
      took_candidates_[t] = 1;
      const double likelihood = hypothesis.likelihood;
      candidates_.push_back({static_cast<int>(t), j, std::move(hypothesis), likelihood});
    }
  }
}

ImmEstimate Gater::coast(const PointTrack& track, std::size_t t, const ImmFilter& filter,
                         double time) {
  ImmEstimate& coasted = coasted_[t];
  if (!coasted.modes.empty() && coasted.time == std::max(time, track.estimate.time) &&
      predicted_[t].time == track.estimate.time) {
    ImmEstimate out = std::move(coasted);
    coasted.modes.clear();
    return out;
  }
  return filter.predict(track.estimate, std::max(time, track.estimate.time));
}

double Gater::search_radius(const Gaussian& g, const Eigen::Vector3d& centre, double threshold,
                            const PlotScan& scan) const {
  const double track_sigma = position_spread(g, dims_);
  const double plot_sigma = plot_spread_at(centre, scan);
  return std::sqrt(threshold * (track_sigma * track_sigma + plot_sigma * plot_sigma)) +
         velocity_of(g.mean, dims_).norm() * half_span_;
}

double Gater::nearest_time(const Preprocessing& pre, std::span<const int> neighbours,
                           const Eigen::Vector3d& centre) {
  int nearest = neighbours.front();
  double best = std::numeric_limits<double>::infinity();
  for (const int j : neighbours) {
    const double d = (pre.positions()[j] - centre).squaredNorm();
    if (d < best) {
      best = d;
      nearest = j;
    }
  }
  return pre.plots()[nearest].time;
}

double Gater::plot_spread_at(const Eigen::Vector3d& position, const PlotScan& scan) const {
  // Plot position spread near a track from the batch's sigmas (plot overrides are rare); in
  // 3-D the height error counts too (elevation is often measured worse than azimuth).
  const config::MeasurementSigmas& d = default_sigma_;
  const MeasurementSigma& s = scan.sigma;
  const bool height = dims_ == 3;
  const double range = (position - scan.platform.position).norm();
  const double angle =
      std::max(s.azimuth.value_or(d.azimuth), height ? s.elevation.value_or(d.elevation) : 0.0);
  const double polar = std::max(s.range.value_or(d.range), range * angle);
  const double cartesian =
      std::max({s.x.value_or(d.x), s.y.value_or(d.y), height ? s.z.value_or(d.z) : 0.0});
  return std::max(polar, cartesian);
}

bool Gater::covers(const PlotScan& scan, const Eigen::Vector3d& position) {
  return !scan.coverage || scan.coverage->contains(enu_to_polar(position, scan.platform).azimuth);
}

bool Gater::covers_region(const PlotScan& scan, const Eigen::Vector3d& centre, double radius) {
  if (!scan.coverage) return true;
  const PolarPoint polar = enu_to_polar(centre, scan.platform);
  const double margin = std::atan2(radius, std::max(polar.range, radius));
  return scan.coverage->contains(polar.azimuth - margin) ||
         scan.coverage->contains(polar.azimuth + margin) || scan.coverage->contains(polar.azimuth);
}

SearchRegion Gater::region_bound(const std::vector<PointTrack>& tracks, int t,
                                 const ImmFilter& filter, const PlotScan& header, double time,
                                 double threshold, double accel) const {
  // The combined estimate at its own time, kept until the track changes, extrapolated with a
  // bound on its growth rather than an IMM prediction (a feed of a few plots per batch asks
  // for regions thousands of times a revolution): position and velocity spread, and what a
  // turn or an acceleration of `accel` does meanwhile.
  const PointTrack& track = tracks[static_cast<std::size_t>(t)];
  const int dims = dims_;
  if (region_seeds_.size() < tracks.size()) region_seeds_.resize(tracks.size());
  RegionSeed& seed = region_seeds_[static_cast<std::size_t>(t)];
  if (seed.id != track.id || seed.time != track.estimate.time) {
    const Gaussian g = filter.combine(track.estimate);
    Gaussian velocity = g;
    for (int a = 0; a < dims; ++a) {
      for (int b = 0; b < dims; ++b) {
        velocity.covariance(2 * a, 2 * b) = g.covariance(2 * a + 1, 2 * b + 1);
      }
    }
    seed = {track.id,
            track.estimate.time,
            position_of(g.mean, dims),
            velocity_of(g.mean, dims),
            position_spread(g, dims),
            position_spread(velocity, dims)};
  }
  const double dt = std::abs(time - seed.time);
  const Eigen::Vector3d centre = seed.position + seed.velocity * (time - seed.time);
  const double track_sigma = seed.spread + seed.velocity_spread * dt;
  const double plot_sigma = plot_spread_at(centre, header);
  const double manoeuvre = 0.5 * std::max(accel, max_turn_rate_ * seed.velocity.norm()) * dt * dt;
  return {centre,
          std::sqrt(threshold * (track_sigma * track_sigma + plot_sigma * plot_sigma)) + manoeuvre};
}

void Gater::search_regions(const std::vector<PointTrack>& tracks, const ImmFilter& filter,
                           const PlotScan& header, double time,
                           std::vector<SearchRegion>& out) const {
  for (std::size_t t = 0; t < tracks.size(); ++t) {
    if (tracks[t].life.status == TrackStatus::kDeleted) continue;
    out.push_back(region_bound(tracks, static_cast<int>(t), filter, header, time,
                               gate_threshold_[kMaxMeasurementDim], region_accel_));
  }
}

}  // namespace skytrack
