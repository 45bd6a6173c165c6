// Multi-object extended tracker: partition, gate by extent, update, initiate, delete
// (see extended_tracker.hpp).
#include "skytrack/extended/extended_tracker.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include <Eigen/Cholesky>

#include "skytrack/extended/ellipse_geometry.hpp"
#include "skytrack/extended/extended_existence.hpp"

namespace skytrack::extended {
namespace {

// A plot's position in the tracking plane and its noise there: R_xy = J diag(sigma^2) J',
// J = d(x, y)/d(position components) by central differences of approximate_position, so
// Cartesian and polar plots (any platform attitude) take one path.
bool cartesian_plot(const PlotMeasurement& m, Eigen::Vector2d& position, Eigen::Matrix2d& noise) {
  position = approximate_position(m).head<2>();
  const int components = m.model.position_components;
  if (!position.allFinite() || m.z.size() < components || m.model.sigma.size() < components) {
    return false;
  }
  noise.setZero();
  for (int c = 0; c < components; ++c) {
    const double h = 1e-6 * std::max(1.0, std::abs(m.z[c]));
    PlotMeasurement shifted = m;
    shifted.z[c] += h;
    const Eigen::Vector2d up = approximate_position(shifted).head<2>();
    shifted.z[c] -= 2.0 * h;
    const Eigen::Vector2d down = approximate_position(shifted).head<2>();
    const Eigen::Vector2d column = (up - down) / (2.0 * h);
    noise.noalias() += m.model.sigma[c] * m.model.sigma[c] * column * column.transpose();
  }
  return noise.allFinite();
}

}  // namespace

double ExtendedTrack::existence() const {
  return existence_probability(existence_log_odds);
}

ExtendedTracker::ExtendedTracker(const ExtendedSpec& spec) : spec_(spec), estimator_(spec) {}

bool ExtendedTracker::mixes_levels() const noexcept {
  return spec_.kind != EstimatorKind::kSmf &&
         spec_.motion.manoeuvre_accel > spec_.motion.accel_noise;
}

bool ExtendedTracker::chooses_levels() const noexcept {
  return spec_.kind == EstimatorKind::kSmf &&
         spec_.motion.manoeuvre_accel > spec_.motion.accel_noise;
}

Eigen::Matrix2d ExtendedTracker::gate_centre_cov(int t) {
  // SMF-EOT picks a scan's level from the plots it gates, so its gates span the manoeuvre
  // level's set: on the quiet level's alone a turn's first scan falls outside them and the
  // level choice never sees it. The mixed levels' prediction already holds the manoeuvre.
  const PosMat H = position_matrix();
  if (!chooses_levels() || !(scan_dt_ > 0.0)) return H * tracks_[t].object.P * H.transpose();
  MotionSpec manoeuvre = spec_.motion;
  manoeuvre.accel_noise = spec_.motion.manoeuvre_accel;
  ExtendedObject& turning = manoeuvre_predictions_[t];
  turning = priors_[t];
  estimator_.predict(turning, scan_dt_, manoeuvre);
  return H * turning.P * H.transpose();
}

ExtendedScanReport ExtendedTracker::process(double time, std::span<const PlotMeasurement> plots,
                                            std::span<const std::vector<int>> partitions) {
  plane_positions_.resize(plots.size());
  plane_noises_.resize(plots.size());
  for (std::size_t i = 0; i < plots.size(); ++i) {
    if (!cartesian_plot(plots[i], plane_positions_[i], plane_noises_[i])) {
      plane_positions_[i].setConstant(std::numeric_limits<double>::quiet_NaN());
    }
  }
  return process(time, plane_positions_, plane_noises_, partitions);
}

double ExtendedTracker::gate_distance(int t, const Eigen::Vector2d& z, const Eigen::Matrix2d& noise,
                                      double extent_weight, double* log_det) const noexcept {
  const ExtendedTrack& track = tracks_[t];
  const Eigen::Matrix2d G = gate_centre_covs_[t] + extent_weight * association_extents_[t] + noise;
  const Eigen::LLT<Eigen::Matrix2d> llt(G);
  if (llt.info() != Eigen::Success) return std::numeric_limits<double>::infinity();
  const Eigen::Vector2d nu = z - track.position();
  if (log_det) *log_det = 2.0 * std::log(llt.matrixL()(0, 0) * llt.matrixL()(1, 1));
  return nu.dot(llt.solve(nu));
}

ExtendedScanReport ExtendedTracker::process(double time, std::span<const Eigen::Vector2d> positions,
                                            std::span<const Eigen::Matrix2d> noises,
                                            std::span<const std::vector<int>> partitions) {
  ExtendedScanReport report;
  deleted_.clear();
  if (!std::isfinite(time) || (started_ && time < last_time_) ||
      positions.size() != noises.size()) {
    report.skipped = true;
    return report;
  }
  const double dt = started_ ? time - last_time_ : 0.0;
  scan_dt_ = dt;
  started_ = true;
  last_time_ = time;

  const int n = static_cast<int>(positions.size());
  positions_.assign(positions.begin(), positions.end());
  noises_.assign(noises.begin(), noises.end());
  for (int i = 0; i < n; ++i) {
    const Eigen::Matrix2d& R = noises_[i];
    if (!positions_[i].allFinite() || !R.allFinite() || !(R(0, 0) > 0.0) || !(R(1, 1) > 0.0)) {
      positions_[i].setConstant(std::numeric_limits<double>::quiet_NaN());
      ++report.rejected_plots;
    }
  }
  report.plots = n - report.rejected_plots;

  association_extents_.clear();
  gate_centre_covs_.clear();
  manoeuvre_predictions_.resize(chooses_levels() ? tracks_.size() : 0);
  was_unresolved_.clear();
  priors_.clear();
  for (ExtendedTrack& track : tracks_) {
    was_unresolved_.push_back(track.unresolved);
    priors_.push_back(track.object);
    if (dt > 0.0 && mixes_levels()) {
      predict_levels(track.levels, estimator_, spec_.motion, dt, track.object);
    } else if (dt > 0.0) {
      estimator_.predict(track.object, dt);
    }
    track.plots = 0;
    track.unresolved = false;
    association_extents_.push_back(association_extent(track));
    gate_centre_covs_.push_back(gate_centre_cov(static_cast<int>(gate_centre_covs_.size())));
  }
  if (partitions.empty()) {
    partitioner_.partition(positions_, spec_.partition_distance, groups_);
  } else {  // the caller's groups, without unusable or out-of-range plots
    groups_.clear();
    for (const std::vector<int>& group : partitions) {
      groups_.emplace_back();
      for (int i : group) {
        if (i >= 0 && i < n && positions_[i].allFinite()) groups_.back().push_back(i);
      }
      if (groups_.back().empty()) groups_.pop_back();
    }
  }
  report.partitions = static_cast<int>(groups_.size());
  partition_of_.assign(n, -1);
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    for (int i : groups_[g]) partition_of_[i] = static_cast<int>(g);
  }
  associate(report);
  manage(report);
  return report;
}

