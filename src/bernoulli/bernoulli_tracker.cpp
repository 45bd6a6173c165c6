#include "skytrack/bernoulli/bernoulli_tracker.hpp"

#include <cmath>
#include <numeric>
#include <string>

namespace skytrack::bernoulli {
namespace {

std::string existence_text(double q) {
  return "existence " + std::to_string(q);
}

}  // namespace

Expected<BernoulliTracker> BernoulliTracker::create(const config::TrackingProfile& profile) {
  const BernoulliSpec& spec = profile.bernoulli;
  const std::string where = "profile '" + profile.identity.name + "', mode bernoulli: ";
  if (spec.model_count < 1 || spec.model_count > kMaxModels ||
      spec.model_count != static_cast<int>(profile.motion_models.size())) {
    return make_error(where + "one to " + std::to_string(kMaxModels) +
                      " motion models (constant_velocity or coordinated_turn) are needed");
  }
  std::vector<std::string> names;
  for (int j = 0; j < spec.model_count; ++j) {
    const auto& row = spec.transition[static_cast<std::size_t>(j)];
    const double sum = std::accumulate(row.begin(), row.begin() + spec.model_count, 0.0);
    if (std::abs(sum - 1.0) > 1e-6) return make_error(where + "transition rows must sum to 1");
    if (spec.models[static_cast<std::size_t>(j)].particles < 1) {
      return make_error(where + "every model needs at least one particle");
    }
    names.push_back(profile.motion_models[static_cast<std::size_t>(j)].name);
  }
  return BernoulliTracker(profile, std::move(names));
}

BernoulliTracker::Watch& BernoulliTracker::watch_of(std::uint32_t sensor) {
  auto it = watches_.find(sensor);
  if (it == watches_.end()) {
    // Each sensor's filter draws from its own stream, so adding a sensor leaves the others'
    // estimates as they were.
    BernoulliSpec spec = profile_.bernoulli;
    spec.seed += sensor;
    it = watches_.emplace(sensor, Watch{MmBernoulliFilter(spec)}).first;
  }
  return it->second;
}

void BernoulliTracker::report(const Watch& watch, const BernoulliEstimate& estimate,
                              TrackStatus status, TrackFrame& frame, ScanReport& report) const {
  TrackReport track;
  track.id = status == TrackStatus::kTentative ? kProvisionalNumber + frame.sensor : watch.number;
  track.status = status;
  track.dims = 2;
  const Eigen::Vector4d& x = estimate.mean;  // [x vx y vy]
  track.position = {x[0], x[2], 0.0};
  track.velocity = {x[1], x[3], 0.0};
  track.covariance.assign(estimate.covariance.data(), estimate.covariance.data() + 16);
  for (int j = 0; j < estimate.model_count; ++j) {
    track.modes.emplace_back(model_names_[static_cast<std::size_t>(j)],
                             estimate.model_probabilities[static_cast<std::size_t>(j)]);
  }
  track.quality = estimate.existence;
  frame.tracks.push_back(std::move(track));
  if (status == TrackStatus::kTentative) ++report.tentative;
  if (status == TrackStatus::kConfirmed) ++report.confirmed;
}

void BernoulliTracker::process(const PlotScan& look, Preprocessing& pre, TrackFrame& frame,
                               ScanReport& report) {
  begin_frame(look, frame);
  Watch& watch = watch_of(look.sensor);
  const Eigen::Vector2d platform = look.platform.position.head<2>();
  const BernoulliEstimate estimate = watch.filter.step(look.time, platform, pre.plots());
  report.plots_invalid += estimate.plots_rejected;
  if (estimate.target_reported) {
    if (estimate.report_epoch != watch.epoch || watch.number == 0) {
      watch.number = next_number_++;
      watch.epoch = estimate.report_epoch;
      frame.events.push_back(
          {TrackEventType::kConfirmed, watch.number, existence_text(estimate.existence), {}});
      ++report.initiated;
    }
    watch.reported = true;
    this->report(watch, estimate, TrackStatus::kConfirmed, frame, report);
    return;
  }
  if (watch.reported) {
    // Its existence fell below the threshold: the target is gone (or hidden too long).
    watch.reported = false;
    frame.events.push_back(
        {TrackEventType::kDeleted, watch.number, existence_text(estimate.existence), {}});
    ++report.deleted;
    this->report(watch, estimate, TrackStatus::kDeleted, frame, report);
  }
  this->report(watch, estimate, TrackStatus::kTentative, frame, report);
}

void BernoulliTracker::report_only(const PlotScan& batch, TrackFrame& frame, ScanReport& report) {
  begin_frame(batch, frame);
  report.plots = static_cast<int>(batch.plots.size());
  const auto it = watches_.find(batch.sensor);
  if (it == watches_.end()) return;
  const Watch& watch = it->second;
  this->report(watch, watch.filter.last(),
               watch.reported ? TrackStatus::kConfirmed : TrackStatus::kTentative, frame, report);
}

}  // namespace skytrack::bernoulli
