// Scenario evaluation: per-scan OSPA/GOSPA and run summaries (see scenario_evaluation.hpp).
#include "skytrack/metrics/scenario_evaluation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "skytrack/metrics/gaussian_wasserstein.hpp"

namespace skytrack::metrics {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void set_head(Eigen::VectorXd& out, const Eigen::Vector3d& v, int dims) {
  out.resize(std::clamp(dims, 1, 3));  // no reallocation when the size is unchanged
  out = v.head(out.size());
}

double squared_error(const Eigen::Vector3d& a, int dims_a, const Eigen::Vector3d& b, int dims_b) {
  const int dims = std::clamp(std::min(dims_a, dims_b), 1, 3);
  return (a.head(dims) - b.head(dims)).squaredNorm();
}

}  // namespace

ScenarioEvaluation::ScenarioEvaluation(ScenarioEvaluationConfig config)
    : config_(config),
      calculator_(OspaGospaConfig{config.cutoff, config.order}),
      kept_(config.cutoff) {}

const ScanRecord& ScenarioEvaluation::add(const TruthFrame& truth,
                                          const TrackFrame* tracks_or_null) {
  if (tracks_or_null == nullptr) return add(truth, std::span<const TrackReport>{});
  return add(truth, std::span<const TrackReport>(tracks_or_null->tracks));
}

const ScanRecord& ScenarioEvaluation::add(const TruthFrame& truth,
                                          std::span<const TrackReport> tracks) {
  const std::vector<TruthObject>& objects = truth.objects;
  truth_positions_.resize(objects.size());
  for (std::size_t i = 0; i < objects.size(); ++i) {
    set_head(truth_positions_[i], objects[i].position, objects[i].dims);
  }
  firm_.clear();
  for (std::size_t j = 0; j < tracks.size(); ++j) {
    if (is_reported_as_firm(tracks[j].status)) firm_.push_back(static_cast<int>(j));
  }
  track_positions_.resize(firm_.size());
  for (std::size_t k = 0; k < firm_.size(); ++k) {
    const TrackReport& track = tracks[firm_[k]];
    set_head(track_positions_[k], track.position, track.dims);
  }

  const OspaGospaResult& result = calculator_.compute(truth_positions_, track_positions_);

  // Matched pairs feed RMSE, GWD and continuity.
  matched_track_.assign(objects.size(), std::nullopt);
  for (const MatchedPair& pair : result.pairs) {
    const TruthObject& object = objects[pair.truth];
    const TrackReport& track = tracks[firm_[pair.estimate]];
    matched_track_[pair.truth] = track.id;
    sum_sq_position_ += squared_error(object.position, object.dims, track.position, track.dims);
    sum_sq_velocity_ += squared_error(object.velocity, object.dims, track.velocity, track.dims);
    ++matched_;
    if (object.extent && track.extent) {
      sum_gwd_ += gaussian_wasserstein_distance(object.position.head<2>(), *object.extent,
                                                track.position.head<2>(), *track.extent);
      ++gwd_pairs_;
    }
  }
  for (std::size_t i = 0; i < objects.size(); ++i) {
    continuity_.observe(objects[i].id, matched_track_[i]);
  }
  truth_ids_.resize(objects.size());
  firm_ids_.resize(firm_.size());
  distances_.resize(static_cast<Eigen::Index>(objects.size()),
                    static_cast<Eigen::Index>(firm_.size()));
  for (std::size_t i = 0; i < objects.size(); ++i) {
    truth_ids_[i] = objects[i].id;
    for (std::size_t k = 0; k < firm_.size(); ++k) {
      const TrackReport& track = tracks[firm_[k]];
      distances_(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) = std::sqrt(
          squared_error(objects[i].position, objects[i].dims, track.position, track.dims));
    }
  }
  for (std::size_t k = 0; k < firm_.size(); ++k) firm_ids_[k] = tracks[firm_[k]].id;
  kept_.match(truth_ids_, firm_ids_, distances_, kept_track_);
  for (std::size_t i = 0; i < objects.size(); ++i) {
    kept_continuity_.observe(objects[i].id, kept_track_[i]);
  }

  record_ = ScanRecord{truth.time,
                       result.ospa,
                       result.gospa,
                       result.localisation,
                       result.missed,
                       result.false_tracks,
                       static_cast<int>(objects.size()),
                       static_cast<int>(firm_.size())};
  ++scans_;
  sum_gospa_ += record_.gospa;
  sum_ospa_ += record_.ospa;
  sum_localisation_ += record_.gospa_localisation;
  sum_missed_ += record_.gospa_missed;
  sum_false_ += record_.gospa_false;
  return record_;
}

EvaluationSummary ScenarioEvaluation::summary() const {
  EvaluationSummary s;
  s.scans = scans_;
  if (scans_ > 0) {
    const auto n = static_cast<double>(scans_);
    s.gospa_mean = sum_gospa_ / n;
    s.ospa_mean = sum_ospa_ / n;
    s.gospa_localisation_mean = sum_localisation_ / n;
    s.gospa_missed_mean = sum_missed_ / n;
    s.gospa_false_mean = sum_false_ / n;
  }
  s.matched_pairs = matched_;
  s.rmse_position = matched_ > 0 ? std::sqrt(sum_sq_position_ / matched_) : kNaN;
  s.rmse_velocity = matched_ > 0 ? std::sqrt(sum_sq_velocity_ / matched_) : kNaN;
  s.id_changes = continuity_.id_changes();
  s.fragmentations = continuity_.fragmentations();
  s.continuity = continuity_.per_truth();
  s.kept_id_changes = kept_continuity_.id_changes();
  s.kept_fragmentations = kept_continuity_.fragmentations();
  s.gwd_pairs = gwd_pairs_;
  s.gwd_mean = gwd_pairs_ > 0 ? sum_gwd_ / static_cast<double>(gwd_pairs_) : kNaN;
  return s;
}

}  // namespace skytrack::metrics