void ExtendedTracker::associate(ExtendedScanReport& report) {
  const int track_count = static_cast<int>(tracks_.size());
  track_plots_.resize(track_count);
  gate_areas_.assign(track_count, 0.0);
  for (std::vector<int>& plots : track_plots_) plots.clear();
  std::vector<const std::vector<int>*>& unassigned = unassigned_;
  unassigned.clear();
  partition_split_.assign(groups_.size(), 0);
  yieldable_.clear();
  for (const std::vector<int>& group : groups_) {
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    Eigen::Matrix2d noise = Eigen::Matrix2d::Zero();
    for (int i : group) mean += positions_[i], noise += noises_[i];
    mean /= static_cast<double>(group.size());
    noise /= static_cast<double>(group.size());
    gated_.clear();
    for (int t = 0; t < track_count; ++t) {
      const double d2 = gate_distance(t, mean, noise, 1.0, nullptr);
      if (d2 <= spec_.gate) gated_.push_back({t, d2});
    }
    if (gated_.empty()) {
      unassigned.push_back(&group);
      continue;
    }
    // A confirmed track's plots are not shared with a tentative one beside it: that would
    // feed a duplicate until it is confirmed and takes the object's number.
    const bool any_confirmed = std::any_of(gated_.begin(), gated_.end(), [this](const Gated& g) {
      return tracks_[g.track].status == ExtendedTrackStatus::kConfirmed;
    });
    if (any_confirmed) {
      std::erase_if(gated_, [this](const Gated& g) {
        return tracks_[g.track].status != ExtendedTrackStatus::kConfirmed;
      });
    }
    if (!any_confirmed && gated_.size() > 1) keep_likeliest_tentative(mean, noise);
    if (gated_.size() == 1) {
      const int t = gated_.front().track;
      for (int i : group) {  // clutter beside the object stays out of its update
        if (gate_distance(t, positions_[i], noises_[i], kUniformScatter, nullptr) <=
            spec_.plot_gate) {
          track_plots_[t].push_back(i);
        }
      }
      continue;
    }
    if (crossing_unresolved()) {
      for (const Gated& g : gated_) tracks_[g.track].unresolved = true;
      continue;
    }
    partition_split_[&group - groups_.data()] = 1;
    split_shared(group);
  }
  for (int t = 0; t < track_count; ++t) keep_partitions_within_reach(t);
  // After the gated partitions, so a track is known to have found none of its own.
  reconsider_missed_scans();
  std::size_t kept = 0;
  for (const std::vector<int>* group : unassigned) {
    if (!claim_by_confirmed(*group)) unassigned[kept++] = group;
  }
  unassigned.resize(kept);
  for (int t = 0; t < track_count; ++t) drop_lone_plots(t);
  for (int t = 0; t < track_count; ++t) {
    ExtendedTrack& track = tracks_[t];
    const std::vector<int>& plots = track_plots_[t];
    // Fewer plots than start a track are taken as clutter in a scan the object was missed:
    // one stray plot would drag the centre, velocity and extent off the object.
    const bool enough = static_cast<int>(plots.size()) >= std::max(1, spec_.min_partition_plots);
    const Eigen::Matrix2d noise = enough ? buffer_track_plots(t) : Eigen::Matrix2d::Zero();
    const bool mixing = mixes_levels();
    track.missed_scan.kept = false;
    const double evidence_before = track.manoeuvre_evidence;
    const bool turned = enough && !mixing && predict_manoeuvre_if_likelier(t, noise);
    const double log_ratio =
        enough ? clutter_log_ratio(t, noise) : std::numeric_limits<double>::quiet_NaN();
    if (!enough || log_ratio < 0.0) {
      // Taken as clutter: the object is unseen, nothing shows a manoeuvre.
      if (turned) std::swap(track.object, turning_);
      // Unseen: coast at constant velocity (the acceleration estimated before is no evidence
      // that the object keeps accelerating; extrapolated it carries the coast off).
      if (spec_.coast_constant_velocity && scan_dt_ > 0.0) {
        const Eigen::Vector2d accel(priors_[t].x[4], priors_[t].x[5]);
        coast_constant_velocity(track.object.x, accel, scan_dt_);
        if (mixing) {
          for (ExtendedObject& level : track.levels.object) level.x = track.object.x;
        }
      }
      continue;
    }
    keep_missed_scan(t, turned ? turning_ : track.object, evidence_before, log_ratio);
    // The plot gate's area before the update, where clutter could have come from.
    const Eigen::Matrix2d G =
        gate_centre_covs_[t] + kUniformScatter * association_extents_[t] + noise;
    const Eigen::LLT<Eigen::Matrix2d> llt(G);  // sqrt(det G) = L00 L11
    gate_areas_[t] = llt.info() == Eigen::Success ? std::numbers::pi * spec_.plot_gate *
                                                        llt.matrixL()(0, 0) * llt.matrixL()(1, 1)
                                                  : 0.0;
    if (track.hits == 1 && scan_dt_ > 0.0) two_point_velocity(track);
    const UpdateStatus status =
        mixing ? update_levels(track.levels, estimator_, plot_buffer_, noise,
                               kUniformScatter * association_extents_[t] + noise, track.object)
               : estimator_.update(track.object, plot_buffer_, noise);
    if (status == UpdateStatus::kNumericFailure) ++report.numeric_failures;
    track.plots = static_cast<int>(plots.size());
    ++report.updated;
  }
  for (const std::vector<int>* group : unassigned) initiate(*group, report);
}

void ExtendedTracker::two_point_velocity(ExtendedTrack& track) const noexcept {
  // A new track started at rest; its second partition gives the velocity (two-point
  // initiation). Without it the first innovation is the whole displacement (150 m for
  // 15 m/s over 10 s), which MEM-EKF* reads as extent: semi-axes of kilometres.
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& z : plot_buffer_) mean += z;
  mean /= static_cast<double>(plot_buffer_.size());
  const Eigen::Vector2d v = (mean - track.position()) / scan_dt_;
  KinVec& x = track.object.x;
  x[0] = mean.x();
  x[1] = v.x();
  x[2] = mean.y();
  x[3] = v.y();
  KinMat P = KinMat::Zero();
  const double pos_var = track.birth_variance;
  const double vel_var = 2.0 * pos_var / (scan_dt_ * scan_dt_);
  const double a2 = spec_.initial_accel_sigma * spec_.initial_accel_sigma;
  for (int axis = 0; axis < 2; ++axis) {
    P(2 * axis, 2 * axis) = pos_var;
    P(2 * axis + 1, 2 * axis + 1) = vel_var;
    P(2 * axis, 2 * axis + 1) = P(2 * axis + 1, 2 * axis) = pos_var / scan_dt_;
    P(4 + axis, 4 + axis) = a2;
  }
  track.object.P = P;
  track.object.S = P;
  for (ExtendedObject& level : track.levels.object) {
    level.x = track.object.x;
    level.P = level.S = P;
  }
}

void ExtendedTracker::initiate(const std::vector<int>& group, ExtendedScanReport& report) {
  if (static_cast<int>(group.size()) < spec_.min_partition_plots) return;
  const double count = static_cast<double>(group.size());
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  Eigen::Matrix2d noise = Eigen::Matrix2d::Zero();
  for (int i : group) mean += positions_[i], noise += noises_[i];
  mean /= count;
  noise /= count;
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  for (int i : group)
    scatter.noalias() += (positions_[i] - mean) * (positions_[i] - mean).transpose();
  // Scatterers uniform over an ellipse X have covariance X / 4.
  const EllipseAxes axes = ellipse_axes(4.0 * (scatter / count - noise));
  const double floor = spec_.initial_extent_axis;
  const Eigen::Matrix2d extent =
      shape_from_axes(std::max(axes.major, floor), std::max(axes.minor, floor), axes.orientation);
  KinVec x = KinVec::Zero();
  x[0] = mean.x();
  x[2] = mean.y();
  const double pos_var = extent.trace() / (4.0 * count) + noise.trace();
  const double v2 = spec_.initial_speed_sigma * spec_.initial_speed_sigma;
  const double a2 = spec_.initial_accel_sigma * spec_.initial_accel_sigma;
  const KinMat P = (KinVec() << pos_var, v2, pos_var, v2, a2, a2).finished().asDiagonal();
  ExtendedTrack track;
  track.id = next_id_++;
  track.object = estimator_.initiate(x, P, extent);
  track.levels = start_levels(track.object, spec_.motion);
  track.hits = 1;
  track.birth_variance = pos_var;
  track.existence_log_odds = existence_birth(spec_.existence);
  track.plots = static_cast<int>(group.size());
  tracks_.push_back(track);
  ++report.initiated;
}

void ExtendedTracker::hand_over_split_objects() {
  // A turn's first scan can split an object's plots: the track takes the part its gate holds,
  // the rest starts a track beside it, and the next scan's plots all fall to the new track.
  // A confirmed track that took plots last scan and none now gives its number to a track born
  // last scan within its object's length of it (a piece of the same hull) that took plots.
  // The length is that of the extent association uses; SMF-EOT's, an inner bound, collapses
  // on the split's few plots to the floor, so its ships are seldom reached.
  for (int c = 0; c < static_cast<int>(priors_.size()); ++c) {
    ExtendedTrack& confirmed = tracks_[c];
    if (confirmed.status != ExtendedTrackStatus::kConfirmed || confirmed.plots > 0 ||
        confirmed.unresolved || confirmed.misses > 0) {
      continue;
    }
    const double length = 2.0 * ellipse_axes(association_extents_[c]).major;
    int piece = -1;
    double nearest = length;
    for (int n = 0; n < static_cast<int>(priors_.size()); ++n) {
      const ExtendedTrack& born = tracks_[n];
      if (born.status != ExtendedTrackStatus::kTentative || born.hits != 1 || born.plots == 0) {
        continue;
      }
      const double d = (priors_[n].position() - priors_[c].position()).norm();
      if (d <= nearest) nearest = d, piece = n;
    }
    if (piece < 0) continue;
    ExtendedTrack& born = tracks_[piece];
    const std::uint64_t id = confirmed.id;
    const int hits = confirmed.hits;
    const double log_odds = confirmed.existence_log_odds;
    confirmed = born;
    confirmed.id = id;
    confirmed.status = ExtendedTrackStatus::kConfirmed;
    confirmed.hits = hits;
    confirmed.existence_log_odds = log_odds;
    gate_areas_[c] = gate_areas_[piece];
    born.plots = 0;
    born.misses = spec_.tentative_max_misses;  // deleted below: its object is the number's
  }
}

void ExtendedTracker::manage(ExtendedScanReport& report) {
  const std::uint64_t first_new = next_id_ - static_cast<std::uint64_t>(report.initiated);
  hand_over_split_objects();
  for (int t = 0; t < static_cast<int>(tracks_.size()); ++t) {
    ExtendedTrack& track = tracks_[t];
    if (track.id >= first_new) continue;  // born this scan
    // Existence: a coast through a crossing (unresolved) is neither a hit nor a miss.
    const ExistenceSpec& e = spec_.existence;
    double& log_odds = track.existence_log_odds;
    log_odds = existence_predict(log_odds, e);
    if (track.plots > 0) {
      log_odds = existence_hit(log_odds, track.plots, gate_areas_[t], e);
    } else if (!track.unresolved) {
      log_odds = existence_miss(log_odds, std::max(1, spec_.min_partition_plots), e);
    }
    if (track.plots > 0) {
      ++track.hits;
      track.misses = 0;
      // With existence, only once one missed scan would not delete it: plot pairs a large
      // young gate would hold as clutter do not confirm a track only to delete it, and a
      // young object's track is not numbered on the scan it clears the deletion threshold,
      // to be dropped and renumbered after its next miss.
      const bool likely =
          !e.enabled || existence_probability(existence_miss(existence_predict(log_odds, e),
                                                             std::max(1, spec_.min_partition_plots),
                                                             e)) >= e.delete_below;
      if (track.status == ExtendedTrackStatus::kTentative && track.hits >= spec_.confirm_hits &&
          likely) {
        track.status = ExtendedTrackStatus::kConfirmed;
        ++report.confirmed;
      }
    } else if (!track.unresolved) {
      ++track.misses;
    }
  }
  // A tentative track whose centre lies inside an older track's ellipse duplicates it.
  auto lost = [this](const ExtendedTrack& track) {
    if (!track.object.x.allFinite() || !track.object.extent.allFinite()) return true;
    // A confirmed track goes when its object's existence is no longer likely (one that showed
    // many plots a scan starts its coast higher than one of plot pairs, so lasts longer);
    // without existence, after delete_misses.
    if (track.status == ExtendedTrackStatus::kConfirmed) {
      return spec_.existence.enabled ? track.existence() < spec_.existence.delete_below
                                     : track.misses >= spec_.delete_misses;
    }
    if (track.misses >= spec_.tentative_max_misses) return true;
    for (const ExtendedTrack& other : tracks_) {
      if (other.id >= track.id) break;  // ordered by number: only older ones
      const Eigen::Vector2d d = track.position() - other.position();
      const Eigen::LLT<Eigen::Matrix2d> llt(other.object.extent);
      if (llt.info() == Eigen::Success && d.dot(llt.solve(d)) < 1.0) return true;
    }
    return false;
  };
  for (const ExtendedTrack& track : tracks_) {
    if (lost(track)) {
      deleted_.push_back(track.id);
      ++report.deleted;
    }
  }
  if (!deleted_.empty()) {
    std::erase_if(tracks_, [this](const ExtendedTrack& track) {
      return std::find(deleted_.begin(), deleted_.end(), track.id) != deleted_.end();
    });
  }
}

}  // namespace skytrack::extended
